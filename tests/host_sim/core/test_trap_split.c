/*
 * test_trap_split.c — a plain-pointer access wider than its register, or
 * spanning registers, is performed as the per-register accesses an ARM926
 * issues for the source's separate statements, lowest address first, each
 * through its register's hook: gcc -O2 merges adjacent stores (an 8-byte
 * store over two 32-bit registers, a 4-byte store over two 16-bit ones, even
 * at an address that is not 4-aligned) and vectorizes runs of them into SSE
 * stores; loads likewise.  The exact instructions run through the real trap
 * and the register log must show the per-register accesses in order.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tap.h"
#include "sil.h"
#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/regs.h"
#include "host_sim/scenario.h"
#include "host_sim/trace.h"

#define TDEV_PHYS 0x01E00000U

static const struct rtos_cfg cfg = { .name = "trap_split" };

static unsigned hook_order[16], hooks;

/* Records which register's hook ran, in order. */
static void note_write(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	if (hooks < 16U)
		hook_order[hooks++] = a->offset;
}

static const struct hs_reg tdev_regs[] = {
	{ .name = "A", .offset = 0x00, .kind = HS_RW, .after_write = note_write },
	{ .name = "B", .offset = 0x04, .kind = HS_RW, .after_write = note_write },
	{ .name = "H0", .offset = 0x10, .width = 2, .kind = HS_RW, .after_write = note_write },
	{ .name = "H1", .offset = 0x12, .width = 2, .kind = HS_RW, .after_write = note_write },
	{ .name = "H2", .offset = 0x14, .width = 2, .kind = HS_RW, .after_write = note_write },
	{ .name = "C", .offset = 0x20, .kind = HS_RW, .after_write = note_write },
	{ .name = "D", .offset = 0x24, .kind = HS_RW, .after_write = note_write },
	{ .name = "E", .offset = 0x28, .kind = HS_RW, .after_write = note_write },
	{ .name = "F", .offset = 0x2C, .kind = HS_RW, .after_write = note_write },
	{ .name = "W", .offset = 0x30, .kind = HS_RW, .widths = HS_W16, .after_write = note_write },
};

#if defined(__x86_64__) || defined(__arm__)
static char *log_text;
static size_t log_len;
static FILE *log_file;

/* Starts logging every access of TDEV. */
static void log_start(void)
{
	hooks = 0;
	log_file = open_memstream(&log_text, &log_len);
	hs_trace_reglog("TDEV", log_file);
}

/* Stops logging; true if the log holds exactly the accesses in want ("W4 TDEV.A", ...), in order. */
static bool log_is(const char *const *want, unsigned n)
{
	const char *p;
	unsigned lines = 0;
	bool good = true;

	hs_trace_reglog(NULL, NULL);
	fclose(log_file);
	p = log_text;
	for (const char *q = log_text; (q = strchr(q, '\n')) != NULL; q++)
		lines++;
	for (unsigned i = 0; i < n && good; i++) {
		p = strstr(p, want[i]);
		good = p != NULL;
		if (good)
			p += strlen(want[i]);
	}
	if (!good || lines != n)
		tap_diag("register log:\n%s", log_text);
	free(log_text);
	log_text = NULL;
	return good && lines == n;
}

static uint32_t reg(unsigned offset, unsigned width)
{
	volatile void *p = rtos_host_map_io(TDEV_PHYS + offset, width);

	return width == 2U ? sil_reh_mem((uint16_t *)p) : sil_rew_mem((uint32_t *)p);
}

static void clear(volatile uint8_t *w)
{
	static const unsigned words[] = { 0x00, 0x04, 0x20, 0x24, 0x28, 0x2C, 0x30 };

	for (unsigned i = 0; i < HS_ARRAY_SIZE(words); i++)
		sil_wrw_mem((uint32_t *)(w + words[i]), 0);
	for (unsigned o = 0x10; o <= 0x14; o += 2)
		sil_wrh_mem((uint16_t *)(w + o), 0);
}
#endif

#if defined(__x86_64__)
static void check_x86(volatile uint8_t *w)
{
	uint64_t q;
	uint32_t l;
	uint8_t v16[16] = { 0x11, 0x11, 0x11, 0x11, 0x22, 0x22, 0x22, 0x22, 0x33, 0x33, 0x33, 0x33, 0x44, 0x44, 0x44, 0x44 };
	uint8_t r16[16];

	clear(w);
	log_start();
	__asm__ volatile("movq %1, %0" : "=m" (*(volatile uint64_t *)w) : "r" (0x0000020100000021ULL));
	ok(log_is((const char *const[]){ "W4 TDEV.A", "W4 TDEV.B" }, 2) && reg(0, 4) == 0x21U && reg(4, 4) == 0x201U &&
	   hooks == 2 && hook_order[0] == 0x00 && hook_order[1] == 0x04,
	   "an 8-byte mov over two 32-bit registers: two 32-bit writes, lowest first, each register's hook");

	log_start();
	__asm__ volatile("movq %1, %0" : "=r" (q) : "m" (*(volatile uint64_t *)w));
	ok(log_is((const char *const[]){ "R4 TDEV.A", "R4 TDEV.B" }, 2) && q == 0x0000020100000021ULL,
	   "an 8-byte load: two 32-bit reads, lowest first, combined");

	log_start();
	__asm__ volatile("movl %1, %0" : "=m" (*(volatile uint32_t *)(w + 0x12)) : "r" (0x02010021U));
	ok(log_is((const char *const[]){ "W2 TDEV.H1", "W2 TDEV.H2" }, 2) && reg(0x12, 2) == 0x21U && reg(0x14, 2) == 0x201U,
	   "a 4-byte store at a 2-aligned address over two 16-bit registers (eHRPWM's AQCTLA/AQCTLB): two 16-bit writes");

	log_start();
	__asm__ volatile("movl %1, %0" : "=r" (l) : "m" (*(volatile uint32_t *)(w + 0x10)));
	ok(log_is((const char *const[]){ "R2 TDEV.H0", "R2 TDEV.H1" }, 2) && l == 0x00210000U,
	   "a 4-byte load over two 16-bit registers: two 16-bit reads");

	log_start();
	__asm__ volatile("movl $0x00050004, %0" : "=m" (*(volatile uint32_t *)(w + 0x10)));
	ok(log_is((const char *const[]){ "W2 TDEV.H0", "W2 TDEV.H1" }, 2) && reg(0x10, 2) == 4U && reg(0x12, 2) == 5U,
	   "a 4-byte immediate store over two 16-bit registers");

	log_start();
	__asm__ volatile("movq $-2, %0" : "=m" (*(volatile uint64_t *)w));
	ok(log_is((const char *const[]){ "W4 TDEV.A", "W4 TDEV.B" }, 2) && reg(0, 4) == 0xFFFFFFFEU && reg(4, 4) == 0xFFFFFFFFU,
	   "an 8-byte sign-extended immediate store (REX.W c7)");

	log_start();
	__asm__ volatile("movdqu %1, %%xmm1\n\tmovups %%xmm1, %0" : "=m" (*(volatile uint8_t (*)[16])(w + 0x20))
			 : "m" (v16) : "xmm1");
	ok(log_is((const char *const[]){ "W4 TDEV.C", "W4 TDEV.D", "W4 TDEV.E", "W4 TDEV.F" }, 4) &&
	   reg(0x20, 4) == 0x11111111U && reg(0x2C, 4) == 0x44444444U &&
	   hooks == 4 && hook_order[0] == 0x20 && hook_order[3] == 0x2C,
	   "an SSE store (movups) over four registers: four 32-bit writes, lowest first");

	log_start();
	__asm__ volatile("movdqu %1, %%xmm2\n\tmovdqu %%xmm2, %0" : "=m" (r16)
			 : "m" (*(volatile uint8_t (*)[16])(w + 0x20)) : "xmm2");
	ok(log_is((const char *const[]){ "R4 TDEV.C", "R4 TDEV.D", "R4 TDEV.E", "R4 TDEV.F" }, 4) &&
	   memcmp(r16, v16, 16) == 0, "an SSE load (movdqu) over four registers: four reads, the value whole");

	log_start();
	__asm__ volatile("movq %1, %%xmm3\n\tmovq %%xmm3, %0" : "=m" (*(volatile uint64_t *)(w + 0x28))
			 : "r" (0x0000000700000006ULL) : "xmm3");
	ok(log_is((const char *const[]){ "W4 TDEV.E", "W4 TDEV.F" }, 2) && reg(0x28, 4) == 6U && reg(0x2C, 4) == 7U,
	   "movq from an xmm register (66 0f d6) over two registers");

	log_start();
	__asm__ volatile("movq %1, %%xmm4\n\tmovhps %%xmm4, %0" : "=m" (*(volatile uint64_t *)(w + 0x20))
			 : "m" (*(const uint64_t *)v16) : "xmm4");
	ok(log_is((const char *const[]){ "W4 TDEV.C", "W4 TDEV.D" }, 2) && reg(0x20, 4) == 0U && reg(0x24, 4) == 0U,
	   "movhps stores the xmm register's upper half (zero after movq)");

	log_start();
	__asm__ volatile("movw $0x1234, %0" : "=m" (*(volatile uint16_t *)(w + 0x32)));
	ok(log_is((const char *const[]){ "W2 TDEV.W @0x01e00032" }, 1) && reg(0x30, 4) == 0x12340000U,
	   "inside one register a narrow access stays one access at its byte lane");
}
#endif

#if defined(__arm__)
static void check_arm(volatile uint8_t *w)
{
	uint32_t l;

	clear(w);
	log_start();
	__asm__ volatile("str %1, %0" : "=m" (*(volatile uint32_t *)(w + 0x10)) : "r" (0x02010021U));
	ok(log_is((const char *const[]){ "W2 TDEV.H0", "W2 TDEV.H1" }, 2) && reg(0x10, 2) == 0x21U && reg(0x12, 2) == 0x201U,
	   "STR over two 16-bit registers: two 16-bit writes, lowest first");
	log_start();
	__asm__ volatile("ldr %0, %1" : "=r" (l) : "m" (*(volatile uint32_t *)(w + 0x10)));
	ok(log_is((const char *const[]){ "R2 TDEV.H0", "R2 TDEV.H1" }, 2) && l == 0x02010021U,
	   "LDR over two 16-bit registers: two 16-bit reads");
}
#endif

int main(void)
{
	struct hs_scenario scn = { .rtos = &cfg };
	volatile uint8_t *w;
#if defined(__x86_64__)
	const unsigned n = 11;
#elif defined(__arm__)
	const unsigned n = 2;
#else
	const unsigned n = 1;
#endif

	tap_plan(n);
	if (hs_sim_boot(&scn) != E_OK)
		tap_bail_out("boot failed");
	if (!hs_board_traps_pointers()) {
		hs_sim_shutdown();
		tap_skip(n, "the trap does not emulate accesses here");
		return tap_done();
	}
	hs_region_add(&(struct hs_region_cfg){ .name = "TDEV", .phys = TDEV_PHYS, .size = 0x1000,
		.regs = tdev_regs, .nregs = HS_ARRAY_SIZE(tdev_regs) });
	w = rtos_host_map_io(TDEV_PHYS, 0x40);
#if defined(__x86_64__)
	check_x86(w);
#elif defined(__arm__)
	check_arm(w);
#else
	(void)w;
	tap_skip(n, "no split forms to run on this host");
#endif
	hs_sim_shutdown();
	return tap_done();
}

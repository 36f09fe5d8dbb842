/*
 * test_trap_arm.c — the ARM trap end to end (the arm926 configuration, under
 * qemu-arm): each load/store form, written as an instruction in inline
 * assembly, runs on a simulated register device through the real SIGSEGV
 * path, and must leave the CPU registers (destination, base write-back, a
 * loaded PC) as the ARM926EJ-S would and make exactly the expected register
 * accesses — 8- and 16-bit ones at their byte lanes of the 32-bit registers,
 * as the AM1808's peripheral bus carries them.  An unaligned word load is
 * done as Linux's kernel alignment fixup does it (byte reads, lowest address
 * first).  An instruction the decoder does not take (Thumb code) stops the
 * run with a report naming the instruction word, its address and the
 * register's physical address.  The decoder's forms on a plain bus are
 * test_arm_decode's; elsewhere than on ARM this test skips.
 */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "tap.h"
#include "sil.h"
#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/regs.h"
#include "host_sim/scenario.h"
#include "host_sim/trace.h"

#define TDEV_PHYS 0x01E00000U
#define NTESTS    21

static const struct rtos_cfg cfg = { .name = "trap_arm" };

#if defined(__arm__) && defined(__linux__)
/* Eight 32-bit read/write registers that also take 8- and 16-bit accesses at any lane. */
static const struct hs_reg tdev_regs[] = {
	{ .name = "R", .offset = 0x0, .kind = HS_RW, .widths = HS_W8 | HS_W16, .count = 8, .stride = 4 },
};

static volatile uint32_t *tdev;
static char *log_buf;
static size_t log_len;
static FILE *log_file;

static void set_reg(unsigned i, uint32_t v)
{
	sil_wrw_mem((uint32_t *)&tdev[i], v);
}

static uint32_t get_reg(unsigned i)
{
	return sil_rew_mem((uint32_t *)&tdev[i]);
}

/* Sets R[0..7] to 0xA0000000 + i * 0x01010101. */
static void init_regs(void)
{
	for (unsigned i = 0; i < 8U; i++)
		set_reg(i, 0xA0000000U + i * 0x01010101U);
}

/* Starts recording the register log. */
static void record(void)
{
	log_file = open_memstream(&log_buf, &log_len);
	hs_trace_reglog("TDEV", log_file);
}

static void start(void)
{
	init_regs();
	record();
}

/*
 * Stops recording; true if the log is exactly `want`: its accesses, each
 * "<R|W><width> <reg> @<phys> = <value>", separated by "; ".
 */
static bool accesses(const char *what, const char *want)
{
	char got[512] = "";
	size_t n = 0;
	bool same;

	hs_trace_reglog(NULL, NULL);
	fclose(log_file);
	for (char *line = strtok(log_buf, "\n"); line != NULL; line = strtok(NULL, "\n")) {
		const char *access = strchr(line, ' ');        /* after the time */

		if (access != NULL && n < sizeof(got))
			n += (size_t)snprintf(got + n, sizeof(got) - n, "%s%s", n ? "; " : "", access + 1);
	}
	same = strcmp(got, want) == 0;
	if (!same)
		tap_diag("%s: accesses\n#   got  %s\n#   want %s", what, got, want);
	free(log_buf);
	log_buf = NULL;
	return same;
}

static void single_transfers(void)
{
	uintptr_t base = (uintptr_t)tdev, b;
	uint32_t v;

	init_regs();
	set_reg(0, 0x44332211U);
	record();
	b = base;
	__asm__ volatile("ldrb %0, [%1, #1]" : "=r" (v) : "r" (b) : "memory");
	ok(accesses("ldrb", "R1 TDEV.R[0] @0x01e00001 = 0x22") && v == 0x22U,
	   "ldrb r, [b, #1]: lane 1 of R[0] (0x44332211), one 8-bit read");

	start();
	b = base;
	v = 0xABU;
	__asm__ volatile("strb %0, [%1, #7]" : : "r" (v), "r" (b) : "memory");
	ok(accesses("strb", "W1 TDEV.R[1] @0x01e00007 = 0xab") && get_reg(1) == 0xAB010101U,
	   "strb r, [b, #7]: only lane 3 of R[1] changes (0xA1010101 -> 0xAB010101)");

	start();
	b = base;
	v = 0x1234U;
	__asm__ volatile("strh %1, [%0, #10]!" : "+r" (b) : "r" (v) : "memory");
	ok(accesses("strh", "W2 TDEV.R[2] @0x01e0000a = 0x1234") && b == base + 10U && get_reg(2) == 0x12340202U,
	   "strh r, [b, #10]!: the upper half of R[2], base written back");

	init_regs();
	set_reg(3, 0x8001A3A3U);
	record();
	b = base;
	__asm__ volatile("ldrsh %0, [%1, #14]" : "=r" (v) : "r" (b) : "memory");
	ok(accesses("ldrsh", "R2 TDEV.R[3] @0x01e0000e = 0x8001") && v == 0xFFFF8001U,
	   "ldrsh r, [b, #14]: R[3]'s upper half, sign-extended");

	start();
	b = base + 19U;
	__asm__ volatile("ldrsb %0, [%1], #-12" : "=r" (v), "+r" (b) : : "memory");
	ok(accesses("ldrsb", "R1 TDEV.R[4] @0x01e00013 = 0xa4") && v == 0xFFFFFFA4U && b == base + 7U,
	   "ldrsb r, [b], #-12: lane 3 of R[4], post-indexed, sign-extended, base written back");
}

static void register_offsets(void)
{
	uintptr_t base = (uintptr_t)tdev, b;
	uint32_t v, idx = 5;

	start();
	b = base;
	__asm__ volatile("ldr %0, [%1, %2, lsl #2]!" : "=&r" (v), "+r" (b) : "r" (idx) : "memory");
	ok(accesses("ldr lsl", "R4 TDEV.R[5] @0x01e00014 = 0xa5050505") && v == 0xA5050505U && b == base + 20U,
	   "ldr r, [b, i, lsl #2]!: R[5], base written back");

	start();
	b = base + 24U;
	v = 0x600DF00DU;
	idx = 8;
	__asm__ volatile("str %1, [%0], -%2" : "+r" (b) : "r" (v), "r" (idx) : "memory");
	ok(accesses("str post", "W4 TDEV.R[6] @0x01e00018 = 0x600df00d") && get_reg(6) == 0x600DF00DU && b == base + 16U,
	   "str r, [b], -i: R[6] written, then the base goes down by i");

	start();
	b = base + 28U;
	idx = 2;
	__asm__ volatile("ldrh %0, [%1, -%2]!" : "=&r" (v), "+r" (b) : "r" (idx) : "memory");
	ok(accesses("ldrh reg", "R2 TDEV.R[6] @0x01e0001a = 0xa606") && v == 0xA606U && b == base + 26U,
	   "ldrh r, [b, -i]!: R[6]'s upper half, base written back");
}

/* The doubleword and multiple forms name their registers: r4..r7 and the base in r2. */
static void doubles_and_multiples(void)
{
	uintptr_t base = (uintptr_t)tdev, b;
	uint32_t x[4];
	bool seen;

	start();
	b = base;
	__asm__ volatile("mov r2, %[b]\n\tldrd r4, r5, [r2, #8]!\n\t"
			 "mov %[x0], r4\n\tmov %[x1], r5\n\tmov %[b], r2"
			 : [b] "+r" (b), [x0] "=r" (x[0]), [x1] "=r" (x[1]) : : "r2", "r4", "r5", "memory");
	seen = accesses("ldrd", "R4 TDEV.R[2] @0x01e00008 = 0xa2020202; R4 TDEV.R[3] @0x01e0000c = 0xa3030303");
	ok(seen && x[0] == 0xA2020202U && x[1] == 0xA3030303U && b == base + 8U,
	   "ldrd r4, r5, [b, #8]!: two word reads, base written back");

	start();
	b = base + 16U;
	__asm__ volatile("mov r2, %[b]\n\tmov r4, #0x44\n\torr r4, r4, r4, lsl #8\n\torr r4, r4, r4, lsl #16\n\t"
			 "add r5, r4, r4, lsr #2\n\t"
			 "strd r4, r5, [r2], #-8\n\tmov %[b], r2"
			 : [b] "+r" (b) : : "r2", "r4", "r5", "memory");
	seen = accesses("strd", "W4 TDEV.R[4] @0x01e00010 = 0x44444444; W4 TDEV.R[5] @0x01e00014 = 0x55555555");
	ok(seen && get_reg(4) == 0x44444444U && get_reg(5) == 0x55555555U && b == base + 8U,
	   "strd r4, r5, [b], #-8: two word writes, post-indexed");

	start();
	b = base;
	__asm__ volatile("mov r2, %[b]\n\tldmia r2!, {r4-r7}\n\t"
			 "mov %[x0], r4\n\tmov %[x1], r5\n\tmov %[x2], r6\n\tmov %[x3], r7\n\tmov %[b], r2"
			 : [b] "+r" (b), [x0] "=r" (x[0]), [x1] "=r" (x[1]), [x2] "=r" (x[2]), [x3] "=r" (x[3])
			 : : "r2", "r4", "r5", "r6", "r7", "memory");
	seen = accesses("ldmia", "R4 TDEV.R[0] @0x01e00000 = 0xa0000000; R4 TDEV.R[1] @0x01e00004 = 0xa1010101; "
			"R4 TDEV.R[2] @0x01e00008 = 0xa2020202; R4 TDEV.R[3] @0x01e0000c = 0xa3030303");
	ok(seen && x[0] == 0xA0000000U && x[1] == 0xA1010101U && x[2] == 0xA2020202U && x[3] == 0xA3030303U &&
	   b == base + 16U, "ldmia b!, {r4-r7}: four reads in ascending order, base + 16");

	start();
	b = base + 32U;
	__asm__ volatile("mov r2, %[b]\n\tmov r4, #10\n\tmov r5, #11\n\tstmdb r2!, {r4, r5}\n\tmov %[b], r2"
			 : [b] "+r" (b) : : "r2", "r4", "r5", "memory");
	seen = accesses("stmdb", "W4 TDEV.R[6] @0x01e00018 = 0x0000000a; W4 TDEV.R[7] @0x01e0001c = 0x0000000b");
	ok(seen && get_reg(6) == 10U && get_reg(7) == 11U && b == base + 24U,
	   "stmdb b!, {r4, r5}: the lowest register at the lowest address, base - 8");

	start();
	b = base;
	__asm__ volatile("mov r2, %[b]\n\tldmib r2, {r4, r5}\n\tmov %[x0], r4\n\tmov %[x1], r5\n\tmov %[b], r2"
			 : [b] "+r" (b), [x0] "=r" (x[0]), [x1] "=r" (x[1]) : : "r2", "r4", "r5", "memory");
	seen = accesses("ldmib", "R4 TDEV.R[1] @0x01e00004 = 0xa1010101; R4 TDEV.R[2] @0x01e00008 = 0xa2020202");
	ok(seen && x[0] == 0xA1010101U && x[1] == 0xA2020202U && b == base,
	   "ldmib b, {r4, r5}: from b + 4, no write-back");

	start();
	b = base + 12U;
	__asm__ volatile("mov r2, %[b]\n\tmov r4, #1\n\tmov r5, #2\n\tstmda r2!, {r4, r5}\n\tmov %[b], r2"
			 : [b] "+r" (b) : : "r2", "r4", "r5", "memory");
	seen = accesses("stmda", "W4 TDEV.R[2] @0x01e00008 = 0x00000001; W4 TDEV.R[3] @0x01e0000c = 0x00000002");
	ok(seen && get_reg(2) == 1U && get_reg(3) == 2U && b == base + 4U, "stmda b!, {r4, r5}: ending at b, base - 8");
}

static void swaps_and_branches(void)
{
	uintptr_t base = (uintptr_t)tdev;
	uint32_t old, v = 0x5A5A5A5AU, skipped;

	start();
	__asm__ volatile("swp %0, %1, [%2]" : "=&r" (old) : "r" (v), "r" (base + 4U) : "memory");
	ok(accesses("swp", "R4 TDEV.R[1] @0x01e00004 = 0xa1010101; W4 TDEV.R[1] @0x01e00004 = 0x5a5a5a5a") &&
	   old == 0xA1010101U && get_reg(1) == 0x5A5A5A5AU, "swp: one read, then one write of R[1]");

	start();
	v = 0x7EU;
	__asm__ volatile("swpb %0, %1, [%2]" : "=&r" (old) : "r" (v), "r" (base + 9U) : "memory");
	ok(accesses("swpb", "R1 TDEV.R[2] @0x01e00009 = 0x02; W1 TDEV.R[2] @0x01e00009 = 0x7e") &&
	   old == 0x02U && get_reg(2) == 0xA2027E02U, "swpb at lane 1 of R[2]: one byte read, one byte written");

	/* A code address stored in a register, then loaded into the PC: the branch is taken. */
	{
		uint32_t target;
		char want[200];

		start();
		__asm__ volatile("adr %1, 1f\n\t"
				 "str %1, [%2, #4]\n\t"
				 "mov %0, #1\n\t"
				 "ldmia %2, {r3, pc}\n\t"
				 "mov %0, #2\n"          /* skipped by the branch */
				 "1:"
				 : "=&r" (skipped), "=&r" (target) : "r" (base) : "r3", "memory");
		snprintf(want, sizeof(want), "W4 TDEV.R[1] @0x01e00004 = 0x%08x; R4 TDEV.R[0] @0x01e00000 = 0xa0000000; "
			 "R4 TDEV.R[1] @0x01e00004 = 0x%08x", target, target);
		ok(skipped == 1U && accesses("ldm pc", want),
		   "ldmia b, {r3, pc}: two reads, and execution goes on at the loaded PC");

		start();
		__asm__ volatile("adr %1, 1f\n\t"
				 "str %1, [%2, #8]\n\t"
				 "mov %0, #1\n\t"
				 "ldr pc, [%2, #8]\n\t"
				 "mov %0, #2\n"
				 "1:"
				 : "=&r" (skipped), "=&r" (target) : "r" (base) : "memory");
		snprintf(want, sizeof(want), "W4 TDEV.R[2] @0x01e00008 = 0x%08x; R4 TDEV.R[2] @0x01e00008 = 0x%08x",
			 target, target);
		ok(skipped == 1U && accesses("ldr pc", want), "ldr pc, [b, #8]: a branch through a register");
	}
}

/* An unaligned load, and an instruction the decoder refuses, each alone in a function so that its address is known. */
__asm__(".text\n"
	".arm\n"
	".balign 4\n"
	".global trap_arm_unaligned_load\n"
	".type trap_arm_unaligned_load, %function\n"
	"trap_arm_unaligned_load:\n"
	"	ldr r0, [r0, #1]\n"
	"	bx lr\n"
	".size trap_arm_unaligned_load, . - trap_arm_unaligned_load\n"
	".thumb\n"
	".balign 4\n"
	".global trap_arm_thumb_load\n"
	".type trap_arm_thumb_load, %function\n"
	".thumb_func\n"
	"trap_arm_thumb_load:\n"
	"	nop\n"                 /* the load at an odd halfword */
	"	ldr r0, [r0]\n"
	"	bx lr\n"
	".size trap_arm_thumb_load, . - trap_arm_thumb_load\n"
	".arm\n");
uint32_t trap_arm_unaligned_load(volatile void *p);
uint32_t trap_arm_thumb_load(volatile void *p);

/* Runs fn(p) in a child; true if it died (not exiting 0) with a report containing each of parts. */
static bool stops_with_report(const char *what, uint32_t (*fn)(volatile void *), volatile void *p,
			      const char *const parts[], size_t nparts)
{
	char out[4096];
	size_t len = 0;
	ssize_t n;
	int fds[2], status;
	bool good = true;
	pid_t pid;

	fflush(NULL);
	if (pipe(fds) != 0)
		return false;
	pid = fork();
	if (pid == 0) {
		close(fds[0]);
		dup2(fds[1], 1);
		dup2(fds[1], 2);
		fn(p);
		fflush(NULL);
		_exit(0);
	}
	close(fds[1]);
	while (len + 1 < sizeof(out) && (n = read(fds[0], out + len, sizeof(out) - 1 - len)) > 0)
		len += (size_t)n;
	out[len] = '\0';
	close(fds[0]);
	waitpid(pid, &status, 0);
	if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
		tap_diag("%s: the child went on", what);
		good = false;
	}
	for (size_t i = 0; i < nparts; i++)
		if (strstr(out, parts[i]) == NULL) {
			tap_diag("%s: no \"%s\" in the report:\n%s", what, parts[i], out);
			good = false;
		}
	return good;
}

static void refusals(void)
{
	char thumb_pc_text[48];
	uint32_t v;

	snprintf(thumb_pc_text, sizeof(thumb_pc_text), "the instruction at %p",
		 (void *)(((uintptr_t)trap_arm_thumb_load & ~(uintptr_t)1) + 2U));
	init_regs();
	set_reg(0, 0x44332211U);
	record();
	v = trap_arm_unaligned_load(tdev);
	ok(accesses("unaligned ldr", "R1 TDEV.R[0] @0x01e00001 = 0x22; R1 TDEV.R[0] @0x01e00002 = 0x33; "
				     "R1 TDEV.R[0] @0x01e00003 = 0x44; R1 TDEV.R[1] @0x01e00004 = 0x01") &&
	   v == 0x01443322U,
	   "an unaligned ldr on a register: four byte reads, lowest first, as Linux's alignment fixup does");
	{
		const char *const parts[] = { "(physical 0x01e00000)", thumb_pc_text, "Thumb instruction",
					      "instruction word 0x00006800" };

		ok(stops_with_report("thumb", trap_arm_thumb_load, tdev, parts, HS_ARRAY_SIZE(parts)),
		   "a Thumb load on a register stops with a report saying so, naming its halfword");
	}
}
#endif

int main(void)
{
	struct hs_scenario scn = { .rtos = &cfg };

	tap_plan(NTESTS);
#if defined(__arm__) && defined(__linux__)
	if (hs_sim_boot(&scn) != E_OK)
		tap_bail_out("boot failed");
	if (!hs_board_traps_pointers())
		tap_bail_out("the ARM trap is not installed");
	hs_region_add(&(struct hs_region_cfg){ .name = "TDEV", .phys = TDEV_PHYS, .size = 0x1000,
		.regs = tdev_regs, .nregs = HS_ARRAY_SIZE(tdev_regs) });
	tdev = rtos_host_map_io(TDEV_PHYS, 32);
	ok((uintptr_t)tdev == TDEV_PHYS, "the register window is at its physical address (0x%08lx)",
	   (unsigned long)(uintptr_t)tdev);
	single_transfers();
	register_offsets();
	doubles_and_multiples();
	swaps_and_branches();
	refusals();
	hs_sim_shutdown();
#else
	(void)scn;
	tap_skip(NTESTS, "the ARM trap runs in the arm926 configuration (qemu-arm)");
#endif
	return tap_done();
}

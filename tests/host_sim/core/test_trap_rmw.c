/*
 * test_trap_rmw.c — the x86 trap (x86-64 and i386)'s read-modify-write and compare forms,
 * instruction by instruction: each form runs once on plain memory and once
 * on a trapped register window, from several start values and operands,
 * and must leave the same memory value, the same destination register and
 * the same arithmetic flags (OF SF ZF AF PF CF); an RMW is one bus read and
 * one write of the instruction's width, a compare or bit test one read.
 * (Narrow forms here use byte lane 0; the other lanes are test_trap_arm's
 * and test_regs'.)  Compound statements through a plain pointer at -O2 on
 * every host whose trap emulates (on ARM the forms are test_arm_decode's
 * and test_trap_arm's).
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

#define TDEV_PHYS   0x01E00000U
#define ARITH_FLAGS 0x8D5U

static const struct rtos_cfg cfg = { .name = "trap_rmw" };

static const struct hs_reg tdev_regs[] = {
	{ .name = "R32", .offset = 0x0, .kind = HS_RW, .widths = HS_W8 | HS_W16 },
};

#if defined(__x86_64__) || defined(__i386__)
#define X86_FORMS 1
#ifdef __x86_64__
/* below the red zone, as the trap's own flags computation does */
#define SP_DOWN "lea -128(%%rsp), %%rsp\n\t"
#define SP_UP "\n\tlea 128(%%rsp), %%rsp"
#else
#define SP_DOWN ""
#define SP_UP ""
#endif
static const uint32_t starts[] = { 0x00000000U, 0x00000001U, 0x7FFFFFFFU, 0x80000000U, 0xFFFFFFFFU, 0x12F0A55AU };
static const uint32_t operands[] = { 0x00000000U, 0x00000001U, 0x0000001FU, 0x80000080U, 0xFFFFFFFFU, 0x00000F0FU };

struct outcome {
	uint32_t mem, reg, flags;
};

/* Runs `text` (operands %[m] memory of type, %[r] register) with all arithmetic flags set or clear. */
#define FORM(name, type, text)								\
	static struct outcome name(volatile void *mem, uint32_t reg, bool carry_in)	\
	{										\
		unsigned long f;							\
		struct outcome o;							\
		__asm__ volatile(SP_DOWN						\
				 "push %[c]\n\tpopf\n\t"					\
				 text "\n\t"						\
				 "pushf\n\tpop %[f]" SP_UP					\
				 : [m] "+m" (*(type *)mem), [r] "+q" (reg), [f] "=&r" (f)	\
				 : [c] "r" ((unsigned long)(carry_in ? 0x202U | ARITH_FLAGS : 0x202U)) : "cc", "memory");	\
		o.reg = reg;								\
		o.flags = (uint32_t)f & ARITH_FLAGS;					\
		o.mem = 0;								\
		return o;								\
	}

FORM(or_rm_r,    uint32_t, "orl %k[r], %[m]")
FORM(and_rm_i32, uint32_t, "andl $0xFFFF00FF, %[m]")
FORM(xor_rm_i8,  uint32_t, "xorl $0x10, %[m]")
FORM(add_rm_r,   uint32_t, "addl %k[r], %[m]")
FORM(adc_rm_r,   uint32_t, "adcl %k[r], %[m]")
FORM(sbb_rm_i8,  uint32_t, "sbbl $-3, %[m]")
FORM(sub_rm_r,   uint32_t, "subl %k[r], %[m]")
FORM(cmp_rm_r,   uint32_t, "cmpl %k[r], %[m]")
FORM(cmp_rm_i8,  uint32_t, "cmpl $5, %[m]")
FORM(cmp_r_rm,   uint32_t, "cmpl %[m], %k[r]")
FORM(or_r_rm,    uint32_t, "orl %[m], %k[r]")
FORM(sub_r_rm,   uint32_t, "subl %[m], %k[r]")
FORM(test_rm_r,  uint32_t, "testl %k[r], %[m]")
FORM(test_rm_i,  uint32_t, "testl $0x80000000, %[m]")
FORM(inc_rm,     uint32_t, "incl %[m]")
FORM(dec_rm,     uint32_t, "decl %[m]")
FORM(not_rm,     uint32_t, "notl %[m]")
FORM(neg_rm,     uint32_t, "negl %[m]")
FORM(bts_rm_r,   uint32_t, "andl $31, %k[r]\n\tbtsl %k[r], %[m]")
FORM(btr_rm_i,   uint32_t, "btrl $3, %[m]")
FORM(bt_rm_i,    uint32_t, "btl $31, %[m]")
FORM(btc_rm_i,   uint32_t, "btcl $0, %[m]")
FORM(lock_or,    uint32_t, "lock orl %k[r], %[m]")
FORM(or_rm_r16,  uint16_t, "orw %w[r], %[m]")
FORM(and_rm_i16, uint16_t, "andw $0x00FF, %[m]")
FORM(add_rm_i8w, uint16_t, "addw $-1, %[m]")
FORM(or_rm_r8,   uint8_t,  "orb %b[r], %[m]")
FORM(and_rm_i8b, uint8_t,  "andb $0xF0, %[m]")
FORM(test_rm_i8, uint8_t,  "testb $0x80, %[m]")
FORM(add_r8_rm,  uint8_t,  "addb %[m], %b[r]")
FORM(inc_rm8,    uint8_t,  "incb %[m]")
FORM(neg_rm16,   uint16_t, "negw %[m]")

struct form {
	const char *name;
	struct outcome (*run)(volatile void *mem, uint32_t reg, bool carry_in);
	unsigned width;        /* memory operand width */
	unsigned offset;       /* byte lane used in the 32-bit register */
	bool writes;           /* one read and one write (else one read) */
};

static const struct form forms[] = {
	{ "or r/m32, r32 (09)", or_rm_r, 4, 0, true },
	{ "and r/m32, imm32 (81 /4)", and_rm_i32, 4, 0, true },
	{ "xor r/m32, imm8 (83 /6)", xor_rm_i8, 4, 0, true },
	{ "add r/m32, r32 (01)", add_rm_r, 4, 0, true },
	{ "adc r/m32, r32 (11)", adc_rm_r, 4, 0, true },
	{ "sbb r/m32, imm8 (83 /3)", sbb_rm_i8, 4, 0, true },
	{ "sub r/m32, r32 (29)", sub_rm_r, 4, 0, true },
	{ "cmp r/m32, r32 (39)", cmp_rm_r, 4, 0, false },
	{ "cmp r/m32, imm8 (83 /7)", cmp_rm_i8, 4, 0, false },
	{ "cmp r32, r/m32 (3b)", cmp_r_rm, 4, 0, false },
	{ "or r32, r/m32 (0b)", or_r_rm, 4, 0, false },
	{ "sub r32, r/m32 (2b)", sub_r_rm, 4, 0, false },
	{ "test r/m32, r32 (85)", test_rm_r, 4, 0, false },
	{ "test r/m32, imm32 (f7 /0)", test_rm_i, 4, 0, false },
	{ "inc r/m32 (ff /0)", inc_rm, 4, 0, true },
	{ "dec r/m32 (ff /1)", dec_rm, 4, 0, true },
	{ "not r/m32 (f7 /2)", not_rm, 4, 0, true },
	{ "neg r/m32 (f7 /3)", neg_rm, 4, 0, true },
	{ "bts r/m32, r32 (0f ab)", bts_rm_r, 4, 0, true },
	{ "btr r/m32, imm8 (0f ba /6)", btr_rm_i, 4, 0, true },
	{ "bt r/m32, imm8 (0f ba /4)", bt_rm_i, 4, 0, false },
	{ "btc r/m32, imm8 (0f ba /7)", btc_rm_i, 4, 0, true },
	{ "lock or r/m32, r32", lock_or, 4, 0, true },
	{ "or r/m16, r16 (66 09)", or_rm_r16, 2, 0, true },
	{ "and r/m16, imm16 (66 81 /4)", and_rm_i16, 2, 0, true },
	{ "add r/m16, imm8 (66 83 /0)", add_rm_i8w, 2, 0, true },
	{ "or r/m8, r8 (08)", or_rm_r8, 1, 0, true },
	{ "and r/m8, imm8 (80 /4)", and_rm_i8b, 1, 0, true },
	{ "test r/m8, imm8 (f6 /0)", test_rm_i8, 1, 0, false },
	{ "add r8, r/m8 (02)", add_r8_rm, 1, 0, false },
	{ "inc r/m8 (fe /0)", inc_rm8, 1, 0, true },
	{ "neg r/m16 (66 f7 /3)", neg_rm16, 2, 0, true },
};

/* Counts the register log's lines of one kind ("R4 TDEV.R32" etc.). */
static unsigned count(const char *log, const char *what)
{
	unsigned n = 0;

	for (const char *p = log; (p = strstr(p, what)) != NULL; p += strlen(what))
		n++;
	return n;
}

static void check_form(const struct form *fm, volatile uint32_t *reg32)
{
	unsigned mismatches = 0, bus_errors = 0;
	char rd[32], wr[32];

	snprintf(rd, sizeof(rd), "R%u TDEV.R32", fm->width);
	snprintf(wr, sizeof(wr), "W%u TDEV.R32", fm->width);
	for (size_t s = 0; s < HS_ARRAY_SIZE(starts); s++) {
		for (size_t k = 0; k < HS_ARRAY_SIZE(operands); k++) {
			for (int carry = 0; carry < 2; carry++) {
				uint32_t plain = starts[s];
				struct outcome want, got;
				char *log = NULL;
				size_t len = 0;
				FILE *f;

				want = fm->run((uint8_t *)&plain + fm->offset, operands[k], carry);
				want.mem = plain;
				sil_wrw_mem((uint32_t *)reg32, starts[s]);
				f = open_memstream(&log, &len);
				hs_trace_reglog("*", f);
				got = fm->run((volatile uint8_t *)reg32 + fm->offset, operands[k], carry);
				hs_trace_reglog(NULL, NULL);
				fclose(f);
				got.mem = sil_rew_mem((uint32_t *)reg32);
				if (memcmp(&want, &got, sizeof(want)) != 0) {
					if (mismatches++ == 0)
						tap_diag("%s from %08x, operand %08x, CF %d: want mem %08x reg %08x flags %03x,"
							 " got %08x %08x %03x", fm->name, starts[s], operands[k], carry,
							 want.mem, want.reg, want.flags, got.mem, got.reg, got.flags);
				}
				if (count(log, rd) != 1 || count(log, wr) != (fm->writes ? 1U : 0U)) {
					if (bus_errors++ == 0)
						tap_diag("%s: bus log\n%s", fm->name, log);
				}
				free(log);
			}
		}
	}
	ok(mismatches == 0 && bus_errors == 0, "%s: memory, register and flags as on plain memory; %s",
	   fm->name, fm->writes ? "one read, one write" : "one read only");
}
#endif

int main(void)
{
	struct hs_scenario scn = { .rtos = &cfg };

#ifdef X86_FORMS
	tap_plan(HS_ARRAY_SIZE(forms) + 1);
#else
	tap_plan(1);
#endif
	if (hs_sim_boot(&scn) != E_OK)
		tap_bail_out("boot failed");
	if (!hs_board_traps_pointers()) {
		hs_sim_shutdown();
		tap_skip(1, "the trap does not emulate accesses here");
		return tap_done();
	}
	{
		volatile uint32_t *reg32;

		hs_region_add(&(struct hs_region_cfg){ .name = "TDEV", .phys = TDEV_PHYS, .size = 0x1000,
			.regs = tdev_regs, .nregs = HS_ARRAY_SIZE(tdev_regs) });
		reg32 = rtos_host_map_io(TDEV_PHYS, 4);
#ifdef X86_FORMS
		for (size_t i = 0; i < HS_ARRAY_SIZE(forms); i++)
			check_form(&forms[i], reg32);
#endif
		/* What gcc -O2 makes of compound statements through plain pointers
		 * (on ARM: LDR/ORR/STR, LDRH/ADD/STRH, performed by the ARM decoder). */
		sil_wrw_mem((uint32_t *)reg32, 0x0F0F0000U);
		*reg32 |= 0x11U;
		*reg32 &= ~0x0F000000U;
		reg32[0] = (reg32[0] & ~0xF0U) | 0x20U;
		*(volatile uint16_t *)reg32 += 1;
		is_u64(sil_rew_mem((uint32_t *)reg32), 0x000F0022U, "compound statements on a register at -O2");
	}
	hs_sim_shutdown();
	return tap_done();
}

/*
 * test_arm_decode.c — hs_arm_emulate, the ARM load/store decoder of the
 * arm926 trap, on a plain memory bus that records every access: each form
 * (words as GNU as encodes them for -march=armv5te) leaves the registers,
 * the PC and memory as the ARM926EJ-S would and makes exactly the bus
 * accesses expected; write-back, every offset shift, negative offsets, the
 * PC as a base and a load into the PC (interworking); what is not a
 * load/store, or not emulated, is refused with its reason and changes
 * nothing.  Pure: runs in every configuration.
 */
#include <stdio.h>
#include <string.h>

#include "tap.h"
#include "host_sim/arm_decode.h"

#define BASE     0x01E00000U
#define MEM_SIZE 0x100U
#define R1_START (BASE + 0x40U)
#define PC_START 0x00010000U
#define MAX_ACC  8

struct access {
	char dir;          /* 'r' or 'w' */
	uint32_t addr;
	unsigned width;
	uint32_t value;
};

static uint8_t mem[MEM_SIZE];
static struct access log_[MAX_ACC];
static unsigned nlog;

static uint32_t mem_get(uint32_t addr, unsigned width)
{
	uint32_t v = 0;

	for (unsigned i = 0; i < width; i++)
		v |= (uint32_t)mem[addr - BASE + i] << (8U * i);
	return v;
}

static uint32_t bus_read(void *ctx, uint32_t addr, unsigned width)
{
	uint32_t v = mem_get(addr, width);

	(void)ctx;
	if (nlog < MAX_ACC)
		log_[nlog++] = (struct access){ 'r', addr, width, v };
	return v;
}

static void bus_write(void *ctx, uint32_t addr, unsigned width, uint32_t value)
{
	(void)ctx;
	for (unsigned i = 0; i < width; i++)
		mem[addr - BASE + i] = (uint8_t)(value >> (8U * i));
	if (nlog < MAX_ACC)
		log_[nlog++] = (struct access){ 'w', addr, width, value };
}

static const struct hs_arm_bus bus = { .read = bus_read, .write = bus_write };

struct reg_expect {
	int reg;           /* -1: end */
	uint32_t value;
};

struct form {
	uint32_t insn;
	const char *text;
	struct reg_expect regs[5];     /* registers that change (the PC is checked separately) */
	uint32_t pc;                   /* 0: PC_START + 4 */
	struct access acc[4];
	unsigned nacc;
};

/* Memory word i (at BASE + 4i) holds 0xA0000000 + i * 0x01010101. */
#define WORD(i)  (0xA0000000U + (uint32_t)(i) * 0x01010101U)

static const struct form forms[] = {
	{ 0xe5910000, "ldr r0, [r1]", { { 0, WORD(16) }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x40, 4, WORD(16) } }, 1 },
	{ 0xe5910004, "ldr r0, [r1, #4]", { { 0, WORD(17) }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x44, 4, WORD(17) } }, 1 },
	{ 0xe5110004, "ldr r0, [r1, #-4]", { { 0, WORD(15) }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x3C, 4, WORD(15) } }, 1 },
	{ 0xe5b10008, "ldr r0, [r1, #8]!", { { 0, WORD(18) }, { 1, R1_START + 8 }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x48, 4, WORD(18) } }, 1 },
	{ 0xe4910004, "ldr r0, [r1], #4", { { 0, WORD(16) }, { 1, R1_START + 4 }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x40, 4, WORD(16) } }, 1 },
	{ 0xe7910002, "ldr r0, [r1, r2]", { { 0, WORD(18) }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x48, 4, WORD(18) } }, 1 },
	{ 0xe7110002, "ldr r0, [r1, -r2]", { { 0, WORD(14) }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x38, 4, WORD(14) } }, 1 },
	{ 0xe7910102, "ldr r0, [r1, r2, lsl #2]", { { 0, WORD(24) }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x60, 4, WORD(24) } }, 1 },
	{ 0xe79100a2, "ldr r0, [r1, r2, lsr #1]", { { 0, WORD(17) }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x44, 4, WORD(17) } }, 1 },
	{ 0xe79100c3, "ldr r0, [r1, r3, asr #1]", { { 0, WORD(15) }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x3C, 4, WORD(15) } }, 1 },
	{ 0xe7910464, "ldr r0, [r1, r4, ror #8]", { { 0, WORD(20) }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x50, 4, WORD(20) } }, 1 },
	{ 0xe7910065, "ldr r0, [r1, r5, rrx]", { { 0, WORD(20) }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x50, 4, WORD(20) } }, 1 },
	{ 0xe7b10102, "ldr r0, [r1, r2, lsl #2]!", { { 0, WORD(24) }, { 1, R1_START + 0x20 }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x60, 4, WORD(24) } }, 1 },
	{ 0xe6910002, "ldr r0, [r1], r2", { { 0, WORD(16) }, { 1, R1_START + 8 }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x40, 4, WORD(16) } }, 1 },
	{ 0xe5810000, "str r0, [r1]", { { -1, 0 } }, 0,
	  { { 'w', BASE + 0x40, 4, 0x11223344 } }, 1 },
	{ 0xe5210008, "str r0, [r1, #-8]!", { { 1, R1_START - 8 }, { -1, 0 } }, 0,
	  { { 'w', BASE + 0x38, 4, 0x11223344 } }, 1 },
	{ 0xe4010004, "str r0, [r1], #-4", { { 1, R1_START - 4 }, { -1, 0 } }, 0,
	  { { 'w', BASE + 0x40, 4, 0x11223344 } }, 1 },
	{ 0xe5c10003, "strb r0, [r1, #3]", { { -1, 0 } }, 0,
	  { { 'w', BASE + 0x43, 1, 0x44 } }, 1 },
	{ 0xe5d10002, "ldrb r0, [r1, #2]", { { 0, (WORD(16) >> 16) & 0xFF }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x42, 1, (WORD(16) >> 16) & 0xFF } }, 1 },
	{ 0xe4f10001, "ldrbt r0, [r1], #1", { { 0, WORD(16) & 0xFF }, { 1, R1_START + 1 }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x40, 1, WORD(16) & 0xFF } }, 1 },
	{ 0xe4a10004, "strt r0, [r1], #4", { { 1, R1_START + 4 }, { -1, 0 } }, 0,
	  { { 'w', BASE + 0x40, 4, 0x11223344 } }, 1 },
	{ 0xe1d100b2, "ldrh r0, [r1, #2]", { { 0, WORD(16) >> 16 }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x42, 2, WORD(16) >> 16 } }, 1 },
	{ 0xe19100b2, "ldrh r0, [r1, r2]", { { 0, WORD(18) & 0xFFFF }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x48, 2, WORD(18) & 0xFFFF } }, 1 },
	{ 0xe1f100b2, "ldrh r0, [r1, #2]!", { { 0, WORD(16) >> 16 }, { 1, R1_START + 2 }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x42, 2, WORD(16) >> 16 } }, 1 },
	{ 0xe05100b2, "ldrh r0, [r1], #-2", { { 0, WORD(16) & 0xFFFF }, { 1, R1_START - 2 }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x40, 2, WORD(16) & 0xFFFF } }, 1 },
	{ 0xe1c100b6, "strh r0, [r1, #6]", { { -1, 0 } }, 0,
	  { { 'w', BASE + 0x46, 2, 0x3344 } }, 1 },
	{ 0xe1d100d1, "ldrsb r0, [r1, #1]", { { 0, 0xFFFFFF90U }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x41, 1, 0x90 } }, 1 },
	{ 0xe1d100f2, "ldrsh r0, [r1, #2]", { { 0, 0xFFFFB090U }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x42, 2, 0xB090 } }, 1 },
	{ 0xe1c140d8, "ldrd r4, [r1, #8]", { { 4, WORD(18) }, { 5, WORD(19) }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x48, 4, WORD(18) }, { 'r', BASE + 0x4C, 4, WORD(19) } }, 2 },
	{ 0xe16140f8, "strd r4, [r1, #-8]!", { { 1, R1_START - 8 }, { -1, 0 } }, 0,
	  { { 'w', BASE + 0x38, 4, 0x00000014 }, { 'w', BASE + 0x3C, 4, 0x55667788 } }, 2 },
	{ 0xe891000d, "ldm r1, {r0, r2, r3}", { { 0, WORD(16) }, { 2, WORD(17) }, { 3, WORD(18) }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x40, 4, WORD(16) }, { 'r', BASE + 0x44, 4, WORD(17) }, { 'r', BASE + 0x48, 4, WORD(18) } }, 3 },
	{ 0xe8b10005, "ldm r1!, {r0, r2}", { { 0, WORD(16) }, { 2, WORD(17) }, { 1, R1_START + 8 }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x40, 4, WORD(16) }, { 'r', BASE + 0x44, 4, WORD(17) } }, 2 },
	{ 0xe9910005, "ldmib r1, {r0, r2}", { { 0, WORD(17) }, { 2, WORD(18) }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x44, 4, WORD(17) }, { 'r', BASE + 0x48, 4, WORD(18) } }, 2 },
	{ 0xe8110005, "ldmda r1, {r0, r2}", { { 0, WORD(15) }, { 2, WORD(16) }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x3C, 4, WORD(15) }, { 'r', BASE + 0x40, 4, WORD(16) } }, 2 },
	{ 0xe9310005, "ldmdb r1!, {r0, r2}", { { 0, WORD(14) }, { 2, WORD(15) }, { 1, R1_START - 8 }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x38, 4, WORD(14) }, { 'r', BASE + 0x3C, 4, WORD(15) } }, 2 },
	{ 0xe8a1000d, "stmia r1!, {r0, r2, r3}", { { 1, R1_START + 12 }, { -1, 0 } }, 0,
	  { { 'w', BASE + 0x40, 4, 0x11223344 }, { 'w', BASE + 0x44, 4, 8 }, { 'w', BASE + 0x48, 4, 0xFFFFFFF8U } }, 3 },
	{ 0xe9010005, "stmdb r1, {r0, r2}", { { -1, 0 } }, 0,
	  { { 'w', BASE + 0x38, 4, 0x11223344 }, { 'w', BASE + 0x3C, 4, 8 } }, 2 },
	{ 0xe8918001, "ldm r1, {r0, pc}", { { 0, WORD(16) }, { -1, 0 } }, WORD(17) & ~1U,
	  { { 'r', BASE + 0x40, 4, WORD(16) }, { 'r', BASE + 0x44, 4, WORD(17) } }, 2 },
	{ 0xe1010092, "swp r0, r2, [r1]", { { 0, WORD(16) }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x40, 4, WORD(16) }, { 'w', BASE + 0x40, 4, 8 } }, 2 },
	{ 0xe1410092, "swpb r0, r2, [r1]", { { 0, WORD(16) & 0xFF }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x40, 1, WORD(16) & 0xFF }, { 'w', BASE + 0x40, 1, 8 } }, 2 },
	{ 0xe6310082, "ldrt r0, [r1], -r2, lsl #1", { { 0, WORD(16) }, { 1, R1_START - 16 }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x40, 4, WORD(16) } }, 1 },
	{ 0xe7910022, "ldr r0, [r1, r2, lsr #32]", { { 0, WORD(16) }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x40, 4, WORD(16) } }, 1 },
	{ 0xe7d10043, "ldrb r0, [r1, r3, asr #32]", { { 0, WORD(15) >> 24 }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x3F, 1, WORD(15) >> 24 } }, 1 },
	{ 0xe491f004, "ldr pc, [r1], #4", { { 1, R1_START + 4 }, { -1, 0 } }, WORD(16),
	  { { 'r', BASE + 0x40, 4, WORD(16) } }, 1 },
	{ 0xe13100d2, "ldrsb r0, [r1, -r2]!", { { 0, WORD(14) & 0xFF }, { 1, R1_START - 8 }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x38, 1, WORD(14) & 0xFF } }, 1 },
	{ 0xe09100f2, "ldrsh r0, [r1], r2", { { 0, WORD(16) & 0xFFFF }, { 1, R1_START + 8 }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x40, 2, WORD(16) & 0xFFFF } }, 1 },
	{ 0xe1a100b2, "strh r0, [r1, r2]!", { { 1, R1_START + 8 }, { -1, 0 } }, 0,
	  { { 'w', BASE + 0x48, 2, 0x3344 } }, 1 },
	{ 0xe15102b2, "ldrh r0, [r1, #-34] (split immediate)", { { 0, WORD(7) >> 16 }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x1E, 2, WORD(7) >> 16 } }, 1 },
	{ 0xe0c140d8, "ldrd r4, [r1], #8", { { 4, WORD(16) }, { 5, WORD(17) }, { 1, R1_START + 8 }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x40, 4, WORD(16) }, { 'r', BASE + 0x44, 4, WORD(17) } }, 2 },
	{ 0xe18140d2, "ldrd r4, [r1, r2]", { { 4, WORD(18) }, { 5, WORD(19) }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x48, 4, WORD(18) }, { 'r', BASE + 0x4C, 4, WORD(19) } }, 2 },
	{ 0xe10140f2, "strd r4, [r1, -r2]", { { -1, 0 } }, 0,
	  { { 'w', BASE + 0x38, 4, 0x00001000 }, { 'w', BASE + 0x3C, 4, 0x00000020 } }, 2 },
	{ 0xe9a10005, "stmib r1!, {r0, r2}", { { 1, R1_START + 8 }, { -1, 0 } }, 0,
	  { { 'w', BASE + 0x44, 4, 0x11223344 }, { 'w', BASE + 0x48, 4, 8 } }, 2 },
	{ 0xe8010005, "stmda r1, {r0, r2}", { { -1, 0 } }, 0,
	  { { 'w', BASE + 0x3C, 4, 0x11223344 }, { 'w', BASE + 0x40, 4, 8 } }, 2 },
	{ 0xe8818001, "stm r1, {r0, pc} (the PC stored as its address + 12)", { { -1, 0 } }, 0,
	  { { 'w', BASE + 0x40, 4, 0x11223344 }, { 'w', BASE + 0x44, 4, PC_START + 12 } }, 2 },
	{ 0x15910000, "ldrne r0, [r1] (it faulted: its condition passed)", { { 0, WORD(16) }, { -1, 0 } }, 0,
	  { { 'r', BASE + 0x40, 4, WORD(16) } }, 1 },
};

/* The registers each form starts from. */
static void start_regs(uint32_t regs[16])
{
	memset(regs, 0, 16 * sizeof(regs[0]));
	regs[0] = 0x11223344U;
	regs[1] = R1_START;
	regs[2] = 8;                   /* offsets: 8; lsl #2 = 32; lsr #1 = 4 */
	regs[3] = 0xFFFFFFF8U;         /* asr #1 = -4 */
	regs[4] = 0x00001000U;         /* ror #8 = 0x10 */
	regs[5] = 0x00000020U;         /* rrx, carry clear: 0x10 */
	regs[15] = PC_START;
}

static void fill_memory(void)
{
	for (unsigned i = 0; i < MEM_SIZE / 4U; i++)
		for (unsigned b = 0; b < 4U; b++)
			mem[4U * i + b] = (uint8_t)(WORD(i) >> (8U * b));
}

static bool check_form(const struct form *f)
{
	uint32_t regs[16], before[16], cpsr = 0x10U, expect_pc = f->pc ? f->pc : PC_START + 4U;
	char why[160] = "";
	bool good = true;

	fill_memory();
	if (f->insn == 0xe1d100d1U)                /* ldrsb: a negative byte */
		mem[0x41] = 0x90;
	if (f->insn == 0xe1d100f2U) {              /* ldrsh: a negative halfword, 0xB090 */
		mem[0x42] = 0x90;
		mem[0x43] = 0xB0;
	}
	start_regs(regs);
	if (f->insn == 0xe16140f8U) {              /* strd r4, r5 */
		regs[4] = 0x14;
		regs[5] = 0x55667788U;
	}
	memcpy(before, regs, sizeof(before));
	nlog = 0;
	if (hs_arm_emulate(f->insn, regs, &cpsr, &bus, why, sizeof(why)) != 0) {
		tap_diag("%s: refused: %s", f->text, why);
		return false;
	}
	for (int r = 0; r < 15; r++) {
		uint32_t want = before[r];

		for (const struct reg_expect *e = f->regs; e->reg >= 0; e++)
			if (e->reg == r)
				want = e->value;
		if (regs[r] != want) {
			tap_diag("%s: r%d = 0x%08x, expected 0x%08x", f->text, r, regs[r], want);
			good = false;
		}
	}
	if (regs[15] != expect_pc) {
		tap_diag("%s: pc = 0x%08x, expected 0x%08x", f->text, regs[15], expect_pc);
		good = false;
	}
	if (nlog != f->nacc) {
		tap_diag("%s: %u bus accesses, expected %u", f->text, nlog, f->nacc);
		return false;
	}
	for (unsigned i = 0; i < nlog; i++)
		if (log_[i].dir != f->acc[i].dir || log_[i].addr != f->acc[i].addr ||
		    log_[i].width != f->acc[i].width || log_[i].value != f->acc[i].value) {
			tap_diag("%s: access %u: %c 0x%08x/%u = 0x%08x, expected %c 0x%08x/%u = 0x%08x", f->text, i,
			     log_[i].dir, log_[i].addr, log_[i].width, log_[i].value, f->acc[i].dir,
			     f->acc[i].addr, f->acc[i].width, f->acc[i].value);
			good = false;
		}
	return good;
}

/* A refused word: -1, a reason naming it, nothing changed, no access. */
static void check_refused(uint32_t insn, uint32_t cpsr_in, const char *text, const char *reason_part)
{
	uint32_t regs[16], before[16], cpsr = cpsr_in;
	char why[160] = "";
	int ret;

	start_regs(regs);
	memcpy(before, regs, sizeof(before));
	nlog = 0;
	ret = hs_arm_emulate(insn, regs, &cpsr, &bus, why, sizeof(why));
	ok(ret == -1 && strstr(why, reason_part) != NULL && memcmp(regs, before, sizeof(regs)) == 0 &&
	   cpsr == cpsr_in && nlog == 0, "%s is refused: %s", text, why);
}

int main(void)
{
	unsigned passed = 0;
	uint32_t regs[16], cpsr = 0x10U;
	char why[160];

	tap_plan((int)(sizeof(forms) / sizeof(forms[0])) + 14);
	for (size_t i = 0; i < sizeof(forms) / sizeof(forms[0]); i++) {
		bool good = check_form(&forms[i]);

		passed += good;
		ok(good, "%s (0x%08x)", forms[i].text, forms[i].insn);
	}

	/* ldr r0, [pc, #8]: the PC reads as the instruction's address + 8 */
	fill_memory();
	start_regs(regs);
	regs[15] = BASE + 0x30U;
	nlog = 0;
	ok(hs_arm_emulate(0xe59f0008U, regs, &cpsr, &bus, why, sizeof(why)) == 0 && nlog == 1 &&
	   log_[0].addr == BASE + 0x40U && regs[15] == BASE + 0x34U,
	   "ldr r0, [pc, #8] reads pc + 8 + 8 and steps the PC");

	/* ldr pc, [r1] with bit 0 set: a branch to Thumb (ARMv5 interworking) */
	fill_memory();
	start_regs(regs);
	mem[0x40] = 0x01;
	mem[0x41] = 0x20;
	mem[0x42] = 0x00;
	mem[0x43] = 0x00;
	cpsr = 0x10U;
	ok(hs_arm_emulate(0xe591f000U, regs, &cpsr, &bus, why, sizeof(why)) == 0 && regs[15] == 0x2000U &&
	   (cpsr & HS_ARM_CPSR_T), "ldr pc, [r1] loading an odd address branches to Thumb state");

	check_refused(0xe0000291U, 0x10U, "mul r0, r1, r2", "not a load/store");
	check_refused(0xee070f9aU, 0x10U, "mcr p15 (a coprocessor transfer)", "not a load/store");
	check_refused(0xe8d10005U, 0x10U, "ldm r1, {r0, r2}^", "S bit");
	check_refused(0xe5910000U, 0x30U, "an access in Thumb state", "Thumb");
	check_refused(0xf5d1f000U, 0x10U, "pld [r1]", "unconditional");
	/* unaligned: as Linux's kernel alignment fixup, byte accesses lowest address first */
	fill_memory();
	start_regs(regs);
	cpsr = 0x10U;
	nlog = 0;
	ok(hs_arm_emulate(0xe5910001U, regs, &cpsr, &bus, why, sizeof(why)) == 0 && nlog == 4 &&
	   log_[0].addr == R1_START + 1U && log_[0].width == 1U && log_[3].addr == R1_START + 4U &&
	   regs[0] == ((uint32_t)mem[0x41] | (uint32_t)mem[0x42] << 8 | (uint32_t)mem[0x43] << 16 |
		       (uint32_t)mem[0x44] << 24),
	   "ldr r0, [r1, #1] (unaligned word): four byte reads, lowest first, as Linux's alignment fixup");
	fill_memory();
	start_regs(regs);
	nlog = 0;
	ok(hs_arm_emulate(0xe1c100b1U, regs, &cpsr, &bus, why, sizeof(why)) == 0 && nlog == 2 &&
	   log_[0].dir == 'w' && log_[0].addr == R1_START + 1U && log_[0].value == 0x44U &&
	   log_[1].addr == R1_START + 2U && log_[1].value == 0x33U,
	   "strh r0, [r1, #1] (unaligned halfword): two byte writes, lowest first");
	check_refused(0xe1c150d0U, 0x10U, "ldrd r5, [r1] (odd first register)", "odd");
	check_refused(0xe101009fU, 0x10U, "swp r0, pc, [r1]", "SWP with the PC");
	check_refused(0xe49f0004U, 0x10U, "ldr r0, [pc], #4 (the PC written back)", "writing back the PC");
	check_refused(0xe8910000U, 0x10U, "ldm r1, {} (no register)", "no register");
	check_refused(0xe7910012U, 0x10U, "a media instruction in the load/store space", "media");
	tap_diag("%u of %zu forms as the ARM926 does them", passed, sizeof(forms) / sizeof(forms[0]));
	return tap_done();
}

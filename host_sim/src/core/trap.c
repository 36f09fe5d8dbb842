/*
 * trap.c — plain pointer accesses to register windows.  Host only.
 *
 * The window space is mapped without access rights, so a volatile load or
 * store through a plain pointer faults.  On x86-64 Linux the SIGSEGV
 * handler decodes the faulting instruction (the mov forms gcc emits for
 * 8/16/32-bit volatile accesses: mov r/m<->r, mov imm->r/m, movzx, movsx,
 * movsxd; the read-modify-write and compare forms -O2 makes of compound
 * statements such as `*p |= m`: add/or/adc/sbb/and/sub/xor/cmp with a
 * register or immediate, test, inc, dec, not, neg, bt/bts/btr/btc; with
 * 0x66, REX, lock and segment prefixes), performs the access through
 * sil_host_read/sil_host_write — exactly the accessor path, hooks, log,
 * cost and interrupt deferral included — writes the destination register
 * (and, for arithmetic, the flags, computed by the same instruction on the
 * host) in the saved context and resumes after the instruction.  A read-
 * modify-write is one read and one write on the bus, as on the ARM (LDR,
 * ORR, STR); compares and bit tests only read.  It also takes the 8-byte
 * movs and the SSE moves gcc makes of adjacent stores through a non-volatile
 * pointer (store merging, SLP vectorization).  An access wider than its
 * register or spanning registers is performed as the per-register accesses
 * an ARM926 issues, lowest address first (hs_space_split; the ARM path too).
 * Faults outside the window space go to the handler installed before ours
 * (ASan's, or the default action).
 *
 * On ARM Linux (the arm926 configuration under qemu-arm, whose `unsigned
 * long` and pointers are the target's 32 bits) the handler performs the
 * faulting A32 load/store with hs_arm_emulate (host_sim/arm_decode.h: LDR/
 * STR/LDRB/STRB, LDRH/STRH/LDRSB/LDRSH/LDRD/STRD, LDM/STM, SWP, every
 * addressing mode and write-back) on the same accessor path, updating the
 * saved registers and the PC.  An instruction neither decoder handles stops
 * the run with a report naming the instruction, its address and the
 * register's physical address — never a bare crash.  Other faults go to the
 * kernel's fatal-signal report (rtos_host_crash_install), installed first.
 */
#define _GNU_SOURCE
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <ucontext.h>
#include <unistd.h>

#include "rtos_host.h"
#include "sil.h"
#include "host_sim/arm_decode.h"
#include "core_parts.h"
#include "space_internal.h"

static struct sigaction previous;
static bool installed;

#if defined(__linux__) && (defined(__x86_64__) || defined(__arm__))
/* Stores width bytes (little-endian) at window address addr as the
 * per-register stores an ARM926 issues for them, lowest address first: gcc
 * merges adjacent register stores at -O2 (an 8-byte store over two 32-bit
 * registers, a 4-byte one over two 16-bit registers, an SSE store over
 * four), which the source wrote, and the ARM performs, one register each. */
static void split_write(uintptr_t addr, unsigned width, const uint8_t *bytes)
{
	struct hs_piece pieces[HS_MAX_SPLIT_WIDTH];
	unsigned n = hs_space_split(addr, width, true, pieces), at = 0;

	for (unsigned i = 0; i < n; i++) {
		uint32_t v = 0;

		for (unsigned k = 0; k < pieces[i].width; k++)
			v |= (uint32_t)bytes[at + k] << (8U * k);
		sil_host_write((volatile void *)pieces[i].addr, pieces[i].width, v);
		at += pieces[i].width;
	}
}

/* Loads width bytes at window address addr as the per-register loads an
 * ARM926 issues, lowest address first (split_write's reads). */
static void split_read(uintptr_t addr, unsigned width, uint8_t *bytes)
{
	struct hs_piece pieces[HS_MAX_SPLIT_WIDTH];
	unsigned n = hs_space_split(addr, width, false, pieces), at = 0;

	for (unsigned i = 0; i < n; i++) {
		uint32_t v = sil_host_read((const volatile void *)pieces[i].addr, pieces[i].width);

		for (unsigned k = 0; k < pieces[i].width; k++)
			bytes[at + k] = (uint8_t)(v >> (8U * k));
		at += pieces[i].width;
	}
}

/* split_write of a value of width 1, 2 or 4 bytes. */
static void split_write32(uintptr_t addr, unsigned width, uint32_t value)
{
	uint8_t b[4] = { (uint8_t)value, (uint8_t)(value >> 8), (uint8_t)(value >> 16), (uint8_t)(value >> 24) };

	split_write(addr, width, b);
}

/* split_read of a value of width 1, 2 or 4 bytes. */
static uint32_t split_read32(uintptr_t addr, unsigned width)
{
	uint8_t b[4] = { 0 };

	split_read(addr, width, b);
	return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}
#endif

#if defined(__x86_64__) && defined(__linux__)
#define HS_TRAP_EMULATES 1

/* gregs index of x86-64 register number 0..15 (rax, rcx, rdx, rbx, rsp, rbp, rsi, rdi, r8..r15). */
static const int greg_of[16] = {
	REG_RAX, REG_RCX, REG_RDX, REG_RBX, REG_RSP, REG_RBP, REG_RSI, REG_RDI,
	REG_R8, REG_R9, REG_R10, REG_R11, REG_R12, REG_R13, REG_R14, REG_R15,
};

/* The arithmetic forms, in the order of the x86 group-1 /digit field. */
enum alu_op {
	ALU_ADD, ALU_OR, ALU_ADC, ALU_SBB, ALU_AND, ALU_SUB, ALU_XOR, ALU_CMP,
	ALU_TEST, ALU_INC, ALU_DEC, ALU_NOT, ALU_NEG, ALU_BT, ALU_BTS, ALU_BTR, ALU_BTC,
	ALU_NONE,
};

/* EFLAGS bits an arithmetic instruction defines: OF SF ZF AF PF CF. */
#define ARITH_FLAGS 0x8D5ULL

/*
 * Runs one instruction on registers with the given arithmetic flags in and
 * out (the red zone below the stack pointer is stepped over: this code may
 * run in a leaf function's red zone's place).
 */
#define ALU_ASM(text, type, cons)							\
	do {										\
		type x_ = (type)a, y_ = (type)b;					\
		__asm__("lea -128(%%rsp), %%rsp\n\tpush %[f]\n\tpopf\n\t" text		\
			"\n\tpushf\n\tpop %[f]\n\tlea 128(%%rsp), %%rsp"		\
			: [x] "+" cons (x_), [f] "+r" (fl) : [y] cons (y_) : "cc");	\
		r = x_;									\
	} while (0)
#define ALU_WIDTHS(text)								\
	do {										\
		if (width == 1U)							\
			ALU_ASM(text, uint8_t, "q");					\
		else if (width == 2U)							\
			ALU_ASM(text, uint16_t, "r");					\
		else									\
			ALU_ASM(text, uint32_t, "r");					\
	} while (0)
#define ALU_WIDTHS_16_32(text)								\
	do {										\
		if (width == 2U)							\
			ALU_ASM(text, uint16_t, "r");					\
		else									\
			ALU_ASM(text, uint32_t, "r");					\
	} while (0)

/* a op b at width bytes, as the CPU computes it; *flags: EFLAGS in and out. */
static uint32_t alu(enum alu_op op, unsigned width, uint32_t a, uint32_t b, uint64_t *flags)
{
	uint64_t fl = (*flags & ARITH_FLAGS) | 0x202U;
	uint32_t r = a;

	switch (op) {
	case ALU_ADD:  ALU_WIDTHS("add %[y], %[x]"); break;
	case ALU_OR:   ALU_WIDTHS("or %[y], %[x]"); break;
	case ALU_ADC:  ALU_WIDTHS("adc %[y], %[x]"); break;
	case ALU_SBB:  ALU_WIDTHS("sbb %[y], %[x]"); break;
	case ALU_AND:  ALU_WIDTHS("and %[y], %[x]"); break;
	case ALU_SUB:  ALU_WIDTHS("sub %[y], %[x]"); break;
	case ALU_XOR:  ALU_WIDTHS("xor %[y], %[x]"); break;
	case ALU_CMP:  ALU_WIDTHS("cmp %[y], %[x]"); break;
	case ALU_TEST: ALU_WIDTHS("test %[y], %[x]"); break;
	case ALU_INC:  ALU_WIDTHS("inc %[x]"); break;
	case ALU_DEC:  ALU_WIDTHS("dec %[x]"); break;
	case ALU_NOT:  ALU_WIDTHS("not %[x]"); break;
	case ALU_NEG:  ALU_WIDTHS("neg %[x]"); break;
	case ALU_BT:   ALU_WIDTHS_16_32("bt %[y], %[x]"); break;
	case ALU_BTS:  ALU_WIDTHS_16_32("bts %[y], %[x]"); break;
	case ALU_BTR:  ALU_WIDTHS_16_32("btr %[y], %[x]"); break;
	case ALU_BTC:  ALU_WIDTHS_16_32("btc %[y], %[x]"); break;
	case ALU_NONE: break;
	}
	*flags = (*flags & ~ARITH_FLAGS) | (fl & ARITH_FLAGS);
	return r;
}

/* True if the form only reads its memory operand (no write back). */
static bool alu_reads_only(enum alu_op op)
{
	return op == ALU_CMP || op == ALU_TEST || op == ALU_BT;
}

struct insn {
	unsigned len;          /* bytes */
	unsigned width;        /* memory access width */
	bool store;
	bool has_imm;
	uint32_t imm;
	unsigned reg;          /* register operand number (0..15) */
	bool rex;              /* any REX prefix: byte registers 4..7 are spl..dil */
	unsigned dst_width;    /* load: destination register width (1, 2, 4, 8) */
	bool sign;             /* load: sign-extend */
	enum alu_op alu;       /* ALU_NONE: a mov form */
	bool reg_dst;          /* ALU form whose destination is the register (op r, r/m) */
	bool xmm;              /* SSE move: reg is an xmm register */
	unsigned xmm_at;       /* SSE move: byte of the xmm register the access starts at (movhps: 8) */
	bool xmm_zero;         /* SSE load: the register's other bytes become 0 (movd, movq, movss, movsd) */
};

/* Length of the ModRM/SIB/displacement part starting at p. */
static unsigned modrm_len(const uint8_t *p)
{
	unsigned mod = p[0] >> 6, rm = p[0] & 7U, len = 1;

	if (mod != 3U && rm == 4U) {
		len++;                              /* SIB */
		if (mod == 0U && (p[1] & 7U) == 5U)
			len += 4;                   /* disp32, no base */
	}
	if ((mod == 0U && rm == 5U) || mod == 2U)
		len += 4;                           /* RIP-relative disp32, or base + disp32 */
	else if (mod == 1U)
		len += 1;
	return len;
}

/* Decodes the access instruction at p; false if it is not a supported form. */
static bool decode(const uint8_t *p, struct insn *in)
{
	const uint8_t *start = p;
	bool opsize = false, rex_w = false, rex_r = false;
	unsigned op, mlen, rep = 0;

	memset(in, 0, sizeof(*in));
	in->alu = ALU_NONE;
	for (;; p++) {
		if (*p == 0x66U)
			opsize = true;
		else if (*p == 0xF3U || *p == 0xF2U)
			rep = *p;                   /* an SSE move's mandatory prefix */
		else if (*p == 0xF0U || *p == 0x2EU || *p == 0x3EU || *p == 0x26U || *p == 0x36U || *p == 0x64U || *p == 0x65U)
			continue;
		else
			break;
	}
	if ((*p & 0xF0U) == 0x40U) {
		in->rex = true;
		rex_w = (*p & 8U) != 0;
		rex_r = (*p & 4U) != 0;
		p++;
	}
	op = *p++;
	if (op == 0x0FU)
		op = 0x0F00U | *p++;
	if ((p[0] >> 6) == 3U)
		return false;                       /* register operand: not a memory access */
	in->reg = ((p[0] >> 3) & 7U) | (rex_r ? 8U : 0U);
	mlen = modrm_len(p);
	in->dst_width = rex_w ? 8U : opsize ? 2U : 4U;
	switch (op) {
	case 0x88:  in->store = true; in->width = 1; break;
	case 0x89:  in->store = true; in->width = in->dst_width; break;
	case 0x8A:  in->width = 1; in->dst_width = 1; break;
	case 0x8B:  in->width = in->dst_width; break;
	case 0xC6:
		if (in->reg & 7U)
			return false;
		in->store = true; in->width = 1; in->has_imm = true;
		in->imm = p[mlen];
		mlen += 1;
		break;
	case 0xC7:
		if (in->reg & 7U)
			return false;
		in->store = true; in->has_imm = true;
		if (opsize) {
			in->width = 2;
			in->imm = (uint32_t)p[mlen] | (uint32_t)p[mlen + 1] << 8;
			mlen += 2;
		} else {
			in->width = rex_w ? 8U : 4U;
			memcpy(&in->imm, p + mlen, 4);
			mlen += 4;
		}
		break;
	case 0x0FB6: in->width = 1; break;
	case 0x0FB7: in->width = 2; break;
	case 0x0FBE: in->width = 1; in->sign = true; break;
	case 0x0FBF: in->width = 2; in->sign = true; break;
	case 0x63:   in->width = 4; in->sign = rex_w; break;
	case 0x80: case 0x81: case 0x83:            /* group 1: op r/m, imm */
		in->alu = (enum alu_op)(in->reg & 7U);
		in->width = op == 0x80U ? 1U : in->dst_width;
		in->has_imm = true;
		if (op == 0x81U && in->width == 2U) {
			in->imm = (uint32_t)p[mlen] | (uint32_t)p[mlen + 1] << 8;
			mlen += 2;
		} else if (op == 0x81U) {
			memcpy(&in->imm, p + mlen, 4);
			mlen += 4;
		} else {
			in->imm = op == 0x83U ? (uint32_t)(int32_t)(int8_t)p[mlen] : p[mlen];
			mlen += 1;
		}
		break;
	case 0x84: case 0x85:                       /* test r/m, r */
		in->alu = ALU_TEST;
		in->width = op == 0x84U ? 1U : in->dst_width;
		break;
	case 0xF6: case 0xF7:                       /* group 3: test imm, not, neg */
		in->width = op == 0xF6U ? 1U : in->dst_width;
		switch (in->reg & 7U) {
		case 0:
			in->alu = ALU_TEST;
			in->has_imm = true;
			if (in->width == 1U) {
				in->imm = p[mlen];
				mlen += 1;
			} else if (in->width == 2U) {
				in->imm = (uint32_t)p[mlen] | (uint32_t)p[mlen + 1] << 8;
				mlen += 2;
			} else {
				memcpy(&in->imm, p + mlen, 4);
				mlen += 4;
			}
			break;
		case 2: in->alu = ALU_NOT; break;
		case 3: in->alu = ALU_NEG; break;
		default: return false;               /* mul, div: not register accesses a driver makes */
		}
		break;
	case 0xFE: case 0xFF:                       /* group 4/5: inc, dec */
		if ((in->reg & 7U) > 1U)
			return false;
		in->alu = (in->reg & 7U) ? ALU_DEC : ALU_INC;
		in->width = op == 0xFEU ? 1U : in->dst_width;
		break;
	case 0x0FA3: in->alu = ALU_BT;  in->width = in->dst_width; break;
	case 0x0FAB: in->alu = ALU_BTS; in->width = in->dst_width; break;
	case 0x0FB3: in->alu = ALU_BTR; in->width = in->dst_width; break;
	case 0x0FBB: in->alu = ALU_BTC; in->width = in->dst_width; break;
	case 0x0FBA:                                /* group 8: bt/bts/btr/btc r/m, imm8 */
		if ((in->reg & 7U) < 4U)
			return false;
		in->alu = (enum alu_op)(ALU_BT + ((in->reg & 7U) - 4U));
		in->width = in->dst_width;
		in->has_imm = true;
		in->imm = p[mlen];
		mlen += 1;
		break;
	case 0x0F10: case 0x0F11:                   /* movups/movupd, movss (F3), movsd (F2) */
		in->xmm = true;
		in->store = op == 0x0F11U;
		in->width = rep == 0xF3U ? 4U : rep == 0xF2U ? 8U : 16U;
		in->xmm_zero = rep != 0;
		break;
	case 0x0F28: case 0x0F29:                   /* movaps/movapd */
	case 0x0F6F: case 0x0F7F:                   /* movdqa (66), movdqu (F3) */
		if ((op == 0x0F6FU || op == 0x0F7FU) && !opsize && rep != 0xF3U)
			return false;               /* MMX */
		in->xmm = true;
		in->store = op == 0x0F29U || op == 0x0F7FU;
		in->width = 16;
		break;
	case 0x0F12: case 0x0F13: case 0x0F16: case 0x0F17:   /* movlps/movlpd, movhps/movhpd */
		if (rep)
			return false;               /* movsldup, movshdup: not moves of memory */
		in->xmm = true;
		in->store = op & 1U;
		in->width = 8;
		in->xmm_at = op >= 0x0F16U ? 8U : 0U;
		break;
	case 0x0F6E: case 0x0F7E:                   /* movd/movq r/m <-> xmm (66); movq xmm <- m64 (F3 0F 7E) */
		if (op == 0x0F7EU && rep == 0xF3U) {
			in->xmm = true; in->width = 8; in->xmm_zero = true;
			break;
		}
		if (!opsize)
			return false;               /* MMX */
		in->xmm = true;
		in->store = op == 0x0F7EU;
		in->width = rex_w ? 8U : 4U;
		in->xmm_zero = true;
		break;
	case 0x0FD6:                                /* movq m64 <- xmm (66) */
		if (!opsize)
			return false;
		in->xmm = true; in->store = true; in->width = 8;
		break;
	default:
		if (op < 0x40U && (op & 7U) < 4U) {  /* add/or/adc/sbb/and/sub/xor/cmp r/m<->r */
			in->alu = (enum alu_op)(op >> 3);
			in->width = (op & 1U) ? in->dst_width : 1U;
			in->reg_dst = (op & 2U) != 0;
			if (in->width == 1U)
				in->dst_width = 1U;
			break;
		}
		return false;
	}
	in->len = (unsigned)(p - start) + mlen;
	if (in->xmm)
		return true;
	if (rep && op < 0x0F00U)
		return false;                       /* a string instruction's prefix */
	if (in->alu != ALU_NONE)
		return in->width == 1U || in->width == 2U || in->width == 4U;
	return in->width == 1U || in->width == 2U || in->width == 4U || in->width == 8U;
}

/* Value of a register operand of width bytes (byte registers 4..7 without REX are ah..bh). */
static uint64_t reg_get(const mcontext_t *mc, const struct insn *in, unsigned width)
{
	if (width == 1U && !in->rex && in->reg >= 4U && in->reg < 8U)
		return (uint64_t)(mc->gregs[greg_of[in->reg - 4U]] >> 8) & 0xFFU;
	return (uint64_t)mc->gregs[greg_of[in->reg]];
}

/* Stores a loaded value into the destination register as the instruction would. */
static void reg_put(mcontext_t *mc, const struct insn *in, uint64_t v)
{
	uint64_t x;

	if (in->sign)
		x = in->width == 1U ? (uint64_t)(int64_t)(int8_t)v :
		    in->width == 2U ? (uint64_t)(int64_t)(int16_t)v : (uint64_t)(int64_t)(int32_t)(uint32_t)v;
	else
		x = v;
	switch (in->dst_width) {
	case 1:
		if (!in->rex && in->reg >= 4U && in->reg < 8U) {
			greg_t *r = &mc->gregs[greg_of[in->reg - 4U]];

			*r = (greg_t)(((uint64_t)*r & ~0xFF00ULL) | ((x & 0xFFU) << 8));
		} else {
			greg_t *r = &mc->gregs[greg_of[in->reg]];

			*r = (greg_t)(((uint64_t)*r & ~0xFFULL) | (x & 0xFFU));
		}
		break;
	case 2: {
		greg_t *r = &mc->gregs[greg_of[in->reg]];

		*r = (greg_t)(((uint64_t)*r & ~0xFFFFULL) | (x & 0xFFFFU));
		break;
	}
	case 4:
		mc->gregs[greg_of[in->reg]] = (greg_t)(x & 0xFFFFFFFFULL);   /* 32-bit writes zero-extend */
		break;
	default:
		mc->gregs[greg_of[in->reg]] = (greg_t)x;
		break;
	}
}

/* An arithmetic form: one bus read, the operation, one bus write unless it only reads. */
static void emulate_alu(mcontext_t *mc, const struct insn *in, uintptr_t addr)
{
	uint64_t flags = (uint64_t)mc->gregs[REG_EFL];
	uint32_t mem = split_read32(addr, in->width);
	uint32_t other = in->has_imm ? in->imm : (uint32_t)reg_get(mc, in, in->width);
	uint32_t r;

	if (in->reg_dst) {
		r = alu(in->alu, in->width, other, mem, &flags);
		if (!alu_reads_only(in->alu))
			reg_put(mc, in, r);
	} else {
		r = alu(in->alu, in->width, mem, other, &flags);
		if (!alu_reads_only(in->alu))
			split_write32(addr, in->width, r);
	}
	mc->gregs[REG_EFL] = (greg_t)flags;
}

/* A mov form's store: the source register's (or immediate's) bytes, per register. */
static void emulate_store(const mcontext_t *mc, const struct insn *in, uintptr_t addr)
{
	uint8_t b[HS_MAX_SPLIT_WIDTH];

	if (in->xmm) {
		memcpy(b, (const uint8_t *)mc->fpregs->_xmm[in->reg].element + in->xmm_at, in->width);
	} else {
		uint64_t v = in->has_imm ? (uint64_t)(int64_t)(int32_t)in->imm : reg_get(mc, in, in->width);

		for (unsigned k = 0; k < in->width; k++)
			b[k] = (uint8_t)(v >> (8U * k));
	}
	split_write(addr, in->width, b);
}

/* A mov form's load: the bytes, per register, into the destination as the instruction puts them. */
static void emulate_load(mcontext_t *mc, const struct insn *in, uintptr_t addr)
{
	uint8_t b[HS_MAX_SPLIT_WIDTH];
	uint64_t v = 0;

	split_read(addr, in->width, b);
	if (in->xmm) {
		uint8_t *x = (uint8_t *)mc->fpregs->_xmm[in->reg].element;

		if (in->xmm_zero)
			memset(x, 0, 16);
		memcpy(x + in->xmm_at, b, in->width);
		return;
	}
	for (unsigned k = 0; k < in->width; k++)
		v |= (uint64_t)b[k] << (8U * k);
	reg_put(mc, in, v);
}
#elif defined(__arm__) && defined(__linux__)
#define HS_TRAP_EMULATES 1

static uint32_t bus_read(void *ctx, uint32_t addr, unsigned width)
{
	(void)ctx;
	return split_read32(addr, width);
}

static void bus_write(void *ctx, uint32_t addr, unsigned width, uint32_t value)
{
	(void)ctx;
	split_write32(addr, width, value);
}

/* Performs the faulting ARM instruction on the saved context; false (why set) if it is not a load/store form. */
static bool emulate_arm(mcontext_t *mc, char *why, size_t whylen)
{
	static const struct hs_arm_bus bus = { .read = bus_read, .write = bus_write };
	unsigned long *saved = &mc->arm_r0;          /* r0..r10, fp, ip, sp, lr, pc: consecutive */
	uint32_t regs[16], cpsr = (uint32_t)mc->arm_cpsr, insn;

	for (unsigned r = 0; r < 16U; r++)
		regs[r] = (uint32_t)saved[r];
	/* ARM state: the word at the PC; Thumb (ARMv5: 16-bit instructions, at any halfword): its halfword. */
	if (cpsr & HS_ARM_CPSR_T)
		insn = *(const uint16_t *)(uintptr_t)regs[HS_ARM_PC];
	else
		insn = *(const uint32_t *)(uintptr_t)regs[HS_ARM_PC];
	if (hs_arm_emulate(insn, regs, &cpsr, &bus, why, whylen) != 0)
		return false;
	for (unsigned r = 0; r < 16U; r++)
		saved[r] = regs[r];
	mc->arm_cpsr = cpsr;
	return true;
}
#else
#define HS_TRAP_EMULATES 0
#endif

/* Hands a fault that is not ours to the handler that was there before. */
static void chain(int sig, siginfo_t *si, void *uctx)
{
	if (previous.sa_flags & SA_SIGINFO) {
		if (previous.sa_sigaction) {
			previous.sa_sigaction(sig, si, uctx);
			return;
		}
	} else if (previous.sa_handler != SIG_DFL && previous.sa_handler != SIG_IGN) {
		previous.sa_handler(sig);
		return;
	}
	/* Default action: restore it; the faulting instruction runs again and dies properly. */
	signal(sig, SIG_DFL);
}

static void trap_handler(int sig, siginfo_t *si, void *uctx)
{
	uintptr_t addr = (uintptr_t)si->si_addr;

	if (!hs_space_claims(addr)) {
		chain(sig, si, uctx);
		return;
	}
#if HS_TRAP_EMULATES && defined(__x86_64__)
	{
		ucontext_t *uc = uctx;
		mcontext_t *mc = &uc->uc_mcontext;
		const uint8_t *ip = (const uint8_t *)mc->gregs[REG_RIP];
		struct insn in;

		if (!decode(ip, &in)) {
			rtos_host_bug("host_sim", "plain pointer access to register window address %p (physical 0x%08lx): "
				      "instruction %02x %02x %02x %02x %02x %02x at %p is not an emulated access form "
				      "(mov, movzx/movsx, SSE moves, add/or/adc/sbb/and/sub/xor/cmp/test, inc/dec/not/neg, bt*)",
				      (void *)addr, (unsigned long)hs_space_to_phys(addr), ip[0], ip[1], ip[2], ip[3],
				      ip[4], ip[5], (const void *)ip);
			abort();
		}
		if (in.alu != ALU_NONE)
			emulate_alu(mc, &in, addr);
		else if (in.store)
			emulate_store(mc, &in, addr);
		else
			emulate_load(mc, &in, addr);
		mc->gregs[REG_RIP] += (greg_t)in.len;
	}
#elif HS_TRAP_EMULATES
	{
		ucontext_t *uc = uctx;
		char why[160];

		if (!emulate_arm(&uc->uc_mcontext, why, sizeof(why))) {
			rtos_host_bug("host_sim", "plain pointer access to register window address %p (physical 0x%08lx): "
				      "the instruction at %p is %s", (void *)addr, (unsigned long)hs_space_to_phys(addr),
				      (const void *)uc->uc_mcontext.arm_pc, why);
			abort();
		}
	}
#else
	(void)uctx;
	rtos_host_bug("host_sim", "plain pointer access to register window address %p (physical 0x%08lx): "
		      "%s; use the accessors (readl/writel, ioread*/iowrite*, sil_*_mem)",
		      (void *)addr, (unsigned long)hs_space_to_phys(addr), hs_trap_reason());
	abort();
#endif
	(void)sig;
}

bool hs_trap_install(void)
{
	struct sigaction sa;

	if (installed)
		return HS_TRAP_EMULATES;
	/* the kernel's fatal-signal report first: faults that are not ours go to it */
	rtos_host_crash_install();
	memset(&sa, 0, sizeof(sa));
	sa.sa_sigaction = trap_handler;
	/* SA_NODEFER: an access emulated here may run interrupt handlers or
	 * switch tasks (per-access CPU time), which may trap again.  SA_ONSTACK
	 * only where the alternate stack disarms itself while in use (so such a
	 * switch is safe there): then a fault at a task stack's end, which has no
	 * room for a handler, still reaches the kernel's report through chain. */
	sa.sa_flags = SA_SIGINFO | SA_NODEFER | (rtos_host_signal_stack_disarms() ? SA_ONSTACK : 0);
	sigemptyset(&sa.sa_mask);
	if (sigaction(SIGSEGV, &sa, &previous) != 0)
		return false;
	installed = true;
	return HS_TRAP_EMULATES;
}

void hs_trap_remove(void)
{
	if (!installed)
		return;
	sigaction(SIGSEGV, &previous, NULL);
	installed = false;
}

const char *hs_trap_reason(void)
{
#if HS_TRAP_EMULATES
	return "";
#else
	return "trapping plain pointer accesses needs x86-64 or ARM Linux";
#endif
}

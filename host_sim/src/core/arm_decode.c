/*
 * arm_decode.c — performs one A32 (ARMv5TE) load/store on a bus
 * (host_sim/arm_decode.h).  Encodings: ARM Architecture Reference Manual,
 * ARMv5 edition, A5.2 (addressing mode 2: word and unsigned byte), A5.3
 * (mode 3: halfword, signed byte, doubleword), A5.4 (mode 4: load/store
 * multiple), A4.1.108 (SWP).  The condition field is not looked at: an
 * instruction that faulted on its access passed its condition.
 */
#include <stdio.h>

#include "host_sim/arm_decode.h"

/* A register as an operand: the PC reads as the instruction's address + 8. */
static uint32_t operand(const uint32_t regs[16], unsigned r)
{
	return r == HS_ARM_PC ? regs[HS_ARM_PC] + 8U : regs[r];
}

/* A register stored to memory: the ARM926EJ-S stores the PC as the
 * instruction's address + 12 (ARMv5 leaves +8 or +12 to the implementation). */
static uint32_t stored(const uint32_t regs[16], unsigned r)
{
	return r == HS_ARM_PC ? regs[HS_ARM_PC] + 12U : regs[r];
}

/* Addressing mode 2's scaled register offset: Rm shifted by an immediate. */
static uint32_t scaled_offset(uint32_t insn, const uint32_t regs[16], uint32_t cpsr)
{
	uint32_t v = operand(regs, insn & 0xFU);
	unsigned amount = (insn >> 7) & 0x1FU;

	switch ((insn >> 5) & 3U) {
	case 0:         /* LSL */
		return v << amount;
	case 1:         /* LSR; #0 encodes #32 */
		return amount != 0U ? v >> amount : 0U;
	case 2:         /* ASR; #0 encodes #32 */
		if (amount == 0U)
			return (v & 0x80000000U) ? 0xFFFFFFFFU : 0U;
		return (v >> amount) | ((v & 0x80000000U) ? ~(0xFFFFFFFFU >> amount) : 0U);
	default:        /* ROR; #0 encodes RRX (the carry flag, CPSR bit 29, shifted in) */
		if (amount == 0U)
			return (((cpsr >> 29) & 1U) << 31) | (v >> 1);
		return (v >> amount) | (v << (32U - amount));
	}
}

/* Writes a loaded value to register r; into the PC it is a branch (bit 0 = Thumb). */
static void load_register(uint32_t regs[16], uint32_t *cpsr, unsigned r, uint32_t value, bool *pc_loaded)
{
	if (r != HS_ARM_PC) {
		regs[r] = value;
		return;
	}
	if (value & 1U)
		*cpsr |= HS_ARM_CPSR_T;
	regs[HS_ARM_PC] = value & ~1U;
	*pc_loaded = true;
}

/* Why the instruction is not emulated; -1. */
static int refuse(char *why, size_t whylen, const char *what, uint32_t insn)
{
	if (why != NULL && whylen > 0U)
		snprintf(why, whylen, "%s (instruction word 0x%08lx)", what, (unsigned long)insn);
	return -1;
}

/* The effective address and the written-back base of an indexed form. */
struct indexing {
	uint32_t addr;
	uint32_t wb_value;
	bool write_back;
};

static struct indexing indexed(uint32_t insn, uint32_t base, uint32_t offset)
{
	bool pre = (insn >> 24) & 1U, up = (insn >> 23) & 1U, w = (insn >> 21) & 1U;
	uint32_t offset_addr = up ? base + offset : base - offset;

	return (struct indexing){ .addr = pre ? offset_addr : base, .wb_value = offset_addr,
				  .write_back = !pre || w };
}

/*
 * A width-byte load at addr.  Unaligned, it is what Linux's ARM kernel does
 * for a kernel-mode access that faulted on alignment (arch/arm/mm/alignment.c,
 * do_alignment: the access redone as byte accesses, lowest address first,
 * little-endian), the environment the drivers run here were written for.
 */
static uint32_t bus_load(const struct hs_arm_bus *bus, uint32_t addr, unsigned width)
{
	uint32_t v = 0;

	if (!(addr & (width - 1U)))
		return bus->read(bus->ctx, addr, width);
	for (unsigned i = 0; i < width; i++)
		v |= (bus->read(bus->ctx, addr + i, 1U) & 0xFFU) << (8U * i);
	return v;
}

/* A width-byte store at addr; unaligned, as Linux's alignment fixup (bus_load). */
static void bus_store(const struct hs_arm_bus *bus, uint32_t addr, unsigned width, uint32_t v)
{
	if (!(addr & (width - 1U))) {
		bus->write(bus->ctx, addr, width, v);
		return;
	}
	for (unsigned i = 0; i < width; i++)
		bus->write(bus->ctx, addr + i, 1U, (v >> (8U * i)) & 0xFFU);
}

/* Addressing mode 2: LDR, STR, LDRB, STRB (and their T forms). */
static int single(uint32_t insn, uint32_t regs[16], uint32_t *cpsr, const struct hs_arm_bus *bus,
		  bool *pc_loaded, char *why, size_t whylen)
{
	unsigned rn = (insn >> 16) & 0xFU, rd = (insn >> 12) & 0xFU;
	bool reg_offset = (insn >> 25) & 1U, byte = (insn >> 22) & 1U, load = (insn >> 20) & 1U;
	unsigned width = byte ? 1U : 4U;
	struct indexing ix;

	if (reg_offset && (insn & 0x10U))
		return refuse(why, whylen, "a media or undefined instruction, not a load/store", insn);
	ix = indexed(insn, operand(regs, rn),
		     reg_offset ? scaled_offset(insn, regs, *cpsr) : (insn & 0xFFFU));
	if (ix.write_back && rn == HS_ARM_PC)
		return refuse(why, whylen, "a load/store writing back the PC as its base", insn);
	if (load) {
		uint32_t v = bus_load(bus, ix.addr, width);

		if (ix.write_back)
			regs[rn] = ix.wb_value;
		load_register(regs, cpsr, rd, v, pc_loaded);
	} else {
		uint32_t v = stored(regs, rd);

		bus_store(bus, ix.addr, width, byte ? (v & 0xFFU) : v);
		if (ix.write_back)
			regs[rn] = ix.wb_value;
	}
	return 0;
}

/* Addressing mode 3: LDRH, STRH, LDRSB, LDRSH, LDRD, STRD. */
static int extra(uint32_t insn, uint32_t regs[16], uint32_t *cpsr, const struct hs_arm_bus *bus,
		 bool *pc_loaded, char *why, size_t whylen)
{
	unsigned rn = (insn >> 16) & 0xFU, rd = (insn >> 12) & 0xFU, sh = (insn >> 5) & 3U;
	bool imm = (insn >> 22) & 1U, load = (insn >> 20) & 1U;
	uint32_t offset = imm ? (((insn >> 4) & 0xF0U) | (insn & 0xFU)) : operand(regs, insn & 0xFU);
	struct indexing ix = indexed(insn, operand(regs, rn), offset);
	bool dual = !load && sh != 1U;      /* LDRD (sh 2) / STRD (sh 3): L is 0 for both */
	unsigned width = dual ? 4U : (sh == 2U ? 1U : 2U);

	if (ix.write_back && rn == HS_ARM_PC)
		return refuse(why, whylen, "a load/store writing back the PC as its base", insn);
	if (dual && ((rd & 1U) || rd == 14U))
		return refuse(why, whylen, "LDRD/STRD with an odd or R14 first register", insn);
	if (dual && sh == 2U) {                 /* LDRD */
		uint32_t lo = bus_load(bus, ix.addr, 4U);
		uint32_t hi = bus_load(bus, ix.addr + 4U, 4U);

		if (ix.write_back)
			regs[rn] = ix.wb_value;
		regs[rd] = lo;
		regs[rd + 1U] = hi;
	} else if (dual) {                      /* STRD */
		bus_store(bus, ix.addr, 4U, stored(regs, rd));
		bus_store(bus, ix.addr + 4U, 4U, stored(regs, rd + 1U));
		if (ix.write_back)
			regs[rn] = ix.wb_value;
	} else if (load) {                      /* LDRH, LDRSB, LDRSH */
		uint32_t v = bus_load(bus, ix.addr, width);

		if (sh == 2U)
			v = (uint32_t)(int32_t)(int8_t)(uint8_t)v;
		else if (sh == 3U)
			v = (uint32_t)(int32_t)(int16_t)(uint16_t)v;
		if (ix.write_back)
			regs[rn] = ix.wb_value;
		load_register(regs, cpsr, rd, v, pc_loaded);
	} else {                                /* STRH */
		bus_store(bus, ix.addr, 2U, stored(regs, rd) & 0xFFFFU);
		if (ix.write_back)
			regs[rn] = ix.wb_value;
	}
	return 0;
}

/* Addressing mode 4: LDM, STM (IA, IB, DA, DB). */
static int multiple(uint32_t insn, uint32_t regs[16], uint32_t *cpsr, const struct hs_arm_bus *bus,
		    bool *pc_loaded, char *why, size_t whylen)
{
	unsigned rn = (insn >> 16) & 0xFU, list = insn & 0xFFFFU, n = 0;
	bool pre = (insn >> 24) & 1U, up = (insn >> 23) & 1U, w = (insn >> 21) & 1U, load = (insn >> 20) & 1U;
	uint32_t base, addr, loaded[16];

	if ((insn >> 22) & 1U)
		return refuse(why, whylen, "LDM/STM with the S bit (user registers or SPSR)", insn);
	if (rn == HS_ARM_PC || list == 0U)
		return refuse(why, whylen, "LDM/STM with the PC as base or no register", insn);
	for (unsigned r = 0; r < 16U; r++)
		n += (list >> r) & 1U;
	base = regs[rn];
	if (base & 3U)
		return refuse(why, whylen, "an unaligned LDM/STM", insn);
	addr = up ? (pre ? base + 4U : base) : (pre ? base - 4U * n : base - 4U * n + 4U);
	for (unsigned r = 0; r < 16U; r++) {
		if (!((list >> r) & 1U))
			continue;
		if (load)
			loaded[r] = bus->read(bus->ctx, addr, 4U);
		else
			bus->write(bus->ctx, addr, 4U, stored(regs, r));
		addr += 4U;
	}
	if (w && !(load && ((list >> rn) & 1U)))   /* a loaded base keeps the loaded value */
		regs[rn] = up ? base + 4U * n : base - 4U * n;
	if (load)
		for (unsigned r = 0; r < 16U; r++)
			if ((list >> r) & 1U)
				load_register(regs, cpsr, r, loaded[r], pc_loaded);
	return 0;
}

/* SWP / SWPB: Rd = [Rn]; [Rn] = Rm, one read and one write. */
static int swap(uint32_t insn, uint32_t regs[16], const struct hs_arm_bus *bus, char *why, size_t whylen)
{
	unsigned rn = (insn >> 16) & 0xFU, rd = (insn >> 12) & 0xFU, rm = insn & 0xFU;
	unsigned width = ((insn >> 22) & 1U) ? 1U : 4U;
	uint32_t addr = regs[rn], old, v;

	if (rn == HS_ARM_PC || rd == HS_ARM_PC || rm == HS_ARM_PC)
		return refuse(why, whylen, "SWP with the PC", insn);
	if (addr & (width - 1U))
		return refuse(why, whylen, "an unaligned SWP", insn);
	v = width == 1U ? (regs[rm] & 0xFFU) : regs[rm];
	old = bus->read(bus->ctx, addr, width);
	bus->write(bus->ctx, addr, width, v);
	regs[rd] = old;
	return 0;
}

int hs_arm_emulate(uint32_t insn, uint32_t regs[16], uint32_t *cpsr, const struct hs_arm_bus *bus,
		   char *why, size_t whylen)
{
	uint32_t saved[16], saved_cpsr = *cpsr;
	bool pc_loaded = false;
	int ret;

	if (*cpsr & HS_ARM_CPSR_T)
		return refuse(why, whylen, "a Thumb instruction (only ARM state is emulated)", insn);
	if ((insn >> 28) == 0xFU)
		return refuse(why, whylen, "an unconditional-space instruction (PLD, BLX, ...)", insn);
	for (unsigned r = 0; r < 16U; r++)
		saved[r] = regs[r];
	if (((insn >> 26) & 3U) == 1U)
		ret = single(insn, regs, cpsr, bus, &pc_loaded, why, whylen);
	else if (((insn >> 25) & 7U) == 4U)
		ret = multiple(insn, regs, cpsr, bus, &pc_loaded, why, whylen);
	else if ((insn & 0x0FB00FF0U) == 0x01000090U)
		ret = swap(insn, regs, bus, why, whylen);
	else if (((insn >> 25) & 7U) == 0U && (insn & 0x90U) == 0x90U && ((insn >> 5) & 3U) != 0U)
		ret = extra(insn, regs, cpsr, bus, &pc_loaded, why, whylen);
	else
		ret = refuse(why, whylen, "not a load/store (LDR/STR/LDRH/STRH/LDRSB/LDRSH/LDRD/STRD/LDM/STM/SWP)",
			     insn);
	if (ret != 0) {
		for (unsigned r = 0; r < 16U; r++)
			regs[r] = saved[r];
		*cpsr = saved_cpsr;
		return ret;
	}
	if (!pc_loaded)
		regs[HS_ARM_PC] = saved[HS_ARM_PC] + 4U;
	return 0;
}

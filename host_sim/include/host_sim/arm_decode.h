/*
 * host_sim/arm_decode.h — the ARM (A32, ARMv5TE) load/store instructions a
 * driver's plain-pointer register access compiles to, performed on a bus.
 *
 * In the arm926 configuration (qemu-arm) a load or store through a pointer
 * into a register window faults; the trap (src/core/trap.c) hands the
 * faulting instruction, the saved registers and host_sim's register access
 * path to hs_arm_emulate, which does what the ARM926EJ-S would: the accesses
 * at their widths (the byte lanes of 8- and 16-bit ones are the bus's
 * business), the loaded registers, the base write-back, the PC.  Pure: it
 * knows nothing of host_sim, so it is tested with a plain memory bus on any
 * host.
 *
 * Forms (ARM Architecture Reference Manual, ARMv5, A3.11-A3.13, A5.2-A5.5):
 * LDR/STR/LDRB/STRB/LDRT/STRT/LDRBT/STRBT with an immediate or a (shifted)
 * register offset, pre- or post-indexed, with write-back, up or down;
 * LDRH/STRH/LDRSB/LDRSH/LDRD/STRD, immediate or register offset, the same
 * indexing; LDM/STM in the four modes (IA, IB, DA, DB) with write-back, PC
 * in the list; SWP/SWPB.  A load into the PC branches (bit 0 selects Thumb,
 * as ARMv5's LDR and LDM do).  Anything else — a Thumb instruction, LDM/STM
 * with the S bit (user registers / SPSR), coprocessor transfers — is not
 * emulated: the call says which and returns -1.
 */
#ifndef HOST_SIM_ARM_DECODE_H
#define HOST_SIM_ARM_DECODE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* The bus the accesses go to: widths 1, 2 and 4 bytes, addr aligned to width. */
struct hs_arm_bus {
	uint32_t (*read)(void *ctx, uint32_t addr, unsigned width);
	void (*write)(void *ctx, uint32_t addr, unsigned width, uint32_t value);
	void *ctx;
};

#define HS_ARM_PC	15
#define HS_ARM_CPSR_T	0x20U   /* CPSR bit 5: Thumb state */

/*
 * Performs insn, the instruction at regs[15], on bus: regs[0..15] and *cpsr
 * are the CPU's registers before it and are updated as it leaves them (the PC
 * advanced by 4, or loaded).  Returns 0; or -1, with why (of whylen bytes)
 * naming the form, if insn is not an emulated load/store (nothing changed).
 */
int hs_arm_emulate(uint32_t insn, uint32_t regs[16], uint32_t *cpsr, const struct hs_arm_bus *bus,
		   char *why, size_t whylen);

#endif /* HOST_SIM_ARM_DECODE_H */

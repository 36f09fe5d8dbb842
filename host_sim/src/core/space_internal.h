/*
 * space_internal.h — the register space's window and dispatch, shared by the
 * core's board, trap and trace code (not part of the public API).
 */
#ifndef HOST_SIM_SPACE_INTERNAL_H
#define HOST_SIM_SPACE_INTERNAL_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

/* Reserves the CPU-visible window space; returns 0 or -1. */
int hs_space_init(uint32_t access_ns);
/* Frees every region and the window space. */
void hs_space_fini(void);

/* true if addr lies in the window space (a trapped access belongs to us). */
bool hs_space_claims(uintptr_t addr);
/* Physical address of window address addr, or 0 if addr is in no region's window. */
uintptr_t hs_space_to_phys(uintptr_t addr);
/* Start and length of the window space (for the trap handler). */
void hs_space_bounds(uintptr_t *start, uintptr_t *len);

/* One register access of a CPU access split at register boundaries. */
struct hs_piece {
	uintptr_t addr;         /* window address */
	unsigned width;         /* 1, 2 or 4 */
};

/* Largest CPU access the trap splits (an SSE register's 16 bytes). */
#define HS_MAX_SPLIT_WIDTH 16U

/* Splits a CPU access of width bytes (1..HS_MAX_SPLIT_WIDTH) at window
 * address addr into the per-register accesses an ARM926 would issue for it,
 * lowest address first: one piece when the access lies inside one register;
 * otherwise each register's bytes as one access (a byte lane of a wider
 * register where the access starts or ends inside it), and 4-byte pieces
 * where no register is (the access path reports those).  Returns the count. */
unsigned hs_space_split(uintptr_t addr, unsigned width, bool write, struct hs_piece *pieces);

/* Installs/removes rtos_stub's MMIO handler for the window space. */
void hs_space_install_handler(void);
void hs_space_remove_handler(void);

/* Forgets what the accessors' route cache learnt: a PSC module's power changed, so
 * its regions' accesses must meet the power check again. */
void hs_space_power_changed(void);

/* Register-access log (trace.h's hs_trace_reglog) state. */
void hs_space_set_reglog(const char *filter, FILE *out);

#endif /* HOST_SIM_SPACE_INTERNAL_H */

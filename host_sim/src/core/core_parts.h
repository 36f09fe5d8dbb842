/*
 * core_parts.h — the simulator core's parts the board assembly (soc/board.c)
 * installs and removes: the trap handler and the traces (not part of the
 * public API).
 */
#ifndef HOST_SIM_CORE_PARTS_H
#define HOST_SIM_CORE_PARTS_H

#include <stdbool.h>

/* Installs the SIGSEGV handler that emulates plain pointer accesses to the
 * window space (x86-64), or that reports them clearly elsewhere.  Returns
 * true if accesses are emulated. */
bool hs_trap_install(void);
void hs_trap_remove(void);
/* Why emulation is unavailable ("" if available). */
const char *hs_trap_reason(void);

/* Forgets trace signals and closes files (board shutdown). */
void hs_trace_reset(void);

/* The task and interrupt timeline of an open VCD (kernel_timeline.c): started when
 * the VCD opens, stopped when it closes.  A task's signal holds one of these codes. */
enum hs_task_code {
	HS_TASK_DORMANT = 0, HS_TASK_READY, HS_TASK_RUNNING, HS_TASK_WAITING, HS_TASK_SUSPENDED,
	HS_TASK_WAITING_SUSPENDED,
};
void hs_kernel_timeline_start(void);
void hs_kernel_timeline_stop(void);

#endif /* HOST_SIM_CORE_PARTS_H */

/*
 * system.c — system state service calls: ready-queue rotation, CPU lock,
 * dispatch disabling, and the sns_* state queries.
 */
#include "kernel_impl.h"

/* Rotates the ready queue of tskpri (TPRI_SELF: the caller's priority). */
ER rot_rdq(PRI tskpri)
{
	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("rot_rdq", E_CTX);
	if (tskpri != TPRI_SELF && (tskpri < TMIN_TPRI || tskpri > TMAX_TPRI))
		return svc_result("rot_rdq", E_PAR);
	ready_rotate(tskpri == TPRI_SELF ? runtsk->bpri : tskpri);
	dispatch_if_needed();
	return E_OK;
}

/* rot_rdq from non-task context (TPRI_SELF is E_PAR there). */
ER irot_rdq(PRI tskpri)
{
	svc_charge();
	if (!ctx_nontask_unlocked())
		return svc_result("irot_rdq", E_CTX);
	if (tskpri < TMIN_TPRI || tskpri > TMAX_TPRI)
		return svc_result("irot_rdq", E_PAR);
	ready_rotate(tskpri);
	return E_OK;
}

/* Locks the CPU from a task: interrupts and dispatching held off. */
ER loc_cpu(void)
{
	svc_charge();
	if (cpu.kind != EXEC_TASK)
		return svc_result("loc_cpu", E_CTX);
	cpu.locked = true;
	return E_OK;
}

/* Locks the CPU from non-task context. */
ER iloc_cpu(void)
{
	svc_charge();
	if (cpu.kind == EXEC_TASK)
		return svc_result("iloc_cpu", E_CTX);
	cpu.locked = true;
	return E_OK;
}

/* Unlocks the CPU from a task: pending interrupts are taken, then a pending dispatch. */
ER unl_cpu(void)
{
	svc_charge();
	if (cpu.kind != EXEC_TASK)
		return svc_result("unl_cpu", E_CTX);
	if (cpu.locked) {
		cpu.locked = false;
		irq_dispatch_pending();
		dispatch_if_needed();
	}
	return E_OK;
}

/* Unlocks the CPU from non-task context: higher pending interrupts nest at once. */
ER iunl_cpu(void)
{
	svc_charge();
	if (cpu.kind == EXEC_TASK)
		return svc_result("iunl_cpu", E_CTX);
	if (cpu.locked) {
		cpu.locked = false;
		irq_dispatch_pending();
	}
	return E_OK;
}

/* Disables dispatching (the caller keeps the CPU; interrupts still run). */
ER dis_dsp(void)
{
	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("dis_dsp", E_CTX);
	cpu.dsp_disabled = true;
	return E_OK;
}

/* Enables dispatching; a higher-priority ready task runs at once. */
ER ena_dsp(void)
{
	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("ena_dsp", E_CTX);
	cpu.dsp_disabled = false;
	dispatch_if_needed();
	return E_OK;
}

/* TRUE in non-task context. */
bool_t sns_ctx(void)
{
	svc_charge();
	return cpu.kind != EXEC_TASK;
}

/* TRUE with the CPU locked. */
bool_t sns_loc(void)
{
	svc_charge();
	return cpu.locked;
}

/* TRUE with dispatching disabled. */
bool_t sns_dsp(void)
{
	svc_charge();
	return cpu.dsp_disabled;
}

/* TRUE when a dispatch could not happen now (non-task context, CPU lock, dis_dsp). */
bool_t sns_dpn(void)
{
	svc_charge();
	return cpu.kind != EXEC_TASK || cpu.locked || cpu.dsp_disabled || cpu.sil_lock != 0;
}

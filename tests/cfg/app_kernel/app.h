/*
 * app.h — a small app in EV3RT's idiom for the configurator's tests: IDs
 * come from kernel_cfg.h, priorities from TMIN_APP_TPRI, prototypes hidden
 * from the configurator's pass (TOPPERS_MACRO_ONLY).
 */
#include "kernel.h"
#include "rtos_cfg.h"

#define MAIN_PRIORITY   (TMIN_APP_TPRI + 1)
#define WORKER_PRIORITY (TMIN_APP_TPRI + 2)

#ifndef STACK_SIZE
#define STACK_SIZE      4096
#endif

#ifndef TOPPERS_MACRO_ONLY
extern void main_task(intptr_t exinf);
extern void worker_task(intptr_t exinf);
extern void cyclic_handler(intptr_t exinf);
extern void alarm_handler(intptr_t exinf);
extern void ev3_cyclic(intptr_t exinf);
extern void app_init(intptr_t exinf);

/* What the test reads back. */
struct app_result {
	int inits;
	int main_runs;
	ER get_tim_static;      /* get_tim(&a static of app.o) from the user task */
	ER get_tim_foreign;     /* get_tim(&a static outside app.o) */
	int cyclic_runs;
	bool_t cyclic_in_task;  /* sns_ctx() in the CRE_CYC handler */
	int ev3_cyclic_runs;
	bool_t ev3_cyclic_ctx;  /* sns_ctx() in the EV3_CRE_CYC handler */
	ER ev3_cyclic_dly;      /* dly_tsk(1) from the EV3_CRE_CYC handler */
	int alarm_runs;
	intptr_t received[4];
	int nreceived;
};
extern struct app_result app_result;
extern SYSTIM *app_foreign_static;
#endif

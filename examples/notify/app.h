/*
 * app.h — notify: an EV3RT 1.x app, written for TOPPERS/HRP3: IDs'
 * parameters, priorities, periods (read by app.cfg and app.c).
 *
 * Times are in microseconds, as HRP3 counts them.
 */
#ifdef __cplusplus
extern "C" {
#endif

#include "ev3api.h"
#include "target_test.h"

#define MAIN_PRIORITY   (TMIN_APP_TPRI + 1)
#define BLINK_PRIORITY  (TMIN_APP_TPRI + 2)

#ifndef STACK_SIZE
#define STACK_SIZE      4096
#endif /* STACK_SIZE */

#define BLINK_PERIOD    (500U * 1000U)  /* the LED task is activated every 0.5 s */
#define TICK_PERIOD     (100U * 1000U)  /* a semaphore signalled every 100 ms, once started */
#define QUARTER_PERIOD  (250U * 1000U)  /* an eventflag set every 250 ms */
#define SEND_PERIOD     (50U * 1000U)   /* a sample sent every 50 ms to a one-element queue */
#define COUNT_PERIOD    500U            /* a counter incremented every 500 us */
#define SAMPLE_VALUE    7

#ifndef TOPPERS_MACRO_ONLY

extern void main_task(intptr_t exinf);
extern void blink_task(intptr_t exinf);

/* Written by the kernel's notifications (TNFY_INCVAR, TENFY_INCVAR). */
extern intptr_t count_ticks;
extern intptr_t send_errors;

#endif /* TOPPERS_MACRO_ONLY */

#ifdef __cplusplus
}
#endif

/*
 * app.h — spp_loopback: the brick as Bluetooth SPP master and slave at
 * once, its master connected to its own slave (in ev3sim: --bt and
 * --bt-master on one socket).  Its tasks' priorities and stack size for
 * app.cfg, its tasks for app.c.
 */
#ifdef __cplusplus
extern "C" {
#endif

#include "ev3api.h"
#include "target_test.h"

#ifndef STACK_SIZE
#define STACK_SIZE      4096
#endif

#define MAIN_PRIORITY   (TMIN_APP_TPRI + 2)   /* the master's requests */
#define ANSWER_PRIORITY (TMIN_APP_TPRI + 1)   /* the master's reader */
#define SLAVE_PRIORITY  (TMIN_APP_TPRI + 1)   /* the slave's server */

#define REQUESTS        50      /* sensor requests the master sends */
#define REQUEST_MS      10      /* one every REQUEST_MS */
#define MOTOR_POWER     40      /* the power the master asks for motor A */

#ifndef TOPPERS_MACRO_ONLY

extern void main_task(intptr_t exinf);
extern void answer_task(intptr_t exinf);
extern void slave_task(intptr_t exinf);

#endif /* TOPPERS_MACRO_ONLY */

#ifdef __cplusplus
}
#endif

/*
 * ev3.h — EV3RT's platform header for the EV3 target, which every app sees
 * through kernel.h (target_kernel.h) and some include by name (public
 * source: ev3rt-git/ev3rt-hrp2, target/ev3_gcc/ev3.h): the app priorities,
 * the default stack size and SVC_PERROR.
 */
#ifndef TOPPERS_EV3_H
#define TOPPERS_EV3_H

#include "t_stddef.h"

/* The highest priority an application task may use: the levels above belong
 * to the platform (linux_compat's workers, the API's button task).  EV3RT's
 * platform keeps TMIN_TPRI..TMIN_TPRI + 7 for its own tasks; ev3lx needs five. */
#define TMIN_APP_TPRI 6

/* A task's stack size where the app does not give one: EV3RT's default. */
#ifndef STACK_SIZE
#define STACK_SIZE 4096
#endif

#ifndef TOPPERS_MACRO_ONLY
#ifdef __cplusplus
extern "C" {
#endif

/* Logs a service call's error (ercd < 0) with its expression, file and line,
 * through t_perror at LOG_ERROR; nothing for E_OK or a positive result. */
void svc_perror(const char *file, int_t line, const char *expr, ER ercd);

#ifdef __cplusplus
}
#endif

/* Calls expr and logs it if it fails (EV3RT's ev3.h). */
#define SVC_PERROR(expr) svc_perror(__FILE__, __LINE__, #expr, (expr))
#endif /* TOPPERS_MACRO_ONLY */

#endif /* TOPPERS_EV3_H */

/*
 * t_stdlib.h — TOPPERS's basic library functions: error names and the error
 * log line of a failed service call (public source: ev3rt-git/ev3rt-hrp2,
 * include/t_stdlib.h; on the AM1808 the kernel's library defines them).
 */
#ifndef TOPPERS_T_STDLIB_H
#define TOPPERS_T_STDLIB_H

#include "t_stddef.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The name of ercd's main error code ("E_PAR", "E_OK", ...); "unknown error" otherwise. */
const char *itron_strerror(ER ercd) throw();

/* Logs at prio that expr, at file:line, returned ercd (its name and sub code). */
void t_perror(uint_t prio, const char *file, int_t line, const char *expr, ER ercd) throw();

#ifdef __cplusplus
}
#endif

#endif /* TOPPERS_T_STDLIB_H */

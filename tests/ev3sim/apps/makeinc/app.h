/*
 * app.h — makeinc: an app whose Makefile.inc sets the variables EV3RT's
 * app build honours beyond the sources (COPTS, CDEFS, APPL_CFLAGS, SRCDIRS,
 * LDFLAGS, APPL_LIBS, LIBS, OMIT_OPTIMIZATION, OMIT_WARNING_ALL), in the
 * idiom of an ET Robocon app for EV3RT 1.x: app.cfg INCLUDEs tecsgen.cfg
 * (so it is built in the HRP3 profile) and #includes ev3.h by name.
 */
#ifdef __cplusplus
extern "C" {
#endif

#include "ev3api.h"
#include "target_test.h"

#define MAIN_PRIORITY (TMIN_APP_TPRI + 1)

#ifndef STACK_SIZE
#define STACK_SIZE 4096
#endif

#ifndef TOPPERS_MACRO_ONLY

extern void main_task(intptr_t exinf);
extern int gain_apply(int value);

#endif /* TOPPERS_MACRO_ONLY */

#ifdef __cplusplus
}
#endif

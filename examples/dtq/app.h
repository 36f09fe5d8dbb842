/*
 * app.h — dtq: IDs, priorities and stack sizes (read by app.cfg and app.c).
 */
#ifdef __cplusplus
extern "C" {
#endif

#include "ev3api.h"
#include "target_test.h"

#define CONSUMER_PRIORITY (TMIN_APP_TPRI + 1)

#ifndef STACK_SIZE
#define STACK_SIZE        4096
#endif

#define SAMPLE_PERIOD_MS  10    /* the producer's period */
#define QUEUE_DEPTH       8     /* data elements the queue holds */
#define ITEMS             300   /* the producer stops after this many */

#ifndef TOPPERS_MACRO_ONLY

extern void consumer_task(intptr_t exinf);
extern void producer_cyc(intptr_t exinf);

#endif /* TOPPERS_MACRO_ONLY */

#ifdef __cplusplus
}
#endif

/*
 * api_internal.h — helpers shared by the API's source files (not for applications).
 */
#ifndef EV3API_INTERNAL_H
#define EV3API_INTERNAL_H

#include <stdbool.h>
#include <stdint.h>
#include "kernel.h"
#include "t_syslog.h"

/*
 * The API's context rules (docs/api.md, "Context"), checked before a call does
 * anything: a call that makes a service call or may wait needs a task with the
 * CPU unlocked and dispatching enabled; a reading of the drivers' shared memory
 * works anywhere except in a task with the CPU locked (where TOPPERS offers no
 * prb_mem to check the caller's buffer).  Either way: E_CTX otherwise.
 */
static inline ER api_may_wait(void)
{
	return sns_ctx() || sns_loc() || sns_dsp() ? E_CTX : E_OK;
}

static inline ER api_may_read(void)
{
	return !sns_ctx() && sns_loc() ? E_CTX : E_OK;
}

/*
 * Whether the caller may write size bytes at p, an object aligned to align:
 * E_MACV for NULL or, from a task, memory outside its protection domain
 * (prb_mem; handlers run in the kernel domain); E_PAR if p is misaligned (the
 * ARM926 would store to the wrong address, not fault).  api_check_out_in
 * takes the context the caller already asked for (in_task: !sns_ctx()).
 */
static inline ER api_check_out_in(const void *p, SIZE size, SIZE align, bool_t in_task)
{
	if (p == NULL)
		return E_MACV;
	if ((uintptr_t)p & (align - 1U))
		return E_PAR;
	if (in_task && prb_mem(p, size, TSK_SELF, TPM_WRITE) != E_OK)
		return E_MACV;
	return E_OK;
}

static inline ER api_check_out(const void *p, SIZE size, SIZE align)
{
	return api_check_out_in(p, size, align, !sns_ctx());
}

/* api_check_out for the object p points to. */
#define API_CHECK_OUT(p) api_check_out((p), sizeof(*(p)), __alignof__(*(p)))

/* EV3RT's convention for a call that cannot return its error (a getter, or
 * a value corrected instead of refused): a warning through syslog naming the
 * call, the port or value, and the error. */
void api_warn(const char *call, int arg, ER ercd);

/* Forget everything of a previous boot (ATT_INI of ev3api_cfg, in config.c). */
void api_motor_boot(void);
void api_sensor_boot(void);
void api_brick_boot(void);
void api_battery_boot(void);
void api_speaker_boot(void);
void api_lcd_boot(void);
void api_serial_boot(void);
void api_app_heap_boot(void);
/* The LCD task's body (CRE_TSK EV3_LCD_TSKID in config.c): starts the panel at boot. */
void api_lcd_task(intptr_t exinf);
/* The app-init task's body (CRE_TSK EV3_APP_INIT_TSKID in config.c): runs
 * the app's C++ global constructors at boot (app_init.c). */
void api_app_init_task(intptr_t exinf);
/* What the app's objects call for __cxa_atexit (renamed by the app's
 * build): registers nothing, 0. */
int ev3rt_app_cxa_atexit(void (*destructor)(void *), void *object, void *dso_handle);
/* The apps' heap (app_heap.c): EV3LX_APP_HEAP_SIZE bytes in every user
 * domain's memory, as EV3RT's app heap is in the app's domain. */
#ifndef EV3LX_APP_HEAP_SIZE
#define EV3LX_APP_HEAP_SIZE (1024U * 1024U)
#endif
extern uint8_t api_app_heap[EV3LX_APP_HEAP_SIZE];
/* size bytes, 16-aligned, or NULL if the heap has no room (or size is 0). */
void *api_app_heap_alloc(SIZE size);
/* Frees what api_app_heap_alloc gave; E_PAR for anything else or a second free. */
ER api_app_heap_free(void *p);
/* The bytes usable at p, a block api_app_heap_alloc gave (at least what was asked). */
SIZE api_app_heap_usable_size(const void *p);

/* The frame of the LCD calls (lcd.c), in the format of lcd_draw.h: 7680 bytes. */
extern uint8_t api_lcd_frame[60 * 128];

/* The NXT I2C sensors (nxt_sensor.c), for sensor.c: the port leaves its I2C type old
 * and becomes type (either may be an I2C type or not); E_OK or the error. */
ER api_iic_config(unsigned port, int old_type, int type);
void api_iic_boot(void);
/* sensor.c's check of a reading: context, port, configured type, out pointer. */
ER api_sensor_check(unsigned port, int type, ER out_check);

/* The button task's body (CRE_TSK EV3_BUTTON_TSKID in config.c): runs click handlers. */
void api_button_task(intptr_t exinf);

#endif /* EV3API_INTERNAL_H */

/*
 * lcd_hack.h — st7586fb (the EV3 display's frame buffer driver) on the RTOS:
 * extended service calls (function codes LCD_FN_FIRST.. are the display's)
 * and the configuration fragment that defines them.  Plain TOPPERS C:
 * applications and the api include it.
 *
 * The frame is in the driver's format (st7586fb.h: 128 rows of 60 bytes,
 * three pixels a byte).  LCD_FN_INIT is what LEGO's user space does on
 * opening /dev/fb0: the INIT ioctl (controller reset and set-up, ~310 ms of
 * the caller's time), then START; LCD_FN_UPDATE write()s a frame, which the
 * driver pushes to the panel within FB_ST7586_REFRESH_MS; LCD_FN_FLUSH
 * pushes a pending frame now and returns when it is on the panel.
 *
 * Every call returns a TOPPERS code:
 *   E_PAR   a frame size other than FB_ST7586_SIZE
 *   E_MACV  a frame the calling task may not read
 *   E_CTX   called from non-task context
 *   E_OBJ   the driver is not loaded or found no display
 */
#ifndef EV3LX_LCD_HACK_H
#define EV3LX_LCD_HACK_H

#include "kernel.h"
#include "rtos_cfg.h"
#include "hack_interface.h"

/* The function codes this module owns: LCD_FN_FIRST .. + LCD_FN_COUNT - 1. */
#ifndef LCD_FN_FIRST
#define LCD_FN_FIRST (EV3LX_FNCD_BASE + 87)
#endif
#define LCD_FN_COUNT 8
#define LCD_FN_LAST  (LCD_FN_FIRST + LCD_FN_COUNT - 1)

#define LCD_FN_INIT   (LCD_FN_FIRST + 0)  /* (): INIT then START ioctls */
#define LCD_FN_UPDATE (LCD_FN_FIRST + 1)  /* (const uint8_t *frame, uint_t len): write() of a whole frame */
#define LCD_FN_FLUSH  (LCD_FN_FIRST + 2)  /* (): the pending frame on the panel now */

/* The rest needs the driver's ABI header: not for a configuration's names (cfg/ev3lx.cfg). */
#ifndef EV3LX_CFG_NAMES_ONLY
#include "st7586fb.h"

/* The DEF_SVC rows (INCLUDE it in the application's configuration). */
extern HACK_INTERFACE const struct rtos_cfg lcd_hack_cfg;

static inline ER lcd_svc_init(void)
{
	return (ER)cal_svc(LCD_FN_INIT, 0, 0, 0, 0, 0);
}

static inline ER lcd_svc_update(const uint8_t *frame, uint_t len)
{
	return (ER)cal_svc(LCD_FN_UPDATE, (intptr_t)frame, (intptr_t)len, 0, 0, 0);
}

static inline ER lcd_svc_flush(void)
{
	return (ER)cal_svc(LCD_FN_FLUSH, 0, 0, 0, 0, 0);
}

#endif /* EV3LX_CFG_NAMES_ONLY */
#endif /* EV3LX_LCD_HACK_H */

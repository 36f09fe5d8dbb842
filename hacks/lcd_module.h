/*
 * lcd_module.h — what the st7586fb module shares between its two translation
 * units: the hack file (lcd_hack.c, with the driver) defines it, the service
 * calls (lcd_svc.c) use it.  Linux types only; hidden in the module.
 */
#ifndef EV3LX_LCD_MODULE_H
#define EV3LX_LCD_MODULE_H

#include <linux/types.h>
#include <linux/fs.h>
#include <linux/mutex.h>
#include "st7586fb.h"

extern struct file *lcd_file;		/* /dev/fb0, opened by LCD_FN_INIT */
extern struct mutex lcd_hack_mutex;	/* guards lcd_file */

#endif /* EV3LX_LCD_MODULE_H */

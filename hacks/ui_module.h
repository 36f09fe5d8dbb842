/*
 * ui_module.h — what the d_ui module shares between its two translation
 * units: the hack file (ui_hack.c, with the driver) defines it, the service
 * calls (ui_svc.c) use it.  Linux types only; hidden in the module.
 */
#ifndef EV3LX_UI_MODULE_H
#define EV3LX_UI_MODULE_H

#include <linux/types.h>
#include <linux/fs.h>
#include "lms_ui.h"

extern struct file *ui_file;		/* /dev/lms_ui, non-blocking; NULL while d_ui is not up */
extern const struct lms_ui *ui_map;	/* its shared page, mapped */

#endif /* EV3LX_UI_MODULE_H */

/*
 * linux/pm_runtime.h — runtime power management as a kernel built without
 * CONFIG_PM has it (Linux 6.1's include/linux/pm_runtime.h, its !CONFIG_PM
 * branch): devices are always on, a resume succeeds at once and says the
 * device was active (1), a suspend is refused (-ENOSYS).  The AM1808's
 * modules are powered by the board code here, as LEGO's firmware does.
 */
#ifndef _LINUX_PM_RUNTIME_H
#define _LINUX_PM_RUNTIME_H

#include <linux/device.h>
#include <linux/errno.h>

static inline void pm_runtime_enable(struct device *dev) { }
static inline void pm_runtime_disable(struct device *dev) { }
static inline int devm_pm_runtime_enable(struct device *dev) { return 0; }
static inline bool pm_runtime_enabled(struct device *dev) { return false; }
static inline bool pm_runtime_active(struct device *dev) { return true; }
static inline bool pm_runtime_suspended(struct device *dev) { return false; }
static inline int pm_runtime_set_active(struct device *dev) { return 0; }
static inline void pm_runtime_set_suspended(struct device *dev) { }
static inline void pm_runtime_get_noresume(struct device *dev) { }
static inline void pm_runtime_put_noidle(struct device *dev) { }
static inline void pm_runtime_no_callbacks(struct device *dev) { }
static inline void pm_runtime_irq_safe(struct device *dev) { }
static inline int pm_runtime_resume(struct device *dev) { return 1; }
static inline int pm_runtime_get(struct device *dev) { return 1; }
static inline int pm_runtime_get_sync(struct device *dev) { return 1; }
static inline int pm_runtime_resume_and_get(struct device *dev) { return 0; }
static inline int pm_runtime_put(struct device *dev) { return -ENOSYS; }
static inline int pm_runtime_put_sync(struct device *dev) { return -ENOSYS; }
static inline int pm_runtime_put_autosuspend(struct device *dev) { return -ENOSYS; }
static inline int pm_runtime_put_sync_suspend(struct device *dev) { return -ENOSYS; }
static inline int pm_runtime_suspend(struct device *dev) { return -ENOSYS; }
static inline int pm_runtime_idle(struct device *dev) { return -ENOSYS; }
static inline void pm_runtime_mark_last_busy(struct device *dev) { }
static inline void pm_runtime_use_autosuspend(struct device *dev) { }
static inline void pm_runtime_dont_use_autosuspend(struct device *dev) { }
static inline void pm_runtime_set_autosuspend_delay(struct device *dev, int delay) { }

#endif /* _LINUX_PM_RUNTIME_H */

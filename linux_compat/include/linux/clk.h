/*
 * linux/clk.h — the clock API a driver uses to find and gate its clocks
 * (Linux's include/linux/clk.h), over the machine's table of named clocks
 * (mach-davinci/clock.c).  Gating is counted, not enforced: the PSC model
 * is what powers modules, as the drivers of the DaVinci era also program it.
 */
#ifndef __LINUX_CLK_H
#define __LINUX_CLK_H

#include <linux/err.h>
#include <linux/types.h>

struct device;
struct clk;

/* The clock named con_id for dev (entries without a device serve every
 * device): it, or ERR_PTR(-ENOENT) if the machine has no such clock. */
struct clk *clk_get(struct device *dev, const char *con_id);
/* Gives back what clk_get returned. */
void clk_put(struct clk *clk);
/* Counts an enable: 0, or -EINVAL for an error pointer or NULL. */
int clk_enable(struct clk *clk);
/* Drops an enable (an unbalanced one is reported). */
void clk_disable(struct clk *clk);
/* The clock's rate in Hz (0 for NULL or an error pointer). */
unsigned long clk_get_rate(struct clk *clk);

static inline int clk_prepare(struct clk *clk) { return 0; }
static inline void clk_unprepare(struct clk *clk) { }
static inline int clk_prepare_enable(struct clk *clk) { return clk_enable(clk); }
static inline void clk_disable_unprepare(struct clk *clk) { clk_disable(clk); }

#endif

/*
 * syscfg.c — the DA8xx SYSCFG windows LEGO's drivers write PINMUX and
 * CFGCHIP registers through (mach/da8xx.h), mapped again at every boot.
 */
#include <linux/io.h>
#include <linux/sizes.h>
#include <mach/da8xx.h>
#include <mach/hardware.h>
#include <linux_compat/irq.h>
#include <linux_compat/machine.h>

void __iomem *da8xx_syscfg0_base;
void __iomem *da8xx_syscfg1_base;

/* Maps the SYSCFG0 and SYSCFG1 blocks (4 KiB each). */
void lx_iomap_boot(void)
{
	da8xx_syscfg0_base = lx_io_map(DA8XX_SYSCFG0_BASE, SZ_4K);
	da8xx_syscfg1_base = lx_io_map(DA8XX_SYSCFG1_BASE, SZ_4K);
}

/*
 * mach/da8xx.h — DA8xx (AM1808) physical addresses and the SYSCFG windows.
 *
 * da8xx_syscfg0_base / da8xx_syscfg1_base are set at every boot (lx_io_boot,
 * linux_compat/src/io.c) to ioremap'd windows of SYSCFG0/SYSCFG1, as the
 * DA850 machine code did; on the host they are NULL unless host_sim models
 * those blocks (install its MMIO handler before booting).
 */
#ifndef __ASM_ARCH_DAVINCI_DA8XX_H
#define __ASM_ARCH_DAVINCI_DA8XX_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <mach/irqs.h>
#include <mach/hardware.h>
/*
 * What TI's DaVinci PSP 2.6.33 da8xx.h makes visible through its includes
 * (LEGO's kernel, mindboards/ev3sources extra/linux-03.20.00.13), and 2.6-era
 * board code relies on: <linux/module.h> (da8xx.h -> linux/platform_device.h
 * -> linux/device.h -> linux/module.h: EXPORT_SYMBOL, THIS_MODULE),
 * <linux/interrupt.h> (-> mach/mmc.h -> linux/mmc/host.h -> linux/mmc/core.h
 * -> linux/interrupt.h: irqreturn_t, request_irq) and <linux/sched.h>
 * (linux/mmc/host.h).  LEGO's d_pwm declares its irqreturn_t handlers after
 * am1808.h, which includes only this header, and before its own includes.
 */
#include <linux/module.h>
#include <linux/interrupt.h>
#include <linux/sched.h>
#include <linux/platform_device.h>	/* da8xx.h includes it itself */
#include <linux/io.h>			/* ioremap, memcpy_toio: da8xx.h -> mach/edma.h, mach/serial.h -> asm/io.h */
#include <linux/string.h>

struct davinci_i2c_platform_data;

/* The SoC's I2C controller instance (0: I2C0, 1: I2C1) as bus instance + 1,
 * driven by mach-davinci/i2c.c with pdata's speed (docs/linux-api.md, I2C):
 * 0, -EINVAL, -EBUSY (registered already) or the I2C core's error. */
int da8xx_register_i2c(int instance, struct davinci_i2c_platform_data *pdata);
/* Unregisters the instance's bus and its clients. */
void da8xx_unregister_i2c(int instance);

extern void __iomem *da8xx_syscfg0_base;
extern void __iomem *da8xx_syscfg1_base;

#define DA8XX_SYSCFG0_VIRT(x)	((void __iomem *)((char __iomem *)da8xx_syscfg0_base + (x)))
#define DA8XX_SYSCFG1_VIRT(x)	((void __iomem *)((char __iomem *)da8xx_syscfg1_base + (x)))

#define DA8XX_JTAG_ID_REG	0x18
#define DA8XX_KICK0_REG		0x38
#define DA8XX_KICK1_REG		0x3c
#define DA8XX_PINMUX_REG(n)	(0x120 + (n) * 4)
#define DA8XX_CFGCHIP0_REG	0x17c
#define DA8XX_CFGCHIP1_REG	0x180
#define DA8XX_CFGCHIP2_REG	0x184
#define DA8XX_CFGCHIP3_REG	0x188
#define DA8XX_PUPD_ENA_REG	0x0c    /* SYSCFG1 */
#define DA8XX_PUPD_SEL_REG	0x10    /* SYSCFG1 */

#define DA8XX_SYSCFG0_BASE	0x01c14000
#define DA8XX_SYSCFG1_BASE	0x01e2c000
#define DA8XX_PSC0_BASE		0x01c10000
#define DA8XX_PLL0_BASE		0x01c11000
#define DA8XX_TIMER64P0_BASE	0x01c20000
#define DA8XX_TIMER64P1_BASE	0x01c21000
#define DA8XX_I2C0_BASE		0x01c22000
#define DA8XX_SPI0_BASE		0x01c41000
#define DA8XX_UART0_BASE	0x01c42000
#define DA8XX_PRUSS_MEM_BASE	0x01c30000
#define DA8XX_MCASP0_BASE	0x01d00000
#define DA8XX_UART1_BASE	0x01d0c000
#define DA8XX_UART2_BASE	0x01d0d000
#define DA8XX_PLL1_BASE		0x01e1a000
#define DA8XX_GPIO_BASE		0x01e26000
#define DA8XX_I2C1_BASE		0x01e28000
#define DA8XX_PSC1_BASE		0x01e27000
#define DA8XX_EHRPWM0_BASE	0x01f00000
#define DA8XX_EHRPWM1_BASE	0x01f02000
#define DA8XX_ECAP0_BASE	0x01f06000
#define DA8XX_ECAP1_BASE	0x01f07000
#define DA8XX_ECAP2_BASE	0x01f08000
#define DA8XX_TIMER64P2_BASE	0x01f0c000
#define DA8XX_TIMER64P3_BASE	0x01f0d000
#define DA8XX_SPI1_BASE		0x01f0e000
#define DA8XX_SHARED_RAM_BASE	0x80000000
#define DA8XX_CP_INTC_BASE	0xfffee000

#endif /* __ASM_ARCH_DAVINCI_DA8XX_H */

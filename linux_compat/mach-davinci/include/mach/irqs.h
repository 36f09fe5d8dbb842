/*
 * mach/irqs.h — DA8xx (AM1808) interrupt numbers, as DaVinci's mach/irqs.h.
 *
 * IRQs 0..100 are the AINTC's system interrupts.  As on DaVinci, the GPIO
 * pins' own IRQs follow them: gpio_to_irq(gpio) = DAVINCI_N_AINTC_IRQ + gpio
 * = 101 + gpio, demultiplexed from the bank interrupts 42..50 by
 * linux_compat/mach-davinci/gpio.c.  Only the lines listed in linux_compat/irq.h
 * (LX_IRQ_LINES) have an RTOS interrupt service routine; request_irq on any
 * other AINTC line fails with -EINVAL.
 */
#ifndef __ASM_ARCH_IRQS_H
#define __ASM_ARCH_IRQS_H

#define IRQ_DA8XX_COMMTX	0
#define IRQ_DA8XX_COMMRX	1
#define IRQ_DA8XX_NINT		2
#define IRQ_DA8XX_EVTOUT0	3
#define IRQ_DA8XX_EVTOUT1	4
#define IRQ_DA8XX_EVTOUT2	5
#define IRQ_DA8XX_EVTOUT3	6
#define IRQ_DA8XX_EVTOUT4	7
#define IRQ_DA8XX_EVTOUT5	8
#define IRQ_DA8XX_EVTOUT6	9
#define IRQ_DA8XX_EVTOUT7	10
#define IRQ_DA8XX_EDMA3_CC0	11
#define IRQ_DA8XX_EDMA3_CC0_ERRINT 12
#define IRQ_DA8XX_EDMA3_TC0_ERRINT 13
#define IRQ_DA8XX_EMIFA		14
#define IRQ_DA8XX_I2CINT0	15
#define IRQ_DA8XX_MMCSDINT0	16
#define IRQ_DA8XX_MMCSDINT1	17
#define IRQ_DA8XX_PSCINT0	18
#define IRQ_DA8XX_RTC		19
#define IRQ_DA8XX_SPINT0	20
#define IRQ_DA8XX_TINT12_0	21
#define IRQ_DA8XX_TINT34_0	22
#define IRQ_DA8XX_TINT12_1	23
#define IRQ_DA8XX_TINT34_1	24
#define IRQ_DA8XX_UARTINT0	25
#define IRQ_DA8XX_GPIO0		42
#define IRQ_DA8XX_GPIO1		43
#define IRQ_DA8XX_GPIO2		44
#define IRQ_DA8XX_GPIO3		45
#define IRQ_DA8XX_GPIO4		46
#define IRQ_DA8XX_GPIO5		47
#define IRQ_DA8XX_GPIO6		48
#define IRQ_DA8XX_GPIO7		49
#define IRQ_DA8XX_GPIO8		50
#define IRQ_DA8XX_I2CINT1	51
/* The I2C controllers' lines under their other name (the AM1808 TRM's I2C0_INT/I2C1_INT); the
 * configuration uses the I2CINT names, which EV3RT's own Linux headers define as well. */
#define IRQ_DA8XX_IIC0		IRQ_DA8XX_I2CINT0
#define IRQ_DA8XX_IIC1		IRQ_DA8XX_I2CINT1
#define IRQ_DA8XX_LCDINT	52
#define IRQ_DA8XX_UARTINT1	53
#define IRQ_DA8XX_UARTINT2	61
#define IRQ_DA850_UARTINT1	53
#define IRQ_DA850_UARTINT2	61

/* AINTC system interrupts (0..100), then one IRQ per GPIO pin. */
#define DAVINCI_N_AINTC_IRQ	101
#define DA850_N_CP_INTC_IRQ	101
#define DAVINCI_N_GPIO		144
#define NR_IRQS			(DAVINCI_N_AINTC_IRQ + DAVINCI_N_GPIO)

#endif /* __ASM_ARCH_IRQS_H */

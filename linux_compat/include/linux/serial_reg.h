/*
 * linux/serial_reg.h — the 8250/16550 register numbers and bits (Linux's
 * include/uapi/linux/serial_reg.h), the part serial drivers name.
 */
#ifndef _LINUX_SERIAL_REG_H
#define _LINUX_SERIAL_REG_H

#define UART_RX		0	/* in:  receive buffer */
#define UART_TX		0	/* out: transmit buffer */
#define UART_DLL	0	/* out: divisor latch low (DLAB) */
#define UART_IER	1
#define UART_DLM	1	/* divisor latch high (DLAB) */
#define UART_IIR	2
#define UART_FCR	2
#define UART_LCR	3
#define UART_MCR	4
#define UART_LSR	5
#define UART_MSR	6
#define UART_SCR	7

#define UART_IER_RDI	0x01
#define UART_IER_THRI	0x02
#define UART_IER_RLSI	0x04
#define UART_IER_MSI	0x08

#define UART_IIR_NO_INT	0x01
#define UART_IIR_ID	0x0e

#define UART_LCR_DLAB	0x80
#define UART_LCR_SBC	0x40
#define UART_LCR_WLEN8	0x03

#define UART_LSR_DR	0x01
#define UART_LSR_OE	0x02
#define UART_LSR_PE	0x04
#define UART_LSR_FE	0x08
#define UART_LSR_BI	0x10
#define UART_LSR_THRE	0x20
#define UART_LSR_TEMT	0x40

#endif

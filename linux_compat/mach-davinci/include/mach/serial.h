/*
 * mach/serial.h — the DaVinci (AM1808) UARTs as ttys (mach-davinci/serial.c):
 * what the board registers so that /dev/ttyS<line> exists, as Linux's
 * board files register their 8250 ports.
 *
 * The driver programs the 16550-compatible UART of the AM1808 TRM's UART
 * chapter: 32-bit registers (DLL/DLH at 0x20/0x24, PWREMU_MGMT 0x30, MDR
 * 0x34), 16x oversampling, FIFOs on; reception on the receive-data,
 * timeout and line-status interrupts (break, framing, parity and overrun
 * reach the discipline as TTY_BREAK, _FRAME, _PARITY, _OVERRUN), and
 * transmission from a 512-byte buffer on the THR-empty interrupt (the
 * discipline's write_wakeup when it drains).  Baud, data bits, stop bits
 * and parity come from the tty's termios (divisor = clock / (16 x baud),
 * rounded).  Port opened: powered out of reset; closed: held in reset.
 *
 * On the EV3, input port 1 is UART1 (0x01d0c000, IRQ 53, 132 MHz from
 * PLL1 as LEGO's kernel sets it) and port 2 UART0 (0x01c42000, IRQ 25,
 * 150 MHz); ports 3 and 4 are PRU soft UARTs on the brick.
 */
#ifndef _MACH_SERIAL_H
#define _MACH_SERIAL_H

#include <linux/types.h>

#define DAVINCI_SERIAL_LINES	4

struct davinci_uart_port {
	unsigned int line;          /* /dev/ttyS<line>, 0 .. DAVINCI_SERIAL_LINES - 1 */
	resource_size_t mapbase;    /* physical address of the registers */
	unsigned int irq;           /* its Linux IRQ (one of LX_IRQ_LINES) */
	unsigned int uartclk;       /* module clock, Hz */
};

/* Registers /dev/ttyS<p->line> for the UART: 0, -EINVAL (bad line or
 * clock), -EBUSY (line taken), or the tty layer's error.  Process context. */
int davinci_serial_add(const struct davinci_uart_port *p);
/* Removes /dev/ttyS<line> (its tty must be closed).  Process context. */
void davinci_serial_del(unsigned int line);

#endif /* _MACH_SERIAL_H */

/*
 * serial_core.c — the serial core's helpers that low-level drivers call
 * (Linux's drivers/tty/serial/serial_core.c): uart_update_timeout.
 */
#include <linux/serial_core.h>
#include <linux/jiffies.h>

void uart_update_timeout(struct uart_port *port, unsigned int cflag, unsigned int baud)
{
	/* start bit, data bits, stop bit(s), parity: the character on the wire */
	static const unsigned char data_bits[4] = { 7, 8, 9, 10 };	/* CS5..CS8, with start and stop */
	unsigned int bits = data_bits[(cflag & CSIZE) >> 4];

	if (cflag & CSTOPB)
		bits++;
	if (cflag & PARENB)
		bits++;
	if (!baud)
		baud = 9600;
	port->timeout = (unsigned int)((unsigned long)HZ * bits * port->fifosize / baud) + HZ / 50;
}

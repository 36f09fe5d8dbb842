/*
 * test_serial_core.c — the serial core's pieces a low-level driver uses
 * (linux/serial_core.h): uart_update_timeout as Linux computes it (the FIFO
 * of characters of 7..12 bits at the baud, plus 20 ms, in jiffies), the
 * uart_circ_ helpers, and the port and termios constants' values.
 */
#define KBUILD_MODNAME "serialtest"
#include "lx_test.h"
#include <linux/serial_core.h>
#include "host_sim/board.h"

static void body(void)
{
	struct uart_port port = { .fifosize = 16 };
	char buf[8];
	struct circ_buf circ = { .buf = buf };

	uart_update_timeout(&port, CS8 | CREAD, 2400);
	is_int((int)port.timeout, 66 + 20, "CS8 at 2400 baud, 16 characters: 66 ms + 20 ms");
	uart_update_timeout(&port, CS7 | CSTOPB | PARENB, 2400);
	is_int((int)port.timeout, 73 + 20, "CS7, two stop bits, parity: 11 bits a character");
	uart_update_timeout(&port, CS8, 115200);
	is_int((int)port.timeout, 1 + 20, "CS8 at 115200");
	port.fifosize = 1;
	uart_update_timeout(&port, CS5, 0);
	is_int((int)port.timeout, 0 + 20, "baud 0 taken as 9600 (no division by zero)");
	ok(uart_circ_empty(&circ), "uart_circ_empty on a fresh ring");
	circ.head = 3;
	ok(!uart_circ_empty(&circ), "not after a byte");
	uart_circ_clear(&circ);
	ok(circ.head == 0 && circ.tail == 0, "uart_circ_clear");
	ok(UPIO_MEM == 2 && UPF_BOOT_AUTOCONF == (1U << 28) && UPF_IOREMAP == (1U << 31) && UART_CONFIG_TYPE == 1,
	   "UPIO_MEM, UPF_BOOT_AUTOCONF, UPF_IOREMAP, UART_CONFIG_TYPE as Linux's");
	ok(CSIZE == 060 && CS8 == 060 && CREAD == 0200 && CLOCAL == 04000 && TIOCSER_TEMT == 1,
	   "termios bits as asm-generic/termbits.h");
}

int main(void)
{
	tap_plan(11);
	is_int(hs_board_init(NULL), E_OK, "host_sim board");
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}

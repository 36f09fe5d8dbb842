/*
 * port_uarts.c — the UARTs behind the EV3's input ports as board devices:
 * each creates the SoC's UART model with the port's configuration
 * (ev3_port_uart) and remembers which port it serves.
 */
#include "host_sim/devices/ev3_ports.h"

static struct hs_uart *port_uarts[EV3_INPUT_PORTS];

/* Creates the UART of input port (0..3). */
static ER port_uart_create(unsigned port, void **ctx)
{
	struct hs_uart *u;
	ER er = hs_uart_create(&ev3_port_uart[port], &u);

	if (er != E_OK)
		return er;
	port_uarts[port] = u;
	*ctx = &port_uarts[port];
	return E_OK;
}

/* Frees the UART of a port (ctx: its slot in port_uarts). */
static void port_uart_destroy(void *ctx)
{
	struct hs_uart **slot = ctx;

	hs_uart_destroy(*slot);
	*slot = NULL;
}

static ER uart1_create(const struct hs_board_cfg *cfg, void **ctx)
{
	return port_uart_create(0, ctx);
}

static ER uart0_create(const struct hs_board_cfg *cfg, void **ctx)
{
	return port_uart_create(1, ctx);
}

static ER suart3_create(const struct hs_board_cfg *cfg, void **ctx)
{
	return port_uart_create(2, ctx);
}

static ER suart4_create(const struct hs_board_cfg *cfg, void **ctx)
{
	return port_uart_create(3, ctx);
}

const struct hs_device ev3_uart1_device = { "UART1", uart1_create, NULL, port_uart_destroy };
const struct hs_device ev3_uart0_device = { "UART0", uart0_create, NULL, port_uart_destroy };
const struct hs_device ev3_suart_in3_device = { "SUART_IN3", suart3_create, NULL, port_uart_destroy };
const struct hs_device ev3_suart_in4_device = { "SUART_IN4", suart4_create, NULL, port_uart_destroy };

struct hs_uart *ev3_input_uart(unsigned port)
{
	return port < EV3_INPUT_PORTS ? port_uarts[port] : NULL;
}

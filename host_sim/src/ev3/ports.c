/*
 * ports.c — the EV3 (EP2) port wiring tables (the pin tables of LEGO's d_pwm.c and d_analog.c).
 */
#include "host_sim/psc.h"
#include "host_sim/devices/ev3_ports.h"

const struct ev3_input_pins ev3_input_pins[EV3_INPUT_PORTS] = {
	{ HS_GPIO(8, 10), HS_GPIO(2, 2),  HS_GPIO(0, 2),  HS_GPIO(0, 15), HS_GPIO(8, 11), 6, 5 },
	{ HS_GPIO(8, 12), HS_GPIO(8, 15), HS_GPIO(0, 14), HS_GPIO(0, 13), HS_GPIO(8, 14), 8, 7 },
	{ HS_GPIO(8, 9),  HS_GPIO(7, 11), HS_GPIO(0, 12), HS_GPIO(1, 14), HS_GPIO(7, 9),  10, 9 },
	{ HS_GPIO(6, 4),  HS_GPIO(7, 8),  HS_GPIO(0, 1),  HS_GPIO(1, 15), HS_GPIO(7, 10), 12, 11 },
};

const struct ev3_output_pins ev3_output_pins[EV3_OUTPUT_PORTS] = {
	{ HS_GPIO(3, 15), HS_GPIO(3, 6),  HS_GPIO(5, 11), HS_GPIO(5, 4),  HS_GPIO(0, 4),  1 },
	{ HS_GPIO(2, 1),  HS_GPIO(0, 3),  HS_GPIO(5, 8),  HS_GPIO(2, 5),  HS_GPIO(2, 9),  0 },
	{ HS_GPIO(6, 8),  HS_GPIO(5, 9),  HS_GPIO(5, 13), HS_GPIO(3, 8),  HS_GPIO(3, 14), 13 },
	{ HS_GPIO(5, 3),  HS_GPIO(5, 10), HS_GPIO(6, 9),  HS_GPIO(5, 15), HS_GPIO(2, 8),  14 },
};

const enum hs_pwm_output ev3_output_pwm[EV3_OUTPUT_PORTS] = {
	HS_PWM_EHRPWM1_B, HS_PWM_EHRPWM1_A, HS_PWM_ECAP0, HS_PWM_ECAP1,
};

/* UART1 runs from the ASYNC3 domain at 132 MHz as LEGO's kernel sets PLL1,
 * UART0 from PLL0 SYSCLK2 at 150 MHz: LEGO's d_uart divisors then give the
 * exact rates.  Ports 3 and 4 are stand-ins for the PRU soft UARTs. */
const struct hs_uart_cfg ev3_port_uart[EV3_INPUT_PORTS] = {
	{ "UART1", HS_UART1_BASE, EV3_UART1_INTNO, HS_PLL1_SYSCLK2_HZ, HS_PSC1_MODULE(HS_LPSC1_UART1) },
	{ "UART0", HS_UART0_BASE, EV3_UART0_INTNO, HS_PLL0_SYSCLK2_HZ, HS_PSC0_MODULE(HS_LPSC0_UART0) },
	{ "SUART_IN3", EV3_SUART_PORT3_BASE, EV3_SUART_PORT3_INTNO, EV3_SUART_CLOCK_HZ, HS_NO_PSC },
	{ "SUART_IN4", EV3_SUART_PORT4_BASE, EV3_SUART_PORT4_INTNO, EV3_SUART_CLOCK_HZ, HS_NO_PSC },
};

const struct ev3_suart_pins ev3_port_suart_pins[EV3_INPUT_PORTS] = {
	[2] = { .rx_ser = 2, .tx_ser = 4 },
	[3] = { .rx_ser = 1, .tx_ser = 3 },
};

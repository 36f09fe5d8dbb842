/*
 * ev3_ports.h — how the EV3's input ports 1-4 and output ports A-D are wired
 * to the AM1808 (EP2 board, the pin tables of LEGO's d_pwm.c and d_analog.c): GPIO pins, PWM sources, ADC
 * channels, and the UART behind each input port.  Host only; the tables
 * are data the device models and the tests share.
 *
 * Input ports 3 and 4 use PRU soft UARTs on the real brick.  ev3lx models
 * them as two more 16550-style UARTs at stand-in addresses in a range the
 * AM1808 memory map leaves reserved, on the AINTC lines of the PRU events
 * LEGO uses for those ports (EVTOUT1 = 4 for port 3, EVTOUT0 = 3 for port 4).
 */
#ifndef HOST_SIM_DEVICES_EV3_PORTS_H
#define HOST_SIM_DEVICES_EV3_PORTS_H

#include <stdbool.h>
#include <stdint.h>
#include "host_sim/board.h"
#include "host_sim/gpio.h"
#include "host_sim/devices/pwm.h"
#include "host_sim/devices/uart16550.h"

#define EV3_INPUT_PORTS   4U
#define EV3_OUTPUT_PORTS  4U

/* GPIOs of an input port (LEGO's d_pwm.c/d_analog.c pin tables, EP2). */
struct ev3_input_pins {
	unsigned pin1_9v;           /* pin 1: switches 9 V for NXT sensors (brick output) */
	unsigned pin2;              /* LEGDET: NXT device detect (input) */
	unsigned pin5;              /* brick -> sensor: UART TX via buffer, and GPIO */
	unsigned pin6;              /* sensor -> brick: UART RX, GPIO and ADC */
	unsigned tx_buffer_off;     /* TX buffer disable (low = buffer on) */
	uint8_t adc_pin1, adc_pin6; /* ADC channels of pin 1 and pin 6 */
};

/* GPIOs of an output port. */
struct ev3_output_pins {
	unsigned dir0, dir1;        /* pins 1 / 2: H-bridge inputs */
	unsigned tacho_int;         /* pin 5: tacho INT (both edges) and ADC OutPin5 */
	unsigned det_5w;            /* pin 5w: DETx0 detection pull */
	unsigned tacho_dir;         /* pin 6: tacho DIR */
	uint8_t adc_pin5;           /* ADC channel of pin 5 */
};

extern const struct ev3_input_pins ev3_input_pins[EV3_INPUT_PORTS];
extern const struct ev3_output_pins ev3_output_pins[EV3_OUTPUT_PORTS];
/* Which PWM output of the AM1808 drives each output port. */
extern const enum hs_pwm_output ev3_output_pwm[EV3_OUTPUT_PORTS];

/* ADC channels of the brick's own signals (LEGO's d_analog.c). */
#define EV3_ADC_BATTERY_TEMP     2U
#define EV3_ADC_MOTOR_CURRENT    15U
#define EV3_ADC_BATTERY_CURRENT  3U
#define EV3_ADC_BATTERY_VOLTAGE  4U

/* The UART behind each input port: register base, AINTC line, module clock
 * (ports 3 and 4: stand-ins for the PRU soft UARTs, see below). */
extern const struct hs_uart_cfg ev3_port_uart[EV3_INPUT_PORTS];

/* The board devices creating them (port 1: UART1, port 2: UART0, ports 3/4: stand-ins). */
extern const struct hs_device ev3_uart1_device;
extern const struct hs_device ev3_uart0_device;
extern const struct hs_device ev3_suart_in3_device;
extern const struct hs_device ev3_suart_in4_device;

/* The UART behind input port (0..3), or NULL if its device is not on the board. */
struct hs_uart *ev3_input_uart(unsigned port);

/* Stand-in UARTs for the PRU soft UARTs of ports 3 and 4 (reserved range
 * after the McBSP FIFO registers in the AM1808 memory map). */
#define EV3_SUART_PORT3_BASE  0x01F18000U
#define EV3_SUART_PORT4_BASE  0x01F19000U
#define EV3_SUART_PORT3_INTNO 4U            /* PRU EVTOUT1, as LEGO's port 3 */
#define EV3_SUART_PORT4_INTNO 3U            /* PRU EVTOUT0, as LEGO's port 4 */
#define EV3_SUART_CLOCK_HZ    150000000U

/* The McASP0 serializer pins of the PRU soft UART behind each input port
 * (0: none): LEGO's omapl_suart_board.h gives soft UART 1 receive AXR1 and
 * transmit AXR3, soft UART 2 AXR2 and AXR4, and its d_uart_mod.c drives
 * port 3 through soft UART 2, port 4 through soft UART 1. */
struct ev3_suart_pins {
	uint8_t rx_ser, tx_ser;
};
extern const struct ev3_suart_pins ev3_port_suart_pins[EV3_INPUT_PORTS];

#define EV3_UART0_INTNO       25U
#define EV3_UART1_INTNO       53U

#endif /* HOST_SIM_DEVICES_EV3_PORTS_H */

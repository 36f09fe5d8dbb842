/*
 * board.c — the EV3 board: every model hs_board_init creates for it, the
 * SoC's peripherals first, then the board's own models that connect to them.
 */
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/ev3_ui.h"
#include "host_sim/devices/ev3_lcd.h"
#include "host_sim/devices/ev3_power.h"
#include "host_sim/devices/ev3_speaker.h"
#include "host_sim/devices/pwm.h"
#include "host_sim/devices/spi_adc.h"
#include "host_sim/devices/pru_suart.h"

const struct hs_device *const ev3_board_devices[] = {
	&hs_ehrpwm0_device, &hs_ehrpwm1_device, &hs_ecap0_device, &hs_ecap1_device, &hs_spi0_device, &ev3_adc_device,
	&hs_spi1_device, &ev3_lcd_device,
	&ev3_uart1_device, &ev3_uart0_device, &ev3_suart_in3_device, &ev3_suart_in4_device,
	&hs_pru_suart_device,
	&ev3_ports_device, &ev3_ui_device, &ev3_power_device,
	&ev3_speaker_device, NULL,
};

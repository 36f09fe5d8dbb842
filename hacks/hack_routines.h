/*
 * hack_routines.h — the routines of the modules' RTOS sides that the library's
 * static-API fragment (cfg/ev3lx.cfg) names: every extended service routine
 * (DEF_SVC) and initialisation routine (ATT_INI).  They are global symbols
 * (HACK_INTERFACE), so that the configurator's kernel_cfg.c, HRP2's or
 * ev3cfg's, can name them from outside the module.
 */
#ifndef EV3LX_HACK_ROUTINES_H
#define EV3LX_HACK_ROUTINES_H

#include <kernel.h>
#include "hack_interface.h"

/* An extended service routine: the caller's five parameters and its domain. */
#define HACK_SVC(name) \
	HACK_INTERFACE ER_UINT name(intptr_t par1, intptr_t par2, intptr_t par3, intptr_t par4, \
				    intptr_t par5, ID cdmid)

/* analog */
HACK_SVC(svc_analog_map);
HACK_SVC(svc_analog_input);
HACK_SVC(svc_analog_output);
HACK_SVC(svc_analog_dcm_write);
HACK_SVC(svc_analog_dcm_read);
HACK_SVC(svc_analog_text);
/* iic */
HACK_SVC(svc_iic_start);
HACK_SVC(svc_iic_stop);
HACK_SVC(svc_iic_type_info);
HACK_SVC(svc_iic_set);
HACK_SVC(svc_iic_setup);
HACK_SVC(svc_iic_map);
HACK_SVC(svc_iic_state);
/* lcd */
HACK_SVC(svc_lcd_init);
HACK_SVC(svc_lcd_update);
HACK_SVC(svc_lcd_flush);
/* power */
HACK_SVC(svc_power_rechargeable);
HACK_SVC(svc_power_test_pin);
/* pwm */
HACK_SVC(svc_pwm_command);
HACK_SVC(svc_pwm_command2);
HACK_SVC(svc_pwm_run);
HACK_SVC(svc_pwm_read);
HACK_SVC(svc_pwm_busy);
HACK_SVC(svc_pwm_set_busy);
HACK_SVC(svc_pwm_motor_data);
HACK_SVC(svc_pwm_motor_map);
/* sound */
HACK_SVC(svc_sound_write);
HACK_SVC(svc_sound_play_pcm);
HACK_SVC(svc_sound_status);
/* uart */
HACK_SVC(svc_uart_set_mode);
HACK_SVC(svc_uart_stop);
HACK_SVC(svc_uart_mode_info);
HACK_SVC(svc_uart_clear_changed);
HACK_SVC(svc_uart_write);
HACK_SVC(svc_uart_map);
/* ui */
HACK_SVC(svc_ui_led);
HACK_SVC(svc_ui_map);
HACK_SVC(svc_ui_wait_click);

/* ATT_INI of the UART and I2C sensor modules: forget the previous boot's file. */
HACK_INTERFACE void uart_hack_boot(intptr_t exinf);
HACK_INTERFACE void iic_hack_boot(intptr_t exinf);

#endif /* EV3LX_HACK_ROUTINES_H */

/*
 * test_fuzz_api.c — fuzz harness: EV3RT's API called from an application
 * task of a user domain, as an app would call it, with arguments from the
 * input: any port, type, power, angle, colour, font, coordinate or length,
 * and pointers that are the task's own (its stack), NULL, outside its
 * domain (a global of the harness) or misaligned.  Each call must return
 * (an error code, a logged warning and a neutral value, or its effect);
 * nothing may crash, hang past FZ_WORK_LIMIT_MS or make the stack report a
 * bug.  The input is a sequence of calls: an opcode byte, then the
 * argument bytes its entry of calls[] takes.  Large and medium motors turn
 * on A and B, C and D are empty; a touch sensor is on 1, a gyro on 2, a
 * colour sensor on 3, port 4 is empty.
 */
#define _POSIX_C_SOURCE 200809L
#define _FILE_OFFSET_BITS 64	/* readdir of a 64-bit host directory from a 32-bit guest (qemu-arm) */
#define FZ_WORK_LIMIT_MS 60000	/* a sensor configured on the wrong port waits for it, once: 4 s */
#include "fuzz_brick.h"
#include "ev3api_motor.h"
#include "ev3api_sensor.h"
#include "ev3api_brick.h"
#include "ev3api_cyc.h"
#include "ev3api_lcd.h"
#include "ev3api_speaker.h"
#include "ev3api_battery.h"
#include "ev3api_fs.h"
#include "ev3api_cfg.h"
#include "syssvc/serial.h"
#include "host_sim/devices/uart_sensor.h"

#define FUZZ_NAME "api"
#define APP_DOMAIN 1

/* Memory the app's task may not touch: a global of the harness, in no domain. */
static uint8_t outside_domain[64] __attribute__((aligned(8)));

/* The bytes of one call: read in order, 0 past the end. */
struct args {
	const uint8_t *at, *end;
	uint8_t scratch[96] __attribute__((aligned(8)));     /* the task's own memory (its stack) */
};

static uint8_t arg8(struct args *a)
{
	return a->at < a->end ? *a->at++ : 0;
}

static int32_t arg32(struct args *a)
{
	uint32_t v = 0;

	for (int i = 0; i < 4; i++)
		v |= (uint32_t)arg8(a) << (8 * i);
	return (int32_t)v;
}

/* A small signed value around the valid range, or now and then any 32-bit one. */
static int32_t arg_value(struct args *a)
{
	uint8_t b = arg8(a);

	return b == 0x80 ? arg32(a) : (int32_t)(int8_t)b * 2;
}

/* A pointer the caller might pass: its own buffer (NUL-terminated text from
 * the input), NULL, memory outside its domain, or its buffer misaligned. */
static void *arg_ptr(struct args *a)
{
	uint8_t kind = arg8(a), len = arg8(a) % sizeof(a->scratch);

	for (size_t i = 0; i < len; i++)
		a->scratch[i] = (uint8_t)(arg8(a) | 0x20U);
	a->scratch[len] = '\0';
	switch (kind & 3U) {
	case 0: return a->scratch;
	case 1: return NULL;
	case 2: return outside_domain;
	default: return a->scratch + 1;
	}
}

static void call(uint8_t op, struct args *a)
{
	switch (op % 40U) {
	case 0: (void)ev3_motor_config((motor_port_t)arg8(a), (motor_type_t)arg8(a)); break;
	case 1: (void)ev3_motor_get_type((motor_port_t)arg8(a)); break;
	case 2: (void)ev3_motor_get_counts((motor_port_t)arg8(a)); break;
	case 3: (void)ev3_motor_reset_counts((motor_port_t)arg8(a)); break;
	case 4: (void)ev3_motor_set_power((motor_port_t)arg8(a), arg_value(a)); break;
	case 5: (void)ev3_motor_get_power((motor_port_t)arg8(a)); break;
	case 6: (void)ev3_motor_stop((motor_port_t)arg8(a), arg8(a) & 1U); break;
	case 7: {
		motor_port_t port = (motor_port_t)arg8(a);
		int degrees = arg_value(a);

		(void)ev3_motor_rotate(port, degrees, (uint32_t)arg_value(a), false);
		break;
	}
	case 8: {
		motor_port_t left = (motor_port_t)arg8(a), right = (motor_port_t)arg8(a);
		int power = arg_value(a);

		(void)ev3_motor_steer(left, right, power, arg_value(a));
		break;
	}
	case 9: (void)ev3_sensor_config((sensor_port_t)arg8(a), (sensor_type_t)arg8(a)); break;
	case 10: (void)ev3_sensor_get_type((sensor_port_t)arg8(a)); break;
	case 11: (void)ev3_color_sensor_get_color((sensor_port_t)arg8(a)); break;
	case 12: (void)ev3_color_sensor_get_reflect((sensor_port_t)arg8(a)); break;
	case 13: (void)ev3_color_sensor_get_ambient((sensor_port_t)arg8(a)); break;
	case 14: {
		sensor_port_t port = (sensor_port_t)arg8(a);

		ev3_color_sensor_get_rgb_raw(port, arg_ptr(a));
		break;
	}
	case 15: (void)ev3_gyro_sensor_get_angle((sensor_port_t)arg8(a)); break;
	case 16: (void)ev3_gyro_sensor_get_rate((sensor_port_t)arg8(a)); break;
	case 17: (void)ev3_gyro_sensor_reset((sensor_port_t)arg8(a)); break;
	case 18: (void)ev3_ultrasonic_sensor_get_distance((sensor_port_t)arg8(a)); break;
	case 19: (void)ev3_touch_sensor_is_pressed((sensor_port_t)arg8(a)); break;
	case 20: (void)ev3_infrared_sensor_get_distance((sensor_port_t)arg8(a)); break;
	case 21: (void)ev3_led_set_color((ledcolor_t)arg8(a)); break;
	case 22: (void)ev3_button_is_pressed((button_t)arg8(a)); break;
	case 23: (void)ev3_lcd_set_font((lcdfont_t)arg8(a)); break;
	case 24: {
		lcdfont_t font = (lcdfont_t)arg8(a);
		int32_t *w = arg_ptr(a);

		(void)ev3_font_get_size(font, w, arg_ptr(a));
		break;
	}
	case 25: {
		const char *text = arg_ptr(a);
		int32_t x = arg_value(a);

		(void)ev3_lcd_draw_string(text, x, arg_value(a));
		break;
	}
	case 26: {
		int32_t x0 = arg_value(a), y0 = arg_value(a), x1 = arg_value(a);

		(void)ev3_lcd_draw_line(x0, y0, x1, arg_value(a));
		break;
	}
	case 27: {
		int32_t x = arg_value(a), y = arg_value(a), w = arg_value(a), h = arg_value(a);

		(void)ev3_lcd_fill_rect(x, y, w, h, (lcdcolor_t)arg8(a));
		break;
	}
	case 28: {
		memfile_t file = { .buffer = arg_ptr(a) };
		image_t image;

		file.filesz = file.buffersz = arg8(a);
		if (ev3_image_load(&file, &image) == E_OK) {
			(void)ev3_lcd_draw_image(&image, arg_value(a), arg_value(a));
			(void)ev3_image_free(&image);
		}
		break;
	}
	case 29: (void)ev3_speaker_set_volume(arg8(a)); break;
	case 30: {
		uint16_t frequency = (uint16_t)arg32(a);

		(void)ev3_speaker_play_tone(frequency, arg_value(a));
		break;
	}
	case 31: (void)ev3_speaker_stop(); break;
	case 32: (void)ev3_battery_voltage_mV(); (void)ev3_battery_current_mA(); break;
	case 33: (void)ev3_sta_cyc(arg8(a)); break;
	case 34: (void)ev3_stp_cyc(arg8(a)); break;
	case 35: {
		ID port = arg8(a);
		const char *bytes = arg_ptr(a);

		(void)serial_wri_dat(port, bytes, arg8(a) % 64U);
		break;
	}
	case 36: (void)serial_ctl_por(arg8(a), (uint_t)arg32(a)); break;
	case 37: {
		memfile_t file;
		const char *path = arg_ptr(a);

		if (ev3_memfile_load(path, &file) == E_OK)
			(void)ev3_memfile_free(&file);
		break;
	}
	case 38: (void)ev3_memfile_free(arg_ptr(a)); break;
	default: dly_tsk((RELTIM)(arg8(a) % 20U)); break;
	}
}

static void work(const uint8_t *data, size_t size)
{
	struct args a = { .at = data, .end = data + size };

	while (a.at < a.end)
		call(arg8(&a), &a);
	/* leave the brick as a new input expects it: motors off, the speaker quiet */
	for (motor_port_t p = EV3_PORT_A; p <= EV3_PORT_D; p++)
		(void)ev3_motor_stop(p, false);
	(void)ev3_speaker_stop();
}

static void attach(void)
{
	ev3_attach_motor(0, HS_MOTOR_LARGE, NULL);
	ev3_attach_motor(1, HS_MOTOR_MEDIUM, NULL);
	ev3_attach_analog(0, EV3_INPUT_EV3_TOUCH, NULL);
	ev3_attach_uart_sensor(1, UART_SENSOR_TYPE_GYRO, NULL);
	ev3_attach_uart_sensor(2, UART_SENSOR_TYPE_COLOR, NULL);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static const struct rtos_cfg *const includes[] = { &ev3api_cfg, NULL };

	if (!fz.booted) {
		fz_boot_with(includes, APP_DOMAIN, NULL);
		attach();
	}
	fz_run(work, data, size);
	fz_settle(10, size);
	return 0;
}

#define FUZZ_FINISH fz_shutdown
#include "fuzz_replay.h"

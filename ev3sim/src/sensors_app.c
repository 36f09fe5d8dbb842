/*
 * sensors_app.c — `ev3sim sensors`: what the drivers detect on every port,
 * then live values through the EV3 API (apps.h).
 */
#include <string.h>
#include "ev3api_motor.h"
#include "ev3api_sensor.h"
#include "analog_hack.h"
#include "rtos_host.h"
#include "ev3api_cfg.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/nxt_iic.h"
#include "ev3sim/apps.h"

#define SENSORS_TSKID  1
#define APP_DOMAIN     1
#define DETECT_MS      3000U        /* d_analog starts detecting at 2 s (dcm_start_ms) and needs 350 ms */
#define TOUCH_TOGGLE_NS 1000000000ULL

static const char *const in_names[EV3SIM_IN_COUNT] = {
	"none", "touch", "nxt-touch", "nxt-light", "gyro", "color", "ultrasonic", "ir",
	"ht-accel", "ht-color", "nxt-temp",
};
static const char *const out_names[EV3SIM_OUT_COUNT] = { "none", "large", "medium" };

const char *ev3sim_input_device_name(enum ev3sim_input_device d)
{
	return (unsigned)d < EV3SIM_IN_COUNT ? in_names[d] : "?";
}

const char *ev3sim_output_device_name(enum ev3sim_output_device d)
{
	return (unsigned)d < EV3SIM_OUT_COUNT ? out_names[d] : "?";
}

ER ev3sim_attach_nxt_iic(unsigned port, enum ev3sim_input_device d)
{
	static const struct nxt_iic_scene scene = {
		.accel = { 0, 0, 200 }, .color_number = 17, .rgb = { 255, 255, 255 }, .white = 255,
		.temp_c = 22.5,
	};

	switch (d) {
	case EV3SIM_IN_HT_ACCEL: return ev3_attach_nxt_iic(port, NXT_IIC_HT_ACCEL, &scene);
	case EV3SIM_IN_HT_COLOR: return ev3_attach_nxt_iic(port, NXT_IIC_HT_COLOR_V2, &scene);
	case EV3SIM_IN_NXT_TEMP: return ev3_attach_nxt_iic(port, NXT_IIC_TEMP, &scene);
	default:                 return E_PAR;
	}
}

bool ev3sim_input_device_parse(const char *s, enum ev3sim_input_device *d)
{
	for (unsigned i = 0; i < EV3SIM_IN_COUNT; i++)
		if (strcmp(s, in_names[i]) == 0) {
			*d = (enum ev3sim_input_device)i;
			return true;
		}
	return false;
}

bool ev3sim_output_device_parse(const char *s, enum ev3sim_output_device *d)
{
	for (unsigned i = 0; i < EV3SIM_OUT_COUNT; i++)
		if (strcmp(s, out_names[i]) == 0) {
			*d = (enum ev3sim_output_device)i;
			return true;
		}
	return false;
}

void ev3sim_sensors_defaults(struct ev3sim_sensors_opts *o)
{
	static const struct ev3sim_sensors_opts defaults = {
		.in = { EV3SIM_IN_TOUCH, EV3SIM_IN_GYRO, EV3SIM_IN_COLOR, EV3SIM_IN_ULTRASONIC },
		.out = { EV3SIM_OUT_LARGE, EV3SIM_OUT_MEDIUM, EV3SIM_OUT_NONE, EV3SIM_OUT_LARGE },
		.seconds = 3.0, .every_ms = 500, .seed = 1,
	};

	*o = defaults;
}

static struct {
	struct ev3sim_sensors_opts o;
	FILE *out;
	bool done;
	bool pressed;
	unsigned rows, api_errors;
	int8_t in_conn[4], in_dcm[4], out_conn[4], out_dcm[4];
} run;

/* d_analog's connection codes by name. */
static const char *conn_name(int conn)
{
	switch (conn) {
	case LMS_CONN_UNKNOWN:           return "UNKNOWN";
	case LMS_CONN_DAISYCHAIN:        return "DAISYCHAIN";
	case LMS_CONN_NXT_COLOR:         return "NXT_COLOR";
	case LMS_CONN_NXT_DUMB:          return "NXT_DUMB";
	case LMS_CONN_NXT_IIC:           return "NXT_IIC";
	case LMS_CONN_INPUT_DUMB:        return "INPUT_DUMB";
	case LMS_CONN_INPUT_UART:        return "INPUT_UART";
	case LMS_CONN_OUTPUT_DUMB:       return "OUTPUT_DUMB";
	case LMS_CONN_OUTPUT_INTELLIGENT: return "OUTPUT_INTELLIGENT";
	case LMS_CONN_OUTPUT_TACHO:      return "OUTPUT_TACHO";
	case LMS_CONN_NONE:              return "NONE";
	case LMS_CONN_ERROR:             return "ERROR";
	default:                         return "?";
	}
}

/* LEGO device type codes by name. */
static const char *type_name(int type)
{
	switch (type) {
	case LMS_TYPE_NXT_TOUCH:  return "NXT touch";
	case LMS_TYPE_NXT_LIGHT:  return "NXT light";
	case LMS_TYPE_NXT_SOUND:  return "NXT sound";
	case LMS_TYPE_NXT_COLOR:  return "NXT colour";
	case LMS_TYPE_TACHO:      return "large motor";
	case LMS_TYPE_MINITACHO:  return "medium motor";
	case LMS_TYPE_NEWTACHO:   return "new tacho";
	case LMS_TYPE_NXT_IIC:    return "NXT IIC";
	case LMS_TYPE_TERMINAL:   return "terminal";
	case LMS_TYPE_UNKNOWN:    return "unknown (see the connection)";
	case LMS_TYPE_NONE:       return "none";
	case LMS_TYPE_ERROR:      return "error";
	default:                  return "?";
	}
}

static ER check(ER ercd)
{
	if (ercd != E_OK)
		run.api_errors++;
	return ercd;
}

/* Prints what d_analog detected on every port. */
static void print_detection(void)
{
	char dcm[LMS_DCM_READ_SIZE] = { 0 };

	fprintf(run.out, "# what the drivers detect (d_analog through the analog hack)\n");
	for (unsigned p = 0; p < 4; p++) {
		struct analog_input_state st = { 0, 0, 0, 0 };

		if (check(analog_input(p, &st)) != E_OK)
			continue;
		run.in_conn[p] = st.conn;
		run.in_dcm[p] = st.type;
		fprintf(run.out, "in%u  %-10s InConn=%3d %-12s InDcm=%3d %-28s pin1=%4u mV pin6=%4u mV\n",
			p + 1, in_names[run.o.in[p]], st.conn, conn_name(st.conn), st.type,
			type_name(st.type), st.pin1_mv, st.pin6_mv);
	}
	for (unsigned p = 0; p < 4; p++) {
		struct analog_output_state st = { 0, 0, 0 };

		if (check(analog_output(p, &st)) != E_OK)
			continue;
		run.out_conn[p] = st.conn;
		run.out_dcm[p] = st.type;
		fprintf(run.out, "out%c %-10s OutConn=%3d %-12s OutDcm=%3d %-28s pin5=%4u mV\n",
			'A' + p, out_names[run.o.out[p]], st.conn, conn_name(st.conn), st.type,
			type_name(st.type), st.pin5_mv);
	}
	if (analog_dcm_read(dcm, sizeof(dcm)) >= 8)
		fprintf(run.out, "/dev/lms_dcm: in %d %d %d %d, out %d %d %d %d\n", dcm[0], dcm[1], dcm[2],
			dcm[3], dcm[4], dcm[5], dcm[6], dcm[7]);
}

/* The API type of an input device (NONE_SENSOR for those the API does not read). */
static sensor_type_t api_type(enum ev3sim_input_device d)
{
	switch (d) {
	case EV3SIM_IN_TOUCH:      return TOUCH_SENSOR;
	case EV3SIM_IN_GYRO:       return GYRO_SENSOR;
	case EV3SIM_IN_COLOR:      return COLOR_SENSOR;
	case EV3SIM_IN_ULTRASONIC: return ULTRASONIC_SENSOR;
	case EV3SIM_IN_IR:         return INFRARED_SENSOR;
	case EV3SIM_IN_HT_ACCEL:   return HT_NXT_ACCEL_SENSOR;
	case EV3SIM_IN_HT_COLOR:   return HT_NXT_COLOR_SENSOR;
	case EV3SIM_IN_NXT_TEMP:   return NXT_TEMP_SENSOR;
	default:                   return NONE_SENSOR;
	}
}

/* Appends one port's live value to the row. */
static void print_value(unsigned p)
{
	sensor_port_t port = (sensor_port_t)p;
	struct analog_input_state st = { 0, 0, 0, 0 };
	int16_t a = 0;
	uint8_t pct = 0;
	colorid_t color = COLOR_NONE;
	int8_t prox = 0;
	bool pressed = false;
	int16_t axes[3] = { 0, 0, 0 };
	float temp = 0;

	switch (run.o.in[p]) {
	case EV3SIM_IN_TOUCH:
		if (check(ev3lx_touch_sensor_is_pressed(port, &pressed)) == E_OK)
			fprintf(run.out, "  in%u pressed=%d", p + 1, pressed);
		break;
	case EV3SIM_IN_GYRO:
		/* the angle only: reading the rate would switch modes, which restarts the angle */
		if (check(ev3lx_gyro_sensor_get_angle(port, &a)) == E_OK)
			fprintf(run.out, "  in%u angle=%d", p + 1, a);
		break;
	case EV3SIM_IN_COLOR:
		if (check(ev3lx_color_sensor_get_reflect(port, &pct)) == E_OK &&
		    check(ev3lx_color_sensor_get_color(port, &color)) == E_OK)
			fprintf(run.out, "  in%u reflect=%u color=%d", p + 1, pct, (int)color);
		break;
	case EV3SIM_IN_ULTRASONIC:
		if (check(ev3lx_ultrasonic_sensor_get_distance(port, &a)) == E_OK)
			fprintf(run.out, "  in%u cm=%d", p + 1, a);
		break;
	case EV3SIM_IN_IR:
		if (check(ev3lx_infrared_sensor_get_distance(port, &prox)) == E_OK)
			fprintf(run.out, "  in%u prox=%d", p + 1, prox);
		break;
	case EV3SIM_IN_HT_ACCEL:
		if (check(ev3lx_ht_nxt_accel_sensor_measure(port, axes)) == E_OK)
			fprintf(run.out, "  in%u accel=%d,%d,%d", p + 1, axes[0], axes[1], axes[2]);
		break;
	case EV3SIM_IN_HT_COLOR:
		if (check(ev3lx_ht_nxt_color_sensor_measure_color(port, &pct)) == E_OK)
			fprintf(run.out, "  in%u ht_color=%u", p + 1, pct);
		break;
	case EV3SIM_IN_NXT_TEMP:
		if (check(ev3lx_nxt_temp_sensor_measure(port, &temp)) == E_OK)
			fprintf(run.out, "  in%u temp_c=%.4f", p + 1, (double)temp);
		break;
	case EV3SIM_IN_NXT_TOUCH:
	case EV3SIM_IN_NXT_LIGHT:
		if (check(analog_input(p, &st)) == E_OK)
			fprintf(run.out, "  in%u pin1_mv=%u", p + 1, st.pin1_mv);
		break;
	default:
		break;
	}
}

/* The application: detection, configuration, then a row of values per period. */
static void sensors_task(intptr_t exinf)
{
	uint64_t rows = (uint64_t)(run.o.seconds * 1000.0) / run.o.every_ms;
	SYSTIM t0 = 0, now = 0;

	(void)exinf;
	dly_tsk(DETECT_MS);
	print_detection();
	for (unsigned p = 0; p < 4; p++) {
		if (api_type(run.o.in[p]) != NONE_SENSOR)
			check(ev3lx_sensor_config((sensor_port_t)p, api_type(run.o.in[p])));
		if (run.o.out[p] != EV3SIM_OUT_NONE)
			check(ev3lx_motor_config((motor_port_t)p, run.o.out[p] == EV3SIM_OUT_MEDIUM ?
					       MEDIUM_MOTOR : LARGE_MOTOR));
	}
	/* the first read of a UART sensor waits for its handshake */
	fprintf(run.out, "first values:");
	for (unsigned p = 0; p < 4; p++)
		print_value(p);
	fprintf(run.out, "\n# live values through the EV3 API\n");
	get_tim(&t0);
	for (uint64_t k = 0; k <= rows; k++) {
		SYSTIM target = t0 + (SYSTIM)(k * run.o.every_ms);

		get_tim(&now);
		if (target > now)
			dly_tsk((RELTIM)(target - now));
		get_tim(&now);
		fprintf(run.out, "t=%.3f", (double)now / 1000.0);
		for (unsigned p = 0; p < 4; p++)
			print_value(p);
		for (unsigned p = 0; p < 4; p++) {
			int32_t counts = 0;

			if (run.o.out[p] != EV3SIM_OUT_NONE &&
			    check(ev3lx_motor_get_counts((motor_port_t)p, &counts)) == E_OK)
				fprintf(run.out, "  out%c counts=%ld", 'A' + p, (long)counts);
		}
		fputc('\n', run.out);
		run.rows++;
	}
	run.done = true;
}

static void sensors_boot(intptr_t exinf)
{
	(void)exinf;
	ev3sim_quiet_console();
}

static const struct rtos_task_cfg sensors_tasks[] = {
	{ SENSORS_TSKID, TA_ACT, 0, sensors_task, 8, 16 * 1024, APP_DOMAIN, "sensors" },
};
static const struct rtos_ini_cfg sensors_inis[] = { { sensors_boot, 0 } };
static const struct rtos_cfg *const sensors_includes[] = { &ev3api_cfg, NULL };
static const struct rtos_cfg sensors_cfg = {
	.name = "ev3sim_sensors",
	.tasks = RTOS_TABLE(sensors_tasks),
	.inis = RTOS_TABLE(sensors_inis),
	.includes = sensors_includes,
};

/* Event: the touch sensors change state every second. */
static void toggle_touch(void *arg)
{
	(void)arg;
	run.pressed = !run.pressed;
	for (unsigned p = 0; p < 4; p++)
		if (run.o.in[p] == EV3SIM_IN_TOUCH || run.o.in[p] == EV3SIM_IN_NXT_TOUCH)
			ev3_set_touch(p, run.pressed);
	hs_sim_at(rtos_host_now() + TOUCH_TOGGLE_NS, toggle_touch, NULL);
}

/* Plugs in the devices with their scenes. */
static ER plug_in(const struct ev3sim_sensors_opts *o)
{
	static const struct uart_sensor_scene scene = {
		.reflect_pct = 40, .ambient_pct = 10, .color = 5, .rgb = { 200, 60, 40 },
		.distance_mm = 500, .rate_dps = 15.0,
		.beacon_distance = { -128, -128, -128, -128 },
	};
	static const uint8_t uart_type[EV3SIM_IN_COUNT] = {
		[EV3SIM_IN_GYRO] = UART_SENSOR_TYPE_GYRO, [EV3SIM_IN_COLOR] = UART_SENSOR_TYPE_COLOR,
		[EV3SIM_IN_ULTRASONIC] = UART_SENSOR_TYPE_ULTRASONIC, [EV3SIM_IN_IR] = UART_SENSOR_TYPE_IR,
	};
	ER ercd = E_OK;

	for (unsigned p = 0; p < 4 && ercd == E_OK; p++) {
		switch (o->in[p]) {
		case EV3SIM_IN_NONE:
			break;
		case EV3SIM_IN_TOUCH:
			ercd = ev3_attach_analog(p, EV3_INPUT_EV3_TOUCH, NULL);
			break;
		case EV3SIM_IN_NXT_TOUCH:
			ercd = ev3_attach_analog(p, EV3_INPUT_NXT_TOUCH, NULL);
			break;
		case EV3SIM_IN_NXT_LIGHT:
			ercd = ev3_attach_analog(p, EV3_INPUT_NXT_LIGHT, NULL);
			if (ercd == E_OK)
				ercd = ev3_set_light(p, 40);
			break;
		case EV3SIM_IN_HT_ACCEL:
		case EV3SIM_IN_HT_COLOR:
		case EV3SIM_IN_NXT_TEMP:
			ercd = ev3sim_attach_nxt_iic(p, o->in[p]);
			break;
		default:
			ercd = ev3_attach_uart_sensor(p, uart_type[o->in[p]], NULL);
			if (ercd == E_OK)
				ercd = ev3_set_scene(p, &scene);
			break;
		}
		if (ercd == E_OK && o->out[p] != EV3SIM_OUT_NONE)
			ercd = ev3_attach_motor(p, o->out[p] == EV3SIM_OUT_MEDIUM ? HS_MOTOR_MEDIUM :
						HS_MOTOR_LARGE, NULL);
	}
	return ercd;
}

ER ev3sim_sensors_app(const struct ev3sim_sensors_opts *o, FILE *out, char *err, size_t errlen)
{
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	struct hs_scenario scn = { .rtos = &sensors_cfg, .board = &board };
	uint64_t limit;
	double wall0, wall;

	for (unsigned p = 0; p < 4; p++)
		if ((unsigned)o->in[p] >= EV3SIM_IN_COUNT || (unsigned)o->out[p] >= EV3SIM_OUT_COUNT) {
			snprintf(err, errlen, "bad device on port %u", p);
			return E_PAR;
		}
	if (!(o->seconds > 0) || o->seconds > 3600 || o->every_ms == 0) {
		snprintf(err, errlen, "bad sensors options");
		return E_PAR;
	}
	memset(&run, 0, sizeof(run));
	run.o = *o;
	run.out = out;
	scn.seed = o->seed;
	scn.vcd_path = o->trace_path;
	wall0 = ev3sim_wall_seconds();
	if (hs_sim_boot(&scn) != E_OK) {
		snprintf(err, errlen, "boot failed: %s", rtos_host_boot_error());
		return E_SYS;
	}
	if (plug_in(o) != E_OK) {
		hs_sim_shutdown();
		snprintf(err, errlen, "cannot plug the devices in");
		return E_SYS;
	}
	hs_sim_at(TOUCH_TOGGLE_NS, toggle_touch, NULL);
	/* detection, up to 4 s of handshakes, then the rows */
	limit = (uint64_t)(o->seconds * 1e9) + 8000000000ULL;
	while (!run.done && rtos_host_now() < limit && !rtos_host_exited())
		hs_sim_run_for(10000000ULL);
	wall = ev3sim_wall_seconds() - wall0;
	fprintf(out, "in1=%s/%s in2=%s/%s in3=%s/%s in4=%s/%s outA=%s/%s outB=%s/%s outC=%s/%s "
		"outD=%s/%s rows=%u api_errors=%u bugs=%u sim_speed=%.0fx\n",
		in_names[o->in[0]], conn_name(run.in_conn[0]), in_names[o->in[1]], conn_name(run.in_conn[1]),
		in_names[o->in[2]], conn_name(run.in_conn[2]), in_names[o->in[3]], conn_name(run.in_conn[3]),
		out_names[o->out[0]], conn_name(run.out_conn[0]), out_names[o->out[1]],
		conn_name(run.out_conn[1]), out_names[o->out[2]], conn_name(run.out_conn[2]),
		out_names[o->out[3]], conn_name(run.out_conn[3]), run.rows, run.api_errors,
		rtos_host_bug_count(), wall > 0 ? rtos_host_now() * 1e-9 / wall : 0.0);
	if (hs_sim_shutdown() != E_OK) {
		snprintf(err, errlen, "cannot write %s completely", o->trace_path);
		return E_SYS;
	}
	if (!run.done) {
		snprintf(err, errlen, "the application did not finish");
		return E_SYS;
	}
	return E_OK;
}

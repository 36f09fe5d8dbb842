/*
 * brick.c — the EV3 ports: what is plugged in, the electrical level of
 * each pin, the links between UART sensors and their UARTs, the battery,
 * the ADC's analog sources, and seeded fault injection.
 *
 * Pin electrics (docs/host-sim-devices.md): the brick pulls input pin 1 up
 * to 5 V (10 kOhm assumed), so an ID resistor R reads 5 V * R / (R + 10k);
 * pin 2 (LEGDET) and pin 5 are pulled up and pin 6 down when nothing drives
 * them; an unconnected output port reads 2.47 V on pin 5 (pybricks).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <stdio.h>
#include "rtos_host.h"
#include "host_sim/clock.h"
#include "host_sim/gpio.h"
#include "host_sim/rng.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/pwm.h"
#include "host_sim/devices/spi_adc.h"
#include "host_sim/devices/uart16550.h"
#include "host_sim/devices/pru_suart.h"
#include "host_sim/devices/ev3_ui.h"
#include "host_sim/devices/ev3_power.h"
#include "nxt_iic_bus.h"

#define PULLUP_OHMS       10000U
#define EV3_TOUCH_ID_OHMS 2200U
#define NXT_TOUCH_OHMS    2200U     /* pressed: ~0.9 V, d_analog's 850-950 mV touch window */
#define LOGIC_HIGH_MV     3300U
#define OUT_OPEN_PIN5_MV  2470U
#define MAX_FAULT_LOG     256U

struct in_port {
	unsigned index;
	enum ev3_input_kind kind;
	struct ev3_analog_options aopt;
	bool plugged;               /* false while an unplug fault holds it out */
	bool pressed, contact;
	unsigned bounce_left;
	hs_event_t bounce_ev;
	unsigned light_pct;
	struct uart_sensor *sensor;
	bool line_high;             /* the sensor's TX line (pin 6) */
	double p_flip, p_drop, p_dup;
	uint32_t n_flip, n_drop, n_dup;
	struct hs_rng rng;
};

struct out_port {
	struct hs_motor *motor;
	enum hs_motor_kind kind;
	struct hs_motor_options opt;
	bool has_motor;
};

static struct {
	bool ready;
	struct in_port in[EV3_INPUT_PORTS];
	struct out_port out[EV3_OUTPUT_PORTS];
	double adc_noise_mv;
	struct hs_rng adc_rng;
	struct hs_rng fault_rng;
	struct ev3_fault_record log[MAX_FAULT_LOG];
	unsigned nlog;
} brick;

/* ---- battery ---- */

/* Sets the battery voltage; the motors pick it up at once. */
void ev3_set_battery_mv(uint32_t mv)
{
	ev3_battery_store(mv);
	for (unsigned p = 0; p < EV3_OUTPUT_PORTS; p++)
		if (brick.out[p].motor)
			hs_motor_inputs_changed(brick.out[p].motor);
}

/* ---- input pins ---- */

static uint32_t divider_mv(uint32_t ohms)
{
	return (uint32_t)((5000ULL * ohms + (ohms + PULLUP_OHMS) / 2U) / (ohms + PULLUP_OHMS));
}

/* What the pins show: the device, or nothing while it is unplugged. */
static enum ev3_input_kind effective_kind(const struct in_port *p)
{
	return p->plugged ? p->kind : EV3_INPUT_NONE;
}

/* Drives the external side of the port's GPIO pins from the device. */
static void input_apply_pins(struct in_port *p)
{
	const struct ev3_input_pins *pins = &ev3_input_pins[p->index];
	enum hs_pin_ext pin2 = HS_EXT_PULL_UP, pin5 = HS_EXT_PULL_UP, pin6 = HS_EXT_PULL_DOWN;

	switch (effective_kind(p)) {
	case EV3_INPUT_EV3_TOUCH:
		pin6 = p->contact ? HS_EXT_HIGH : HS_EXT_LOW;
		break;
	case EV3_INPUT_NXT_TOUCH:
		pin2 = HS_EXT_LOW;
		break;
	case EV3_INPUT_NXT_LIGHT:
		pin2 = HS_EXT_LOW;
		pin5 = HS_EXT_PULL_DOWN;
		break;
	case EV3_INPUT_UART:
		pin6 = p->line_high ? HS_EXT_HIGH : HS_EXT_LOW;
		break;
	case EV3_INPUT_NXT_IIC:
		/* pins 5 and 6 are the bus: the sensor's pull-ups and its SDA */
		hs_gpio_drive(pins->pin2, HS_EXT_LOW);
		nxt_iic_bus_apply(p->index, true);
		return;
	default:
		break;
	}
	if (p->kind == EV3_INPUT_NXT_IIC)
		nxt_iic_bus_apply(p->index, false);
	hs_gpio_drive(pins->pin2, pin2);
	hs_gpio_drive(pins->pin5, pin5);
	hs_gpio_drive(pins->pin6, pin6);
}

/* Voltage of an input port's pin 1 now: the device's ID resistor or signal. */
static inline uint32_t input_pin1_mv(const struct in_port *p)
{
	switch (effective_kind(p)) {
	case EV3_INPUT_EV3_TOUCH: return divider_mv(EV3_TOUCH_ID_OHMS);
	case EV3_INPUT_NXT_TOUCH: return p->contact ? divider_mv(NXT_TOUCH_OHMS) : 5000U;
	case EV3_INPUT_NXT_LIGHT: return 4500U - 35U * (p->light_pct > 100 ? 100 : p->light_pct);
	case EV3_INPUT_DUMB: return divider_mv(p->aopt.id_ohms);
	case EV3_INPUT_UART: return 0;
	default: return 5000U;
	}
}

/* Voltage of input port port's pin 6 now: the SoC's output if it drives the
 * pin, the EV3 touch sensor's switch, or the pin's logic level. */
static inline uint32_t input_pin6_mv(unsigned port)
{
	bool lvl;
	unsigned pin6 = ev3_input_pins[port].pin6;

	if (!hs_gpio_soc_output_or_level(pin6, &lvl) && effective_kind(&brick.in[port]) == EV3_INPUT_EV3_TOUCH)
		return brick.in[port].contact ? 5000U : 0U;
	return lvl ? LOGIC_HIGH_MV : 0U;
}

/* Voltage of an input pin now. */
uint32_t ev3_input_pin_mv(unsigned port, unsigned pin)
{
	if (port >= EV3_INPUT_PORTS)
		return 0;
	switch (pin) {
	case 1:
		return input_pin1_mv(&brick.in[port]);
	case 2:
		return hs_gpio_level(ev3_input_pins[port].pin2) ? LOGIC_HIGH_MV : 0U;
	case 5:
		return hs_gpio_level(ev3_input_pins[port].pin5) ? LOGIC_HIGH_MV : 0U;
	case 6:
		return input_pin6_mv(port);
	default:
		return 0;
	}
}

/* ---- touch bounce ---- */

static void bounce_due(void *arg)
{
	struct in_port *p = arg;

	p->bounce_ev = 0;
	if (p->bounce_left) {
		p->bounce_left--;
		p->contact = !p->contact;
		if (!p->bounce_left)
			p->contact = p->pressed;
		else
			p->bounce_ev = hs_event_after(100000U + hs_rng_below(&p->rng, p->aopt.bounce_us * 1000U / 4U + 1U),
						      bounce_due, p);
	}
	input_apply_pins(p);
}

/* Touch state, with contact bounce if configured. */
ER ev3_set_touch(unsigned port, bool pressed)
{
	struct in_port *p;

	if (port >= EV3_INPUT_PORTS)
		return E_ID;
	p = &brick.in[port];
	if (p->kind != EV3_INPUT_EV3_TOUCH && p->kind != EV3_INPUT_NXT_TOUCH)
		return E_OBJ;
	if (pressed == p->pressed)
		return E_OK;
	p->pressed = pressed;
	hs_event_cancel(&p->bounce_ev);
	p->contact = pressed;
	if (p->aopt.bounce_us) {
		/* an odd number of extra toggles over about bounce_us, then the final state */
		p->bounce_left = 2U * (1U + hs_rng_below(&p->rng, 3)) + 1U;
		p->bounce_ev = hs_event_after(100000U, bounce_due, p);
	}
	input_apply_pins(p);
	return E_OK;
}

ER ev3_set_light(unsigned port, unsigned pct)
{
	if (port >= EV3_INPUT_PORTS)
		return E_ID;
	if (brick.in[port].kind != EV3_INPUT_NXT_LIGHT || pct > 100)
		return brick.in[port].kind != EV3_INPUT_NXT_LIGHT ? E_OBJ : E_PAR;
	brick.in[port].light_pct = pct;
	return E_OK;
}

/* ---- UART sensor links ---- */

/* The sensor's TX wire reaches the port's UART and, on ports 3 and 4, the
 * McASP pin the PRU soft UART receives on (whichever listens takes it). */
static void deliver_to_uart(struct in_port *p, uint8_t byte, uint32_t baud)
{
	struct hs_uart *u = ev3_input_uart(p->index);

	if (u)
		hs_uart_rx_byte(u, byte, baud);
	if (ev3_port_suart_pins[p->index].rx_ser)
		hs_pru_suart_rx_byte(hs_pru_suart(), ev3_port_suart_pins[p->index].rx_ser, byte, baud);
}

/* Sensor -> UART, through the fault filters. */
static void link_deliver(void *ctx, uint8_t byte, uint32_t baud)
{
	struct in_port *p = ctx;

	if (p->p_drop > 0 && hs_rng_unit(&p->rng) < p->p_drop) {
		p->n_drop++;
		return;
	}
	if (p->p_flip > 0 && hs_rng_unit(&p->rng) < p->p_flip) {
		p->n_flip++;
		byte ^= (uint8_t)(1U << hs_rng_below(&p->rng, 8));
	}
	deliver_to_uart(p, byte, baud);
	if (p->p_dup > 0 && hs_rng_unit(&p->rng) < p->p_dup) {
		p->n_dup++;
		deliver_to_uart(p, byte, baud);
	}
}

/* The sensor's TX line level: pin 6 and the UART's RX line. */
static void link_line(void *ctx, bool high)
{
	struct in_port *p = ctx;
	struct hs_uart *u = ev3_input_uart(p->index);

	p->line_high = high;
	input_apply_pins(p);
	if (u)
		hs_uart_rx_line(u, high);
	if (ev3_port_suart_pins[p->index].rx_ser)
		hs_pru_suart_rx_line(hs_pru_suart(), ev3_port_suart_pins[p->index].rx_ser, high);
}

/* UART -> sensor: only through the port's TX buffer, enabled by driving its GPIO low. */
static void peer_tx_byte(void *ctx, uint8_t byte, uint32_t baud)
{
	struct in_port *p = ctx;
	bool lvl = true;

	if (!p->sensor || !p->plugged)
		return;
	if (!hs_gpio_soc_output(ev3_input_pins[p->index].tx_buffer_off, &lvl) || lvl) {
		rtos_host_trace("ev3_port", "in%u: byte 0x%02x not sent: TX buffer disabled (its GPIO is not driven low)",
				p->index + 1U, byte);
		return;
	}
	uart_sensor_host_byte(p->sensor, byte, baud);
}

/* A byte the PRU soft UART sent on a McASP transmit pin: the port wired to it. */
static void suart_tx_byte(void *ctx, unsigned ser, uint8_t byte, uint32_t baud)
{
	for (unsigned port = 0; port < EV3_INPUT_PORTS; port++)
		if (ev3_port_suart_pins[port].rx_ser && ev3_port_suart_pins[port].tx_ser == ser)
			peer_tx_byte(&brick.in[port], byte, baud);
}

/* The UART's break reaches the sensor's receiver. */
static void peer_tx_break(void *ctx, bool active)
{
	struct in_port *p = ctx;

	if (p->sensor)
		uart_sensor_host_break(p->sensor, active);
}

/* ---- attach / detach ---- */

static void input_clear(struct in_port *p)
{
	struct hs_uart *u = ev3_input_uart(p->index);

	hs_event_cancel(&p->bounce_ev);
	if (p->kind == EV3_INPUT_NXT_IIC)
		nxt_iic_bus_detach(p->index);
	if (p->sensor) {
		uart_sensor_destroy(p->sensor);
		p->sensor = NULL;
	}
	if (u) {
		hs_uart_set_peer(u, NULL);
		hs_uart_rx_line(u, true);
	}
	p->kind = EV3_INPUT_NONE;
	p->pressed = p->contact = false;
	p->line_high = false;
}

ER ev3_attach_analog(unsigned port, enum ev3_input_kind kind, const struct ev3_analog_options *opt)
{
	struct in_port *p;

	if (!brick.ready)
		return E_OBJ;
	if (port >= EV3_INPUT_PORTS)
		return E_ID;
	if (kind > EV3_INPUT_DUMB || (kind == EV3_INPUT_DUMB && (!opt || !opt->id_ohms)))
		return E_PAR;
	p = &brick.in[port];
	input_clear(p);
	p->kind = kind;
	p->plugged = true;
	memset(&p->aopt, 0, sizeof(p->aopt));
	if (opt)
		p->aopt = *opt;
	input_apply_pins(p);
	return E_OK;
}

ER ev3_attach_uart_sensor(unsigned port, uint8_t type, const struct uart_sensor_options *opt)
{
	struct in_port *p;
	struct uart_sensor_options o = { 0 };
	struct uart_sensor_link link;
	struct hs_uart_peer peer;
	struct hs_uart *u;
	static const char *const names[EV3_INPUT_PORTS] = { "in1.sensor", "in2.sensor", "in3.sensor", "in4.sensor" };

	if (!brick.ready)
		return E_OBJ;
	if (port >= EV3_INPUT_PORTS)
		return E_ID;
	if (!uart_sensor_def_for_type(type))
		return E_PAR;
	p = &brick.in[port];
	input_clear(p);
	if (opt)
		o = *opt;
	if (!o.name)
		o.name = names[port];
	link = (struct uart_sensor_link){ link_deliver, link_line, p };
	p->sensor = uart_sensor_create(type, &o, &link);
	if (!p->sensor)
		return E_NOMEM;
	p->kind = EV3_INPUT_UART;
	p->plugged = true;
	u = ev3_input_uart(port);
	if (u) {
		peer = (struct hs_uart_peer){ peer_tx_byte, peer_tx_break, p };
		hs_uart_set_peer(u, &peer);
	}
	uart_sensor_power(p->sensor, true);
	return E_OK;
}

ER ev3_attach_nxt_iic(unsigned port, enum nxt_iic_kind kind, const struct nxt_iic_scene *scene)
{
	struct in_port *p;

	if (!brick.ready)
		return E_OBJ;
	if (port >= EV3_INPUT_PORTS)
		return E_ID;
	if (kind < NXT_IIC_HT_ACCEL || kind > NXT_IIC_US)
		return E_PAR;
	p = &brick.in[port];
	input_clear(p);
	if (!nxt_iic_bus_attach(port, kind, scene))
		return E_NOMEM;
	p->kind = EV3_INPUT_NXT_IIC;
	p->plugged = true;
	input_apply_pins(p);
	return E_OK;
}

ER ev3_detach_input(unsigned port)
{
	if (!brick.ready)
		return E_OBJ;
	if (port >= EV3_INPUT_PORTS)
		return E_ID;
	input_clear(&brick.in[port]);
	input_apply_pins(&brick.in[port]);
	return E_OK;
}

/* Kind of device on an input port. */
enum ev3_input_kind ev3_input_kind_of(unsigned port)
{
	return port < EV3_INPUT_PORTS ? brick.in[port].kind : EV3_INPUT_NONE;
}

/* The UART sensor on an input port, or NULL. */
struct uart_sensor *ev3_input_uart_sensor(unsigned port)
{
	return port < EV3_INPUT_PORTS ? brick.in[port].sensor : NULL;
}

ER ev3_set_scene(unsigned port, const struct uart_sensor_scene *scene)
{
	if (port >= EV3_INPUT_PORTS)
		return E_ID;
	if (!scene)
		return E_PAR;
	if (!brick.in[port].sensor)
		return E_OBJ;
	uart_sensor_set_scene(brick.in[port].sensor, scene);
	return E_OK;
}

/* Unplug (false) or replug (true) what is attached, keeping its identity. */
static void input_plug(struct in_port *p, bool plugged)
{
	p->plugged = plugged;
	if (p->sensor) {
		uart_sensor_power(p->sensor, plugged);
		if (!plugged)
			link_line(p, false);
	}
	input_apply_pins(p);
}

ER ev3_attach_motor(unsigned port, enum hs_motor_kind kind, const struct hs_motor_options *opt)
{
	struct out_port *o;

	if (!brick.ready)
		return E_OBJ;
	if (port >= EV3_OUTPUT_PORTS)
		return E_ID;
	if (!hs_motor_params_of(kind))
		return E_PAR;
	o = &brick.out[port];
	hs_motor_destroy(o->motor);
	o->motor = hs_motor_create(port, kind, opt);
	if (!o->motor)
		return E_NOMEM;
	o->kind = kind;
	o->has_motor = true;
	memset(&o->opt, 0, sizeof(o->opt));
	if (opt)
		o->opt = *opt;
	return E_OK;
}

ER ev3_detach_output(unsigned port)
{
	if (!brick.ready)
		return E_OBJ;
	if (port >= EV3_OUTPUT_PORTS)
		return E_ID;
	hs_motor_destroy(brick.out[port].motor);
	brick.out[port].motor = NULL;
	brick.out[port].has_motor = false;
	return E_OK;
}

/* The motor on an output port, or NULL. */
struct hs_motor *ev3_output_motor(unsigned port)
{
	return port < EV3_OUTPUT_PORTS ? brick.out[port].motor : NULL;
}

/* Pin 5 of an output port now. */
uint32_t ev3_output_pin5_mv(unsigned port)
{
	bool pull_high = false, lvl;

	if (port >= EV3_OUTPUT_PORTS)
		return 0;
	if (hs_gpio_soc_output(ev3_output_pins[port].det_5w, &lvl))
		pull_high = lvl;
	if (brick.out[port].motor)
		return hs_motor_pin5_mv(brick.out[port].motor, pull_high);
	return pull_high ? 5000U : OUT_OPEN_PIN5_MV;
}

/* ---- ADC sources ---- */

/* What an ADC channel measures: pin 1 or 6 of an input port, pin 5 of an
 * output port, or (ADC_BRICK) a brick quantity; port in the low bits. */
enum { ADC_BRICK = 0x00, ADC_IN_PIN1 = 0x10, ADC_IN_PIN6 = 0x20, ADC_OUT_PIN5 = 0x30 };
#define ADC_CHANNELS 16U

/* The source of each ADC channel (ADC_IN_PIN1 | port, ...), built on first use. */
static uint8_t adc_source[ADC_CHANNELS];
static bool adc_source_built;

/* Builds adc_source from the wiring tables (the first port naming a channel
 * wins, input pins before output pins). */
static void adc_sources_build(void)
{
	for (unsigned ch = 0; ch < ADC_CHANNELS; ch++) {
		adc_source[ch] = ADC_BRICK;
		for (unsigned p = EV3_OUTPUT_PORTS; p-- > 0;)
			if (ch == ev3_output_pins[p].adc_pin5)
				adc_source[ch] = (uint8_t)(ADC_OUT_PIN5 | p);
		for (unsigned p = EV3_INPUT_PORTS; p-- > 0;) {
			if (ch == ev3_input_pins[p].adc_pin6)
				adc_source[ch] = (uint8_t)(ADC_IN_PIN6 | p);
			if (ch == ev3_input_pins[p].adc_pin1)
				adc_source[ch] = (uint8_t)(ADC_IN_PIN1 | p);
		}
	}
	adc_source_built = true;
}

/* ev3_adc_channel_source's functions: an input port's pin 1 and pin 6, a
 * brick quantity (battery, motor current, temperature) by channel. */
static uint32_t adc_input_pin1_mv(unsigned port)
{
	return input_pin1_mv(&brick.in[port]);
}

static uint32_t adc_input_pin6_mv(unsigned port)
{
	return input_pin6_mv(port);
}

static uint32_t adc_brick_mv(unsigned ch)
{
	return ev3_power_adc_mv(ch, ch == EV3_ADC_MOTOR_CURRENT || ch == EV3_ADC_BATTERY_CURRENT ||
				     ch == EV3_ADC_BATTERY_VOLTAGE ? ev3_motors_current_a() : 0);
}

/* What an ADC channel measures (LEGO's d_analog.c channel map). */
struct ev3_adc_source ev3_adc_channel_source(unsigned ch)
{
	unsigned src;

	if (!adc_source_built)
		adc_sources_build();
	src = ch < ADC_CHANNELS ? adc_source[ch] : ADC_BRICK;
	switch (src & 0xF0U) {
	case ADC_IN_PIN1:
		return (struct ev3_adc_source){ adc_input_pin1_mv, src & 0xFU };
	case ADC_IN_PIN6:
		return (struct ev3_adc_source){ adc_input_pin6_mv, src & 0xFU };
	case ADC_OUT_PIN5:
		return (struct ev3_adc_source){ ev3_output_pin5_mv, src & 0xFU };
	default:
		return (struct ev3_adc_source){ adc_brick_mv, ch };
	}
}

/* Voltage of an ADC channel. */
uint32_t ev3_adc_channel_mv(unsigned ch)
{
	struct ev3_adc_source src = ev3_adc_channel_source(ch);

	return src.mv(src.arg);
}

/* Sum of the motor currents now, amperes. */
double ev3_motors_current_a(void)
{
	double amps = 0;

	for (unsigned p = 0; p < EV3_OUTPUT_PORTS; p++)
		if (brick.out[p].motor)
			amps += hs_motor_current_a(brick.out[p].motor);
	return amps;
}

/* ADC noise standard deviation now (mV). */
double ev3_adc_noise_mv(void)
{
	return brick.adc_noise_mv;
}

/* Where the ADC noise standard deviation (mV) is kept (read on every ADC frame). */
const double *ev3_adc_noise_mv_ref(void)
{
	return &brick.adc_noise_mv;
}

/* One standard-normal draw from the ADC noise stream. */
double ev3_adc_noise_sample(void)
{
	return hs_rng_gauss(&brick.adc_rng);
}

/* ---- faults ---- */

struct fault_job {
	struct ev3_fault f;
	hs_event_t ev;
	bool started;
	struct fault_job *next;     /* pending jobs, freed at shutdown */
};

static struct fault_job *fault_jobs;

/* Unlinks and frees a fault job. */
static void fault_job_free(struct fault_job *j)
{
	struct fault_job **pp = &fault_jobs;

	while (*pp && *pp != j)
		pp = &(*pp)->next;
	if (*pp)
		*pp = j->next;
	free(j);
}

/* Records and traces a fault start or end. */
static void fault_log(const struct ev3_fault *f, bool start)
{
	if (brick.nlog < MAX_FAULT_LOG)
		brick.log[brick.nlog++] = (struct ev3_fault_record){ hs_now(), f->kind, f->port, start };
	rtos_host_trace("ev3_fault", "%s kind %d port %u value %g", start ? "start" : "end",
			(int)f->kind, f->port, f->value);
}

/* Starts (on) or ends a fault. */
static void fault_apply(const struct ev3_fault *f, bool on)
{
	struct in_port *ip = &brick.in[f->port % EV3_INPUT_PORTS];
	struct out_port *op = &brick.out[f->port % EV3_OUTPUT_PORTS];
	double v = on ? f->value : 0.0;

	switch (f->kind) {
	case EV3_FAULT_UART_BIT_ERRORS: ip->p_flip = v; break;
	case EV3_FAULT_UART_DROP: ip->p_drop = v; break;
	case EV3_FAULT_UART_DUPLICATE: ip->p_dup = v; break;
	case EV3_FAULT_UNPLUG: input_plug(ip, !on); break;
	case EV3_FAULT_MOTOR_UNPLUG:
		if (on) {
			hs_motor_destroy(op->motor);
			op->motor = NULL;
		} else if (op->has_motor && !op->motor) {
			op->motor = hs_motor_create(f->port, op->kind, &op->opt);
		}
		break;
	case EV3_FAULT_ENCODER_STUCK:
		if (op->motor)
			hs_motor_set_encoder_stuck(op->motor, on);
		break;
	case EV3_FAULT_ENCODER_NOISE:
		if (op->motor)
			hs_motor_set_encoder_noise(op->motor, v);
		break;
	case EV3_FAULT_MOTOR_STALL:
		if (op->motor)
			hs_motor_set_stalled(op->motor, on);
		break;
	case EV3_FAULT_ADC_NOISE:
		brick.adc_noise_mv = v;
		break;
	}
}

/* Event: a fault starts, or ends after its duration. */
static void fault_due(void *arg)
{
	struct fault_job *j = arg;

	j->ev = 0;
	if (!brick.ready) {
		fault_job_free(j);
		return;
	}
	if (!j->started) {
		j->started = true;
		fault_apply(&j->f, true);
		fault_log(&j->f, true);
		if (j->f.duration_ns) {
			j->ev = hs_event_after(j->f.duration_ns, fault_due, j);
			return;
		}
	} else {
		fault_apply(&j->f, false);
		fault_log(&j->f, false);
	}
	fault_job_free(j);
}

ER ev3_fault_at(uint64_t t_ns, const struct ev3_fault *f)
{
	struct fault_job *j;
	bool output_kind;

	if (!brick.ready)
		return E_OBJ;
	if (!f || (unsigned)f->kind > EV3_FAULT_ADC_NOISE || f->value < 0 || t_ns < hs_now())
		return E_PAR;
	output_kind = f->kind >= EV3_FAULT_MOTOR_UNPLUG && f->kind <= EV3_FAULT_MOTOR_STALL;
	/* NOLINTNEXTLINE(bugprone-branch-clone): both counts are 4 on the EV3, but they are two things */
	if (f->kind != EV3_FAULT_ADC_NOISE && f->port >= (output_kind ? EV3_OUTPUT_PORTS : EV3_INPUT_PORTS))
		return E_ID;
	if (f->kind <= EV3_FAULT_UART_DUPLICATE && f->value > 1.0)
		return E_PAR;
	j = calloc(1, sizeof(*j));
	if (!j)
		return E_NOMEM;
	j->f = *f;
	j->next = fault_jobs;
	fault_jobs = j;
	j->ev = hs_event_at(t_ns, fault_due, j);
	return E_OK;
}

/* Number of fault log entries. */
unsigned ev3_fault_log_count(void)
{
	return brick.nlog;
}

/* Fault log entry i, or NULL. */
const struct ev3_fault_record *ev3_fault_log(unsigned i)
{
	return i < brick.nlog ? &brick.log[i] : NULL;
}

/* Bytes the UART faults changed on an input port. */
void ev3_fault_uart_counts(unsigned port, uint32_t *flipped, uint32_t *dropped, uint32_t *duplicated)
{
	const struct in_port *p = &brick.in[port % EV3_INPUT_PORTS];

	if (flipped)
		*flipped = p->n_flip;
	if (dropped)
		*dropped = p->n_drop;
	if (duplicated)
		*duplicated = p->n_dup;
}

/* ---- the board device ---- */

static ER ports_create(const struct hs_board_cfg *cfg, void **ctx)
{
	static const char *const rng_names[EV3_INPUT_PORTS] = { "in1.port", "in2.port", "in3.port", "in4.port" };
	static char boot_args[160];

	memset(&brick, 0, sizeof(brick));
	ev3_battery_store(EV3_BATTERY_MV_DEFAULT);
	hs_rng_stream(&brick.adc_rng, "adc.noise");
	hs_rng_stream(&brick.fault_rng, "faults");
	for (unsigned p = 0; p < EV3_INPUT_PORTS; p++) {
		brick.in[p].index = p;
		brick.in[p].plugged = true;
		hs_rng_stream(&brick.in[p].rng, rng_names[p]);
		input_apply_pins(&brick.in[p]);
	}
	/* The firmware command line of this board: d_uart finds the stand-in
	 * UARTs of ports 3 and 4 through it, as a boot loader tells Linux. */
	snprintf(boot_args, sizeof(boot_args),
		 "d_uart.port3_base=%#x d_uart.port3_irq=%u d_uart.port4_base=%#x d_uart.port4_irq=%u",
		 EV3_SUART_PORT3_BASE, EV3_SUART_PORT3_INTNO, EV3_SUART_PORT4_BASE, EV3_SUART_PORT4_INTNO);
	rtos_host_set_boot_args(boot_args);
	hs_pru_suart_set_peer(hs_pru_suart(), &(struct hs_pru_suart_peer){ suart_tx_byte, NULL });
	brick.ready = true;
	*ctx = &brick;
	return E_OK;
}

/* Unplugs everything and cancels pending faults. */
static void ports_destroy(void *ctx)
{
	for (unsigned p = 0; p < EV3_INPUT_PORTS; p++)
		input_clear(&brick.in[p]);
	for (unsigned p = 0; p < EV3_OUTPUT_PORTS; p++) {
		hs_motor_destroy(brick.out[p].motor);
		brick.out[p].motor = NULL;
	}
	while (fault_jobs) {
		hs_event_cancel(&fault_jobs->ev);
		fault_job_free(fault_jobs);
	}
	rtos_host_set_boot_args(NULL);
	hs_pru_suart_set_peer(hs_pru_suart(), NULL);
	brick.ready = false;
}

const struct hs_device ev3_ports_device = { "EV3_PORTS", ports_create, NULL, ports_destroy };

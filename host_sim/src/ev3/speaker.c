/*
 * speaker.c — the EV3's speaker on eHRPWM0 output B and the amplifier
 * enable GP6_15 (ev3_speaker.h).
 *
 * The output is described piecewise: between two changes (a PWM setting,
 * the amplifier) it is a periodic square wave of frequency f that is high
 * for a fraction h of each period from the period's start (or a constant
 * level while the time base is stopped).  Recording integrates that wave
 * exactly over each sample period, so nothing is sampled between changes.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "host_sim/clock.h"
#include "host_sim/gpio.h"
#include "host_sim/devices/pwm.h"
#include "host_sim/devices/ev3_speaker.h"

#define SPEAKER_OUT    HS_PWM_EHRPWM0_B
#define SAMPLE_NS      (1e9 / EV3_SPEAKER_RATE)

static struct {
	bool ready, recording;
	int watch;
	/* the current piece */
	bool amp;
	double freq, high;          /* Hz (0: stopped), fraction high */
	uint64_t t0;                /* the piece's phase origin, ns */
	/* the recording */
	uint64_t rec_t0;            /* start of sample 0, ns */
	uint64_t done_ns;           /* rendered up to here */
	double acc;                 /* high time in the open sample, ns */
	uint64_t total;             /* samples rendered since the start */
	int16_t *buf;               /* the samples not handed to the sink */
	size_t n, cap;
	ev3_speaker_sink_t sink;    /* NULL: the whole recording stays in buf */
	void *sink_ctx;
} spk;

/* High time of the current piece between a and b (ns from its phase origin). */
static double high_ns(double a, double b)
{
	double period;

	if (!spk.amp)
		return 0;
	if (spk.freq <= 0)
		return spk.high * (b - a);
	period = 1e9 / spk.freq;
	{
		double xa = a / period, xb = b / period;
		double ha = floor(xa) * spk.high + fmin(xa - floor(xa), spk.high);
		double hb = floor(xb) * spk.high + fmin(xb - floor(xb), spk.high);

		return (hb - ha) * period;
	}
}

/* Hands the held samples to the sink. */
static void drain(void)
{
	if (spk.sink && spk.n > 0)
		spk.sink(spk.buf, spk.n, spk.sink_ctx);
	spk.n = 0;
}

/* Appends one sample of high ns; false if out of memory. */
static bool push(double high)
{
	if (spk.sink && spk.n == EV3_SPEAKER_RATE)
		drain();
	if (spk.n == spk.cap) {
		size_t cap = spk.cap ? 2 * spk.cap : EV3_SPEAKER_RATE;
		int16_t *b = realloc(spk.buf, cap * sizeof(*b));

		if (!b)
			return false;
		spk.buf = b;
		spk.cap = cap;
	}
	spk.buf[spk.n++] = (int16_t)lround(fmin(fmax(high / SAMPLE_NS, 0), 1) * EV3_SPEAKER_FULL);
	spk.total++;
	return true;
}

/* Renders the current piece up to now. */
static void render(void)
{
	uint64_t now = hs_now();

	while (spk.recording && spk.done_ns < now) {
		uint64_t end = spk.rec_t0 + (uint64_t)llround((double)(spk.total + 1) * SAMPLE_NS);
		uint64_t stop = end < now ? end : now;

		spk.acc += high_ns((double)(spk.done_ns - spk.t0), (double)(stop - spk.t0));
		spk.done_ns = stop;
		if (stop == end) {
			if (!push(spk.acc))
				spk.recording = false;
			spk.acc = 0;
		}
	}
}

/* A change: the old piece is rendered, the new one starts now. */
static void piece_changed(void)
{
	bool level;

	render();
	spk.amp = hs_gpio_soc_output(EV3_SPEAKER_AMP_PIN, &level) && level;
	spk.freq = hs_pwm_frequency(SPEAKER_OUT);
	spk.high = 1.0 - hs_pwm_low_fraction(SPEAKER_OUT);
	spk.t0 = hs_now();
}

static void pwm_changed(void *ctx, enum hs_pwm_output out)
{
	(void)ctx; (void)out;
	piece_changed();
}

static void amp_changed(void *ctx, unsigned pin, const struct hs_pin_state *st)
{
	(void)ctx; (void)pin; (void)st;
	piece_changed();
}

ER ev3_speaker_record_to(ev3_speaker_sink_t sink, void *ctx)
{
	if (!spk.ready)
		return E_OBJ;
	render();
	drain();
	spk.n = 0;
	spk.total = 0;
	spk.acc = 0;
	spk.sink = sink;
	spk.sink_ctx = ctx;
	spk.rec_t0 = spk.done_ns = hs_now();
	spk.recording = true;
	return E_OK;
}

ER ev3_speaker_record(void)
{
	return ev3_speaker_record_to(NULL, NULL);
}

void ev3_speaker_flush(void)
{
	render();
	drain();
}

size_t ev3_speaker_samples(const int16_t **samples)
{
	render();
	*samples = spk.buf;
	return spk.n;
}

bool ev3_speaker_amp_on(void)
{
	return spk.amp;
}

static ER speaker_create(const struct hs_board_cfg *cfg, void **ctx)
{
	free(spk.buf);
	memset(&spk, 0, sizeof(spk));
	if (!(cfg && cfg->cold_reset))
		hs_gpio_mux_as_gpio(EV3_SPEAKER_AMP_PIN);     /* the board code's pin setup */
	spk.watch = hs_gpio_watch(EV3_SPEAKER_AMP_PIN, amp_changed, NULL);
	if (!spk.watch)
		return E_NOMEM;
	hs_pwm_connect(SPEAKER_OUT, &(struct hs_pwm_peer){ pwm_changed, NULL });
	spk.ready = true;
	*ctx = &spk;
	return E_OK;
}

static void speaker_destroy(void *ctx)
{
	(void)ctx;
	hs_gpio_unwatch(spk.watch);
	hs_pwm_connect(SPEAKER_OUT, NULL);
	spk.ready = spk.recording = false;
	spk.sink = NULL;
}

const struct hs_device ev3_speaker_device = { "EV3_SPEAKER", speaker_create, NULL, speaker_destroy };

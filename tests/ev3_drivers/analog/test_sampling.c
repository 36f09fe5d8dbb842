/*
 * test_sampling.c — d_analog's ADC schedule on the register trace: every
 * millisecond ten SPIDAT0 frames in three bursts 200, 600 and 200 us apart,
 * the burst starts never drifting against the 1 ms grid over 10 s; pin 1 and
 * pin 6 of every port logged once per millisecond (10 000 samples in 10 s),
 * the other eight channels every 8 ms, nothing lost to SPI timeouts.
 */
#include "analog_test.h"

#define US		1000ULL
#define WINDOW_START	(1000 * MS)
#define WINDOW_END	(11000 * MS)

static FILE *reglog;
static unsigned samples_logged;

static void sampling_body(void)
{
	const volatile struct lms_analog *shm = analog_shm();
	unsigned last, i;
	char text[1024];
	ER_UINT n;

	ev3_attach_analog(0, EV3_INPUT_EV3_TOUCH, NULL);
	dly_tsk((RELTIM)(WINDOW_START / MS));
	last = shm->actual[0];
	for (i = 0; i < 100; i++) {
		dly_tsk(100);
		samples_logged += (shm->actual[0] + LMS_ANALOG_LOG_SIZE - last) % LMS_ANALOG_LOG_SIZE;
		last = shm->actual[0];
	}
	n = analog_text(text, sizeof(text) - 1);
	ok(n > 0, "text dump read (%d bytes)", (int)n);
	text[n > 0 ? n : 0] = 0;
	ok(strstr(text, "spi_timeouts 0") != NULL, "no SPI timeouts");
	ok(strstr(text, "late_bursts 0") != NULL, "no late bursts");
}

#define MAX_BURSTS 40000

static uint64_t starts[MAX_BURSTS];
static unsigned lens[MAX_BURSTS];

int main(void)
{
	static const unsigned want_len[3] = { 4, 4, 2 };
	static const uint64_t offset_us[3] = { 0, 200, 800 };
	int64_t min_off = INT64_MAX, max_off = INT64_MIN, early_sum = 0, late_sum = 0;
	char line[200];
	uint64_t t, last = 0;
	unsigned frames = 0, nb = 0, c, i, bad_len = 0, cycles = 0;

	tap_plan(11);
	reglog = tmpfile();
	analog_test_reglog(reglog, "SPI0");
	ok(analog_test_run(sampling_body, 5, 12000), "the test body ran to its end");
	in_range(samples_logged, 9999, 10001, "10 s logged %u pin samples per port", samples_logged);

	rewind(reglog);
	while (fgets(line, sizeof(line), reglog) && nb < MAX_BURSTS) {
		if (!strstr(line, "W4 SPI0.SPIDAT0") || sscanf(line, "%" SCNu64, &t) != 1 ||
		    t < WINDOW_START || t >= WINDOW_END)
			continue;
		frames++;
		if (nb && t - last < 100 * US) {
			lens[nb - 1]++;
		} else {
			starts[nb] = t;
			lens[nb++] = 1;
		}
		last = t;
	}
	fclose(reglog);
	in_range(frames, 99990, 100010, "10 SPI frames per ms over 10 s (%u)", frames);
	in_range(nb, 29997, 30003, "3 bursts per ms (%u)", nb);

	/* The cycle starts after the 2-frame burst; burst k of cycle n is due at
	 * n ms + 0, 200 or 800 us after the first cycle, never before, a timer
	 * latency after (the same whether the cycle is the first or the 10 000th). */
	for (c = 0; c < 3 && lens[c] != 2; c++)
		;
	c++;
	for (i = c; i < nb; i++) {
		unsigned k = (i - c) % 3, n = (i - c) / 3;
		int64_t off = (int64_t)(starts[i] - starts[c]) - (int64_t)(n * 1000 * US + offset_us[k] * US);

		bad_len += lens[i] != want_len[k] && i + 1 < nb;
		min_off = off < min_off ? off : min_off;
		max_off = off > max_off ? off : max_off;
		if (n < 100)
			early_sum += off;
		else if (n >= 9890 && n < 9990)
			late_sum += off;
		cycles = n + 1;
	}
	in_range(cycles, 9990, 10001, "%u cycles analysed", cycles);
	is_int(bad_len, 0, "bursts of 4, 4 and 2 frames");
	ok(min_off >= 0 && max_off < 20000,
	   "bursts start 0, 200 and 800 us into each ms, late by %lld..%lld ns", (long long)min_off,
	   (long long)max_off);
	ok(late_sum - early_sum < 100 * 1000 && early_sum - late_sum < 100 * 1000,
	   "no drift: mean lateness %lld ns in the first 100 cycles, %lld ns 9.9 s later",
	   (long long)(early_sum / 300), (long long)(late_sum / 300));
	return tap_done();
}

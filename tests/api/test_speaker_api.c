/*
 * test_speaker_api.c — EV3RT's speaker calls end to end: application task
 * -> ev3api -> sound_hack -> d_sound -> simulated eHRPWM0 and amplifier ->
 * the speaker model's recording: a note's pitch and length, the volume as
 * the duty, SOUND_MANUAL_STOP until ev3_speaker_stop, a zero duration, and
 * non-task context refused; play_file of an 8 kHz 8-bit WAV (levels, end,
 * a duration, bad formats).
 */
#include <string.h>
#include "api_test.h"
#include "host_sim/devices/ev3_speaker.h"

static ER irq_ercd = E_OK;

static void from_irq(void *arg)
{
	(void)arg;
	irq_ercd = ev3_speaker_stop();
}

/* Rising edges through half scale in s[from..n): their count, first and last index. */
static size_t edges(const int16_t *s, size_t n, size_t *first, size_t *last)
{
	size_t count = 0;

	for (size_t i = 1; i < n; i++)
		if (s[i - 1] < EV3_SPEAKER_FULL / 2 && s[i] >= EV3_SPEAKER_FULL / 2) {
			if (!count++)
				*first = i;
			*last = i;
		}
	return count;
}

static void body(void)
{
	const int16_t *s;
	size_t n, e, first = 0, last = 0;
	double high_ms = 0;
	double freq;

	ev3_speaker_record();
	is_int(ev3_speaker_set_volume(60), E_OK, "volume 60");
	is_int(ev3_speaker_play_tone((uint16_t)NOTE_A4, 300), E_OK, "A4 for 300 ms");
	ok(ev3_speaker_amp_on(), "the amplifier is on at once (the call does not block)");
	dly_tsk(400);
	ok(!ev3_speaker_amp_on(), "off after the note");
	n = ev3_speaker_samples(&s);
	e = edges(s, n, &first, &last);
	freq = (double)(e - 1) * EV3_SPEAKER_RATE / (double)(last - first);
	in_range(freq, 439.5, 440.8, "pitch %.2f Hz", freq);
	for (size_t i = 0; i < n; i++)
		high_ms += (double)s[i] / EV3_SPEAKER_FULL / EV3_SPEAKER_RATE * 1000.0;
	/* volume 60: 30 % duty, so the wave is high 30 % of the 300 ms */
	in_range(high_ms, 0.3 * 300 - 1, 0.3 * 300 + 1, "high 30 %% of 300 ms: the volume is the duty (%.2f ms)", high_ms);

	is_int(ev3_speaker_play_tone(1000, SOUND_MANUAL_STOP), E_OK, "1 kHz until stopped");
	dly_tsk(2000);
	ok(ev3_speaker_amp_on(), "still playing after 2 s");
	hs_sim_at(rtos_host_now() + AT_MS, from_irq, NULL);
	dly_tsk(2);
	is_int(irq_ercd, E_CTX, "stop from an interrupt handler: E_CTX");
	ok(ev3_speaker_amp_on(), "and the tone goes on");
	is_int(ev3_speaker_stop(), E_OK, "stop");
	ok(!ev3_speaker_amp_on(), "silent");
	is_int(ev3_speaker_play_tone(1000, 0), E_OK, "duration 0");
	ok(!ev3_speaker_amp_on(), "plays nothing");
}

static void put32(uint8_t *p, uint32_t v)
{
	for (int i = 0; i < 4; i++)
		p[i] = (uint8_t)(v >> (8 * i));
}

/* An 8 kHz 8-bit mono WAV: 800 samples of 60, then 800 of 180 (200 ms). */
static uint32_t make_wav(uint8_t *w, unsigned bits)
{
	static const uint8_t fmt[16] = { 1, 0, 1, 0, 0x40, 0x1F, 0, 0, 0x40, 0x1F, 0, 0, 1, 0, 8, 0 };

	memcpy(w, "RIFF", 4);
	put32(w + 4, 36 + 1600);
	memcpy(w + 8, "WAVEfmt ", 8);
	put32(w + 16, 16);
	memcpy(w + 20, fmt, 16);
	w[34] = (uint8_t)bits;
	memcpy(w + 36, "data", 4);
	put32(w + 40, 1600);
	memset(w + 44, 60, 800);
	memset(w + 44 + 800, 180, 800);
	return 44 + 1600;
}

static void play_file(void)
{
	uint8_t wav[44 + 1600];     /* on the stack: the application's own memory */
	memfile_t mf = { wav, make_wav(wav, 8), sizeof(wav) };
	const int16_t *s;
	size_t n, first = 0, last = 0;
	double lo = 0, hi = 0;
	unsigned nlo = 0, nhi = 0;

	ev3_speaker_record();
	is_int(ev3_speaker_set_volume(10), E_OK, "volume 10");
	is_int(ev3_speaker_play_file(&mf, SOUND_MANUAL_STOP), E_OK, "play_file of a 200 ms WAV to its end");
	dly_tsk(300);
	ok(!ev3_speaker_amp_on(), "silent after the file");
	n = ev3_speaker_samples(&s);
	for (size_t i = 0; i < n; i++)
		if (s[i]) {
			if (!first)
				first = i;
			last = i;
		}
	in_range((double)(last + 1 - first) * 1000.0 / EV3_SPEAKER_RATE, 199.0, 201.0, "played 200 ms");
	for (size_t i = first; i <= last; i++) {
		double t = (double)(i - first) * 1000.0 / EV3_SPEAKER_RATE;

		if (t > 2 && t < 98) {
			lo += s[i];
			nlo++;
		} else if (t > 102 && t < 198) {
			hi += s[i];
			nhi++;
		}
	}
	in_range(lo / nlo, 10.0 * 60 / 2063 * EV3_SPEAKER_FULL * 0.98, 10.0 * 60 / 2063 * EV3_SPEAKER_FULL * 1.02,
		 "first 100 ms: duty 10 x 60 / 2063");
	in_range(hi / nhi, 10.0 * 180 / 2063 * EV3_SPEAKER_FULL * 0.98, 10.0 * 180 / 2063 * EV3_SPEAKER_FULL * 1.02,
		 "last 100 ms: duty 10 x 180 / 2063");

	ev3_speaker_record();
	is_int(ev3_speaker_play_file(&mf, 50), E_OK, "the same file for 50 ms");
	dly_tsk(150);
	n = ev3_speaker_samples(&s);
	first = last = 0;
	for (size_t i = 0; i < n; i++)
		if (s[i]) {
			if (!first)
				first = i;
			last = i;
		}
	in_range((double)(last + 1 - first) * 1000.0 / EV3_SPEAKER_RATE, 49.0, 51.0, "played 50 ms");

	make_wav(wav, 16);
	is_int(ev3_speaker_play_file(&mf, SOUND_MANUAL_STOP), E_NOSPT, "16-bit samples: E_NOSPT");
	memcpy(wav, "RIFX", 4);
	is_int(ev3_speaker_play_file(&mf, SOUND_MANUAL_STOP), E_PAR, "not a RIFF file: E_PAR");
	is_int(ev3_speaker_play_file(NULL, 10), E_PAR, "no file: E_PAR");
}

/* What a streamed recording's sink was handed. */
static struct {
	uint64_t samples, high;     /* samples, and the sum of their levels */
	size_t largest;             /* the largest block */
} streamed;

static void count_sink(const int16_t *s, size_t n, void *ctx)
{
	(void)ctx;
	streamed.samples += n;
	if (n > streamed.largest)
		streamed.largest = n;
	for (size_t i = 0; i < n; i++)
		streamed.high += (uint64_t)s[i];
}

/* A streamed recording: a second at a time to the sink while the tone plays, a second at most held. */
static void stream(void)
{
	const int16_t *s;
	size_t held;

	memset(&streamed, 0, sizeof(streamed));
	is_int(ev3_speaker_record_to(count_sink, NULL), E_OK, "a streamed recording");
	is_int(ev3_speaker_set_volume(60), E_OK, "volume 60");
	is_int(ev3_speaker_play_tone(1000, SOUND_MANUAL_STOP), E_OK, "1 kHz until stopped");
	dly_tsk(3500);
	held = ev3_speaker_samples(&s);
	ok(streamed.samples >= 3 * EV3_SPEAKER_RATE && streamed.largest <= EV3_SPEAKER_RATE,
	   "after 3.5 s the sink had 3 s in blocks of at most a second (%llu samples, largest block %zu)",
	   (unsigned long long)streamed.samples, streamed.largest);
	ok(held < EV3_SPEAKER_RATE, "and only the unfinished second is held (%zu samples)", held);
	is_int(ev3_speaker_stop(), E_OK, "stopped");
	ev3_speaker_flush();
	in_range((double)streamed.samples, 3.5 * EV3_SPEAKER_RATE, 3.5 * EV3_SPEAKER_RATE + 32,
		 "the flush hands over the rest: 3.5 s (%llu samples)", (unsigned long long)streamed.samples);
	/* volume 60: 30 % duty over the 3.5 s the tone played */
	in_range((double)streamed.high / EV3_SPEAKER_FULL / EV3_SPEAKER_RATE, 0.3 * 3.5 * 0.99, 0.3 * 3.5 * 1.01,
		 "the levels: 30 %% high for 3.5 s");
	is_int(ev3_speaker_samples(&s), 0, "nothing held after the flush");
	(void)ev3_speaker_record();
}

int main(void)
{
	tap_plan(27 + 10);
	ok(at_run(NULL, body, 17, 10), "the application finished");
	ok(at_run(NULL, play_file, 18, 10), "the play_file application finished");
	ok(at_run(NULL, stream, 9, 10), "the streaming application finished");
	return tap_done();
}

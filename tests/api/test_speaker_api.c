/*
 * test_speaker_api.c — EV3RT's speaker calls end to end: application task
 * -> ev3api -> sound_hack -> d_sound -> simulated eHRPWM0 and amplifier ->
 * the speaker model's recording: a note's pitch and length, the volume as
 * the duty, SOUND_MANUAL_STOP until ev3_speaker_stop, a zero duration, and
 * non-task context refused.
 */
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

int main(void)
{
	tap_plan(15);
	ok(at_run(NULL, body, 17, 10), "the application finished");
	return tap_done();
}

/*
 * test_sound.c — d_sound through sound_hack on host_sim's eHRPWM0 and
 * speaker: a 440 Hz tone's frequency and duration measured from what the
 * speaker played, the status byte, a tone until BREAK, PCM playback's
 * pace, levels and end (three slots, a full slot refused), the text read()
 * and bad commands refused.
 */
#include <linux/fcntl.h>
#include <linux/errno.h>
#include <linux_compat/devfs.h>
#include "tap.h"
#include "rtos_host.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/ev3_speaker.h"
#include <linux_compat/config.h>
#include "sound_hack.h"

#define MS        1000000ULL
#define RATE      ((double)EV3_SPEAKER_RATE)
#define PCM_PRD   (132000000 / 64000 + 1)	/* the PCM carrier's period in counts */

static bool done;

/* First and last non-silent sample from index from, or false. */
static bool span(const int16_t *s, size_t n, size_t from, size_t *first, size_t *last)
{
	size_t i;

	for (i = from; i < n && s[i] == 0; i++)
		;
	if (i == n)
		return false;
	*first = i;
	for (*last = i; i < n; i++)
		if (s[i])
			*last = i;
	return true;
}

static void tone(void)
{
	uint8_t cmd[6] = { LMS_SOUND_TONE, 50, 440 & 0xFF, 440 >> 8, 500 & 0xFF, 500 >> 8 };
	const int16_t *s;
	size_t n, first, last, edges = 0, e0 = 0, e1 = 0;
	double freq, dur_ms;
	int peak = 0;

	is_int(ev3_speaker_record(), E_OK, "recording");
	dly_tsk(10);
	is_int(sound_svc_write(cmd, sizeof(cmd)), 0, "TONE 440 Hz, level 50, 500 ms: write() returns 0");
	is_int(sound_svc_status(), LMS_SOUND_BUSY, "status BUSY");
	ok(ev3_speaker_amp_on(), "amplifier on");
	dly_tsk(600);
	is_int(sound_svc_status(), LMS_SOUND_OK, "status OK after the tone");
	ok(!ev3_speaker_amp_on(), "amplifier off");
	n = ev3_speaker_samples(&s);
	if (!span(s, n, 0, &first, &last)) {
		ok(0, "the speaker played nothing");
		return;
	}
	dur_ms = (double)(last + 1 - first) / RATE * 1000.0;
	in_range(dur_ms, 499.5, 500.5, "the tone lasted 500 ms (%.3f ms)", dur_ms);
	for (size_t i = first + 1; i <= last; i++) {
		if (s[i] > peak)
			peak = s[i];
		if (s[i - 1] < EV3_SPEAKER_FULL / 2 && s[i] >= EV3_SPEAKER_FULL / 2) {
			if (!edges++)
				e0 = i;
			e1 = i;
		}
	}
	freq = (double)(edges - 1) / ((double)(e1 - e0) / RATE);
	in_range(freq, 439.5, 440.8, "frequency from the rising edges: %.2f Hz (1031250 / 2343 = 440.14)", freq);
	in_range(edges, 219, 221, "220 periods in 500 ms (%zu)", edges);
	is_int(peak, EV3_SPEAKER_FULL, "a square wave: the output fully high between edges");
}

static void tone_until_break(void)
{
	uint8_t cmd[6] = { LMS_SOUND_TONE, 200, 0x10, 0x27, 0, 0 };	/* level clamped, 10 kHz */
	uint8_t brk = LMS_SOUND_BREAK;

	is_int(sound_svc_write(cmd, sizeof(cmd)), 0, "TONE with duration 0");
	dly_tsk(1000);
	ok(ev3_speaker_amp_on() && sound_svc_status() == LMS_SOUND_BUSY, "still playing after 1 s");
	is_int(sound_svc_write(&brk, 1), 0, "BREAK");
	ok(!ev3_speaker_amp_on() && sound_svc_status() == LMS_SOUND_OK, "stopped, status OK");
}

static void pcm(void)
{
	static uint8_t chunk[1 + LMS_SOUND_SLOT_SAMPLES];
	uint8_t play[2] = { LMS_SOUND_PLAY, 8 };
	const int16_t *s;
	size_t n, first, last, step = 0;
	double dur_ms, lo = 0, hi = 0, lo_want, hi_want;
	unsigned nlo = 0, nhi = 0;
	uint64_t t0;

	is_int(ev3_speaker_record(), E_OK, "recording again");
	dly_tsk(5);
	is_int(sound_svc_write(play, 2), 2, "PLAY level 8: write() returns 2");
	t0 = rtos_host_now();
	chunk[0] = LMS_SOUND_SERVICE;
	for (unsigned k = 0; k < 3; k++) {
		for (unsigned i = 1; i <= LMS_SOUND_SLOT_SAMPLES; i++)
			chunk[i] = (uint8_t)((k * LMS_SOUND_SLOT_SAMPLES + i - 1) < 378 ? 50 : 200);
		is_int(sound_svc_write(chunk, sizeof(chunk)), LMS_SOUND_SLOT_SAMPLES, "SERVICE slot %u: 252 samples", k);
	}
	is_int(sound_svc_write(chunk, sizeof(chunk)), 0, "a fourth SERVICE: 0, every slot full");
	while (sound_svc_status() == LMS_SOUND_BUSY && rtos_host_now() - t0 < 200 * MS)
		dly_tsk(1);
	is_int(sound_svc_status(), LMS_SOUND_OK, "status OK: the samples ran dry");
	ok(!ev3_speaker_amp_on(), "amplifier off at the underrun");
	n = ev3_speaker_samples(&s);
	if (!span(s, n, 0, &first, &last)) {
		ok(0, "the speaker played nothing");
		return;
	}
	dur_ms = (double)(last + 1 - first) / RATE * 1000.0;
	in_range(dur_ms, 94.0, 95.0, "756 samples at 8 kHz: 94.5 ms (%.3f ms)", dur_ms);
	lo_want = 8.0 * 50 / PCM_PRD * EV3_SPEAKER_FULL;
	hi_want = 8.0 * 200 / PCM_PRD * EV3_SPEAKER_FULL;
	for (size_t i = first; i <= last; i++) {
		double t_ms = (double)(i - first) / RATE * 1000.0;

		if (!step && s[i] > (lo_want + hi_want) / 2)
			step = i;
		if (t_ms > 1 && t_ms < 46) {
			lo += s[i];
			nlo++;
		} else if (t_ms > 49 && t_ms < 93) {
			hi += s[i];
			nhi++;
		}
	}
	in_range(lo / nlo, lo_want * 0.98, lo_want * 1.02, "first half: duty 8 x 50 / 2063 (%.0f)", lo / nlo);
	in_range(hi / nhi, hi_want * 0.98, hi_want * 1.02, "second half: duty 8 x 200 / 2063 (%.0f)", hi / nhi);
	in_range((double)(step - first) / RATE * 1000.0, 47.0, 47.6,
		 "sample 378 plays at 47.25 ms, never early");
}

static void file_operations(void)
{
	char buf[16] = "";
	uint8_t bad[1] = { 9 }, short_tone[3] = { LMS_SOUND_TONE, 1, 2 };
	struct file *f;
	loff_t pos = 0;

	if (lx_dev_open("/dev/" LMS_SOUND_DEVICE_NAME, O_RDWR, &f))
		tap_bail_out("cannot open /dev/lms_sound");
	is_int(lx_dev_read(f, buf, sizeof(buf), &pos), 10, "read: 10 characters");
	ok(memcmp(buf, "lms_sound\r", 10) == 0, "\"lms_sound\\r\"");
	is_int(lx_dev_write(f, (const char *)bad, 1, NULL), -EINVAL, "command 9: -EINVAL");
	is_int(lx_dev_write(f, (const char *)short_tone, 3, NULL), -EINVAL, "a 3-byte TONE: -EINVAL");
	is_int(lx_dev_write(f, NULL, 1, NULL), -EFAULT, "from NULL: -EFAULT");
	lx_dev_close(f);
	is_int(sound_svc_write(bad, 0), E_PAR, "service call: empty command E_PAR");
	is_int(sound_svc_write(bad, SOUND_MAX_COMMAND + 1), E_PAR, "too long: E_PAR");
	is_int(sound_svc_write(bad, 1), E_PAR, "refused by the driver: E_PAR");
	is_int(sound_svc_status(), LMS_SOUND_OK, "status unchanged");
}

static void task(intptr_t exinf)
{
	(void)exinf;
	tone();
	tone_until_break();
	pcm();
	file_operations();
	done = true;
}

int main(void)
{
	static const struct rtos_task_cfg tasks[] = {
		{ 1, TA_ACT, 0, task, 8, 64 * 1024, TDOM_KERNEL, "sound_test" },
	};
	static const struct rtos_cfg *const includes[] = { &linux_compat_cfg, &sound_hack_cfg, NULL };
	static const struct rtos_cfg cfg = {
		.name = "sound_test", .tasks = tasks, .ntasks = 1, .includes = includes,
	};
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	struct hs_scenario scn = { .rtos = &cfg, .board = &board, .seed = 13 };

	tap_plan(36);
	if (hs_sim_boot(&scn) != E_OK) {
		tap_diag("boot failed: %s", rtos_host_boot_error());
		tap_bail_out("no brick");
	}
	for (unsigned i = 0; !done && i < 100; i++)
		hs_sim_run_for(100 * MS);
	ok(done, "the test task finished");
	hs_sim_shutdown();
	return tap_done();
}

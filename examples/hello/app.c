/*
 * app.c — hello: the brick says hello with what ev3lx provides so far: it
 * plays a short tune (A4, C#5, E5, then A5 held until stopped) and logs the
 * battery's voltage and current before and during the tune.
 */
#include "ev3api.h"
#include "app.h"
#include "kernel_cfg.h"

static const struct { uint16_t hz; int32_t ms; } tune[] = {
	{ (uint16_t)NOTE_A4, 200 }, { (uint16_t)NOTE_CS5, 200 }, { (uint16_t)NOTE_E5, 200 },
};

void main_task(intptr_t exinf)
{
	tslp_tsk(100);      /* the analog driver's first battery samples */
	syslog(LOG_NOTICE, "hello: battery %d mV, %d mA", ev3_battery_voltage_mV(),
	       ev3_battery_current_mA());
	ev3_speaker_set_volume(50);
	for (unsigned i = 0; i < sizeof(tune) / sizeof(tune[0]); i++) {
		ev3_speaker_play_tone(tune[i].hz, tune[i].ms);
		tslp_tsk(tune[i].ms + 50);      /* the note, then a short rest */
	}
	ev3_speaker_play_tone((uint16_t)NOTE_A5, SOUND_MANUAL_STOP);
	tslp_tsk(400);
	ev3_speaker_stop();
	syslog(LOG_NOTICE, "hello: tune played, battery %d mV", ev3_battery_voltage_mV());
}

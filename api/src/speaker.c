/*
 * speaker.c — EV3RT's speaker calls over d_sound (ev3api_speaker.h): each is
 * one command written through sound_hack (LEGO's TONE and BREAK).
 */
#include "ev3api.h"
#include "api_internal.h"
#include "sound_hack.h"

#define DEFAULT_VOLUME   10     /* EV3RT's */
#define MAX_TONE_MS      0xFFFF /* the TONE command's 16-bit duration */

static uint8_t volume;

void api_speaker_boot(void)
{
	volume = DEFAULT_VOLUME;
}

ER ev3_speaker_set_volume(uint8_t vol)
{
	volume = vol > LMS_SOUND_MAX_LEVEL ? LMS_SOUND_MAX_LEVEL : vol;
	return E_OK;
}

ER ev3_speaker_play_tone(uint16_t frequency, int32_t duration)
{
	uint16_t ms = duration < 0 ? 0 : duration > MAX_TONE_MS ? MAX_TONE_MS : (uint16_t)duration;
	uint8_t cmd[6] = {
		LMS_SOUND_TONE, volume, (uint8_t)frequency, (uint8_t)(frequency >> 8),
		(uint8_t)ms, (uint8_t)(ms >> 8),
	};
	ER_UINT ret;

	if (duration == 0)
		return E_OK;
	ret = sound_svc_write(cmd, sizeof(cmd));
	return ret < 0 ? (ER)ret : E_OK;
}

ER ev3_speaker_stop(void)
{
	const uint8_t cmd[1] = { LMS_SOUND_BREAK };
	ER_UINT ret = sound_svc_write(cmd, sizeof(cmd));

	return ret < 0 ? (ER)ret : E_OK;
}

/*
 * speaker.c — EV3RT's speaker calls over d_sound (ev3api_speaker.h): each is
 * one command written through sound_hack (LEGO's TONE and BREAK); a WAV
 * file's samples go to sound_hack's PCM feeder.
 */
#include <string.h>
#include "ev3api_fs.h"
#include "ev3api_lcd.h"
#include "ev3api_speaker.h"
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

/* Little-endian fields of a RIFF header. */
static uint32_t le32(const uint8_t *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static uint16_t le16(const uint8_t *p)
{
	return (uint16_t)(p[0] | p[1] << 8);
}

/* Finds the samples of an 8 kHz 8-bit mono PCM WAV: E_OK, E_PAR (not a WAV), E_NOSPT (another format). */
static ER wav_samples(const uint8_t *wav, uint32_t size, const uint8_t **data, uint32_t *len)
{
	bool fmt_ok = false;
	uint32_t pos = 12;

	if (size < 12 || memcmp(wav, "RIFF", 4) != 0 || memcmp(wav + 8, "WAVE", 4) != 0)
		return E_PAR;
	while (pos + 8 <= size) {
		uint32_t chunk = le32(wav + pos + 4);
		const uint8_t *body = wav + pos + 8;

		if (chunk > size - pos - 8)
			return E_PAR;
		if (memcmp(wav + pos, "fmt ", 4) == 0) {
			if (chunk < 16)
				return E_PAR;
			if (le16(body) != 1 || le16(body + 2) != 1 || le32(body + 4) != LMS_SOUND_RATE ||
			    le16(body + 14) != 8)
				return E_NOSPT;
			fmt_ok = true;
		} else if (memcmp(wav + pos, "data", 4) == 0) {
			if (!fmt_ok)
				return E_PAR;
			*data = body;
			*len = chunk;
			return E_OK;
		}
		pos += 8 + chunk + (chunk & 1);
	}
	return E_PAR;
}

ER ev3_speaker_play_file(const memfile_t *file, int32_t duration)
{
	const uint8_t *data;
	uint32_t len;
	ER ercd;

	if (file == NULL || file->buffer == NULL)
		return E_PAR;
	if (!sns_ctx() && prb_mem(file, sizeof(*file), TSK_SELF, TPM_READ) != E_OK)
		return E_MACV;
	if (!sns_ctx() && prb_mem(file->buffer, file->filesz, TSK_SELF, TPM_READ) != E_OK)
		return E_MACV;
	ercd = wav_samples(file->buffer, file->filesz, &data, &len);
	if (ercd != E_OK)
		return ercd;
	if (duration == 0 || len == 0)
		return E_OK;
	if (duration > 0 && (uint64_t)duration * LMS_SOUND_RATE / 1000U < len)
		len = (uint32_t)((uint64_t)duration * LMS_SOUND_RATE / 1000U);
	return sound_svc_play_pcm(data, len, volume);
}

ER ev3_speaker_stop(void)
{
	const uint8_t cmd[1] = { LMS_SOUND_BREAK };
	ER_UINT ret = sound_svc_write(cmd, sizeof(cmd));

	return ret < 0 ? (ER)ret : E_OK;
}

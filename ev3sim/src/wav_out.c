/*
 * wav_out.c — the speaker streamed to a WAV file (wav_out.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "host_sim/devices/ev3_speaker.h"
#include "ev3sim/output.h"
#include "ev3sim/wav_out.h"

#define HEADER_BYTES     44U
#define RIFF_SIZE_AT     4L     /* the RIFF chunk's size: the file's bytes after it */
#define DATA_SIZE_AT     40L    /* the data chunk's size: the samples' bytes */
#define UNKNOWN_SIZE     0xFFFFFFFFU

static struct {
	FILE *f;
	char *path;
	uint64_t bytes;         /* sample bytes handed to the file */
	int err;                /* errno of the first failed write, 0: none yet */
} wav;

/* Puts v little-endian into p (bytes of it). */
static void put_le(uint8_t *p, uint32_t v, unsigned bytes)
{
	for (unsigned i = 0; i < bytes; i++)
		p[i] = (uint8_t)(v >> (8 * i));
}

/* Writes n bytes, remembering the first failure (later writes are skipped). */
static void write_bytes(const void *p, size_t n)
{
	if (wav.err != 0)
		return;
	if (fwrite(p, 1, n, wav.f) != n)
		wav.err = errno ? errno : EIO;
}

/* The speaker's sink: the samples as 16-bit little-endian PCM. */
static void wav_sink(const int16_t *samples, size_t n, void *ctx)
{
	uint8_t block[2048];
	size_t done = 0;

	(void)ctx;
	while (done < n) {
		size_t k = n - done < sizeof(block) / 2 ? n - done : sizeof(block) / 2;

		for (size_t i = 0; i < k; i++)
			put_le(&block[2 * i], (uint16_t)samples[done + i], 2);
		write_bytes(block, 2 * k);
		done += k;
	}
	wav.bytes += 2U * (uint64_t)n;
}

/* The header of a 32 kHz 16-bit mono PCM file of data bytes. */
static void header(uint8_t h[HEADER_BYTES], uint32_t riff, uint32_t data)
{
	memcpy(h, "RIFF", 4);
	put_le(h + 4, riff, 4);
	memcpy(h + 8, "WAVEfmt ", 8);
	put_le(h + 16, 16, 4);
	put_le(h + 20, 1, 2);                           /* PCM */
	put_le(h + 22, 1, 2);                           /* mono */
	put_le(h + 24, EV3_SPEAKER_RATE, 4);
	put_le(h + 28, EV3_SPEAKER_RATE * 2U, 4);       /* bytes per second */
	put_le(h + 32, 2, 2);                           /* bytes per frame */
	put_le(h + 34, 16, 2);                          /* bits per sample */
	memcpy(h + 36, "data", 4);
	put_le(h + 40, data, 4);
}

ER ev3sim_wav_begin(const char *path, char *err, size_t errlen)
{
	uint8_t h[HEADER_BYTES];

	memset(&wav, 0, sizeof(wav));
	if ((wav.f = ev3sim_fopen_output(path)) == NULL) {
		snprintf(err, errlen, "cannot write %s: %s", path, ev3sim_output_error(errno));
		return E_SYS;
	}
	if ((wav.path = strdup(path)) == NULL) {
		snprintf(err, errlen, "cannot write %s: out of memory", path);
		fclose(wav.f);
		wav.f = NULL;
		return E_SYS;
	}
	header(h, UNKNOWN_SIZE, UNKNOWN_SIZE);
	write_bytes(h, sizeof(h));
	if (ev3_speaker_record_to(wav_sink, NULL) != E_OK) {
		snprintf(err, errlen, "cannot record the speaker for %s", path);
		fclose(wav.f);
		free(wav.path);
		memset(&wav, 0, sizeof(wav));
		return E_SYS;
	}
	return E_OK;
}

ER ev3sim_wav_end(char *err, size_t errlen)
{
	uint8_t sizes[4];
	ER ercd = E_OK;

	if (wav.f == NULL)
		return E_OK;
	ev3_speaker_flush();
	(void)ev3_speaker_record_to(NULL, NULL);     /* the sink's file closes now */
	/* the real sizes where the file can seek; a stream keeps "to the end" */
	if (wav.err == 0 && wav.bytes <= UNKNOWN_SIZE - 36U && fflush(wav.f) == 0 &&
	    fseek(wav.f, RIFF_SIZE_AT, SEEK_SET) == 0) {
		put_le(sizes, (uint32_t)(36U + wav.bytes), 4);
		write_bytes(sizes, 4);
		if (fseek(wav.f, DATA_SIZE_AT, SEEK_SET) == 0) {
			put_le(sizes, (uint32_t)wav.bytes, 4);
			write_bytes(sizes, 4);
		}
	}
	if (wav.err == 0 && fflush(wav.f) != 0)
		wav.err = errno;
	if (fclose(wav.f) != 0 && wav.err == 0)
		wav.err = errno;
	if (wav.err != 0) {
		snprintf(err, errlen, "cannot write %s completely: %s", wav.path, strerror(wav.err));
		ercd = E_SYS;
	}
	free(wav.path);
	memset(&wav, 0, sizeof(wav));
	return ercd;
}

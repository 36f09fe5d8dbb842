/*
 * test_memfile_use.c — what EV3RT apps do with a file from the SD card: a
 * BMP and a WAV read with ev3_memfile_load, then drawn with ev3_image_load
 * and ev3_lcd_draw_image and played with ev3_speaker_play_file.  The buffer
 * is the apps' heap, in the app's domain as EV3RT's app heap is: the API
 * and the sound driver's service call take it from the app's task; the C
 * library's heap, in no domain, is refused, and memfile_free frees nothing
 * ev3_memfile_load did not give out.
 */
#define _XOPEN_SOURCE 700
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "api_test.h"
#include "text_files_test.h"
#include "ev3sim/brick_io.h"
#include "host_sim/devices/ev3_lcd.h"

static char dir[64], card[96];

static void le32(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
	p[2] = (uint8_t)(v >> 16);
	p[3] = (uint8_t)(v >> 24);
}

/* A 16 x 8 1-bit BMP, all black; and a 0.1 s 8 kHz 8-bit mono WAV. */
static void make_card(void)
{
	static const uint8_t bmp_head[62] = {
		'B', 'M', 62 + 32, 0, 0, 0, 0, 0, 0, 0, 62, 0, 0, 0,
		40, 0, 0, 0, 16, 0, 0, 0, 8, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 0, 32, 0, 0, 0,
		0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0,
		0, 0, 0, 0, 255, 255, 255, 0,
	};
	uint8_t bmp[62 + 32] = { 0 }, wav[44 + 800];

	memcpy(bmp, bmp_head, sizeof(bmp_head));
	memcpy(wav, "RIFF\0\0\0\0WAVEfmt ", 16);
	le32(wav + 4, sizeof(wav) - 8);
	le32(wav + 16, 16);
	wav[20] = 1;  wav[21] = 0;      /* PCM */
	wav[22] = 1;  wav[23] = 0;      /* mono */
	le32(wav + 24, 8000);           /* samples per second */
	le32(wav + 28, 8000);           /* bytes per second */
	wav[32] = 1;  wav[33] = 0;      /* bytes per frame */
	wav[34] = 8;  wav[35] = 0;      /* bits per sample */
	memcpy(wav + 36, "data", 4);
	le32(wav + 40, 800);
	for (unsigned i = 0; i < 800; i++)
		wav[44 + i] = (uint8_t)(128 + (i % 20 < 10 ? 60 : -60));
	snprintf(dir, sizeof(dir), "/tmp/ev3_memfile_XXXXXX");
	tf_make_scratch_dir(dir);
	snprintf(card, sizeof(card), "%s/card", dir);
	mkdir(card, 0755);
	tf_put_file(card, "picture.bmp", bmp, sizeof(bmp));
	tf_put_file(card, "beep.wav", wav, sizeof(wav));
}

static void body(void)
{
	memfile_t picture, beep, forged;
	image_t image;
	uint8_t *not_a_memfile = malloc(64);

	is_int(ev3_memfile_load("/picture.bmp", &picture), E_OK, "memfile_load a BMP");
	is_int(ev3_image_load(&picture, &image), E_OK, "ev3_image_load takes the memfile's heap buffer");
	is_int(ev3_lcd_draw_image(&image, 0, 0), E_OK, "and the image draws");
	dly_tsk(400);
	ok(ev3_lcd_pixel(0, 0), "the panel, once started, shows it black at (0, 0)");
	is_int(ev3_memfile_load("/beep.wav", &beep), E_OK, "memfile_load a WAV");
	is_int(ev3_speaker_play_file(&beep, SOUND_MANUAL_STOP), E_OK, "ev3_speaker_play_file takes it too");
	dly_tsk(200);
	is_int(ev3_image_free(&image), E_OK, "image_free");
	is_int(ev3_memfile_free(&picture), E_OK, "memfile_free");
	is_int(ev3_image_load(&picture, &image), E_PAR, "a freed memfile: E_PAR");

	forged.buffer = not_a_memfile;
	forged.filesz = forged.buffersz = 64;
	if (not_a_memfile != NULL)
		memcpy(not_a_memfile, "BM", 2);
	is_int(ev3_image_load(&forged, &image), E_MACV, "the C library's heap, in no domain: E_MACV");
	is_int(ev3_memfile_free(&forged), E_PAR, "nor does memfile_free free it: E_PAR");
	forged.buffer = (uint8_t *)beep.buffer + 1;
	is_int(ev3_memfile_free(&forged), E_PAR, "nor a pointer into a memfile: E_PAR");
	is_int(ev3_memfile_free(&beep), E_OK, "memfile_free the WAV");
	{
		memfile_t twice = { .buffer = NULL };

		is_int(ev3_memfile_load("/beep.wav", &twice), E_OK, "load it again");
		forged = twice;
		is_int(ev3_memfile_free(&twice), E_OK, "free it");
		is_int(ev3_memfile_free(&forged), E_PAR, "a second free of the same buffer: E_PAR");
	}
	free(not_a_memfile);
}

int main(void)
{
	char err[256];

	make_card();
	at_include(&brick_io_cfg);
	is_int(brick_io_setup(card, NULL, err, sizeof(err)), E_OK, "ev3sim's card");
	ok(at_run(NULL, body, 1, 10), "the app ran");
	brick_io_teardown();
	at_include(NULL);
	tf_remove_tree(dir);
	return tap_done();
}

/*
 * test_hello.c — examples/hello: the battery logged before and after the
 * tune, and the tune as the speaker played it (--audio): A4, C#5 and E5
 * for 200 ms each with 50 ms rests, then A5 held for 400 ms until stopped,
 * at volume 50 (25 % duty); the display as hello drew it, pixel for pixel
 * against the API's drawing core run here with the same calls; the greeting
 * it read from the SD card (--sd) and the battery line on the serial port
 * (--serial FILE), and without a card its note instead.
 */
#define _XOPEN_SOURCE 700         /* mkdtemp, nftw */
#include <ftw.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "ev3api_motor.h"
#include "ev3api_sensor.h"
#include "ev3api_lcd.h"
#include "ev3api_speaker.h"
#include "example_test.h"
#include "text_files_test.h"
#include "host_sim/devices/ev3_speaker.h"
#include "host_sim/devices/ev3_lcd.h"
#include "../../api/src/lcd_draw.h"

/* The frame hello draws (its calls, in the drawing core), for the battery text it logged. */
static void hello_frame(uint8_t *frame, const char *battery)
{
	static const char title[] = "Hello EV3!";

	for (int i = 0; title[i]; i++)
		lcd_char(frame, EV3_FONT_MEDIUM, (unsigned char)title[i], (EV3_LCD_WIDTH - 10 * 12) / 2 + 12 * i, 4);
	lcd_line(frame, 0, 22, EV3_LCD_WIDTH - 1, 22, true);
	for (int i = 0; battery[i]; i++)
		lcd_char(frame, EV3_FONT_SMALL, (unsigned char)battery[i], 2 + 6 * i, 30);
	lcd_fill(frame, 40, 60, 98, 40, true);
	lcd_fill(frame, 42, 62, 94, 36, false);
	for (int i = 0; i < 5; i++)
		lcd_char(frame, EV3_FONT_SMALL, (unsigned char)"ev3lx"[i], 74 + 6 * i, 76);
}

/* Notes found in the recording: frequency and length of each run of sound. */
struct note { double hz, ms; };

static unsigned find_notes(const int16_t *s, size_t n, struct note *out, unsigned max)
{
	unsigned count = 0;
	size_t i = 0;

	while (i < n && count < max) {
		size_t start, last, e0 = 0, e1 = 0, edges = 0, gap = 0;

		while (i < n && s[i] == 0)
			i++;
		if (i == n)
			break;
		start = last = i;
		for (; i < n && gap < 640; i++) {       /* a note ends after 20 ms of silence */
			gap = s[i] ? 0 : gap + 1;
			if (s[i])
				last = i;
			if (s[i - 1] < EV3_SPEAKER_FULL / 2 && s[i] >= EV3_SPEAKER_FULL / 2) {
				if (!edges++)
					e0 = i;
				e1 = i;
			}
		}
		out[count].ms = (double)(last + 1 - start) * 1000.0 / EV3_SPEAKER_RATE;
		out[count].hz = edges > 1 ? (double)(edges - 1) * EV3_SPEAKER_RATE / (double)(e1 - e0) : 0;
		count++;
	}
	return count;
}

static char dir[64], card[96];

/* A card holding hello's greeting, in a fresh directory. */
static void make_card(void)
{
	char path[160];

	snprintf(dir, sizeof(dir), "/tmp/ev3_hello_XXXXXX");
	tf_make_scratch_dir(dir);
	snprintf(card, sizeof(card), "%s/card", dir);
	mkdir(card, 0755);
	snprintf(path, sizeof(path), "%s/ev3rt", card);
	mkdir(path, 0755);
	snprintf(path, sizeof(path), "%s/ev3rt/res", card);
	mkdir(path, 0755);
	snprintf(path, sizeof(path), "%s/ev3rt/res/hello.txt", card);
	if (!tf_write_text(path, "Greetings from the SD card\n"))
		tap_bail_out(path);
}

/* hello with the card, its serial port in a file; then without a card. */
static void card_and_serial(void)
{
	char serial[96], text[256], battery[64];
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;
	const char *line;

	snprintf(serial, sizeof(serial), "%s/serial.txt", dir);
	ev3sim_run_defaults(&o, EV3SIM_ROBOT_BARE);
	o.app_name = "hello";
	o.seconds = 1;
	o.sd_dir = card;
	o.serial_path = serial;
	if (ok(ex_run(&o, &r), "hello runs with --sd and --serial")) {
		line = ex_logged("hello: battery");
		snprintf(battery, sizeof(battery), "%s\n", line ? line + strlen("hello: ") : "?");
		tf_read_text(serial, text, sizeof(text));
		ok(strncmp(text, "Greetings from the SD card\n", 27) == 0, "the serial port got the card's greeting");
		ok(strstr(text, battery) != NULL, "and the battery line (%s)", battery);
	}
	o.sd_dir = NULL;
	remove(serial);
	if (ok(ex_run(&o, &r), "hello runs without a card")) {
		tf_read_text(serial, text, sizeof(text));
		ok(strncmp(text, "hello (no /ev3rt/res/hello.txt)\n", 32) == 0, "the serial port says the card had none");
		is_int(r.errors, 1, "the failed load is the one error logged (as EV3RT logs it)");
	}
	tf_remove_tree(dir);
}

int main(void)
{
	static const struct note want[] = { { 440.0, 200 }, { 554.37, 200 }, { 659.25, 200 }, { 880.0, 400 } };
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;
	struct note got[8];
	const int16_t *s;
	int16_t *samples = NULL;    /* little-endian in the file: the host is too */
	const char *line;
	char serial[96], wav[96];
	unsigned n;
	int mv = 0, ma = 0;
	FILE *f;

	make_card();
	snprintf(serial, sizeof(serial), "%s/serial_audio.txt", dir);
	snprintf(wav, sizeof(wav), "%s/hello.wav", dir);
	ev3sim_run_defaults(&o, EV3SIM_ROBOT_BARE);
	o.app_name = "hello";
	o.seconds = 2;
	o.audio_path = wav;
	o.sd_dir = card;
	o.serial_path = serial;
	if (!ok(ex_run(&o, &r), "hello runs with --audio"))
		return tap_done();
	line = ex_logged("hello: battery");
	if (line)
		sscanf(line, "hello: battery %d mV, %d mA", &mv, &ma);
	in_range(mv, 8900, 9000, "the battery logged: %d mV", mv);
	in_range(ma, 95, 105, "and the brick's %d mA", ma);
	{
		static uint8_t frame[LCD_FRAME_BYTES];
		unsigned bad = 0, dark = 0;

		hello_frame(frame, line ? line + strlen("hello: ") : "");
		ok(ev3_lcd_display_on(), "the display is on");
		for (int y = 0; y < EV3_LCD_HEIGHT; y++)
			for (int x = 0; x < EV3_LCD_WIDTH; x++) {
				bad += ev3_lcd_pixel((unsigned)x, (unsigned)y) != lcd_pixel(frame, x, y);
				dark += lcd_pixel(frame, x, y);
			}
		is_int(bad, 0, "the panel shows hello's title, rule, battery line and box exactly (%u dark pixels)",
		       dark);
	}
	ok(ex_logged("hello: tune played") != NULL, "the tune ended");
	is_int(r.warnings + r.errors + r.bugs, 0, "no warnings, errors or bugs");

	f = fopen(wav, "rb");
	ok(f != NULL, "the WAV file was written");
	if (f) {
		unsigned char h[44];
		uint32_t data = 0;

		ok(fread(h, 1, sizeof(h), f) == sizeof(h) && h[0] == 'R' && h[8] == 'W' && h[22] == 1 &&
		   (h[24] | h[25] << 8) == EV3_SPEAKER_RATE && h[34] == 16, "RIFF WAVE, mono, 32 kHz, 16 bits");
		data = (uint32_t)h[40] | (uint32_t)h[41] << 8 | (uint32_t)h[42] << 16 | (uint32_t)h[43] << 24;
		is_int(((uint32_t)h[4] | (uint32_t)h[5] << 8 | (uint32_t)h[6] << 16 | (uint32_t)h[7] << 24) - data,
		       36, "the RIFF size is the data's plus the header's 36 bytes");
		/* the file streamed as the run went: the sizes written at its end match its samples */
		is_int(data, 2 * 2 * EV3_SPEAKER_RATE, "the data chunk holds the 2 s recorded (%u bytes)", data);
		samples = malloc(data);
		ok(samples && fread(samples, 2, data / 2, f) == data / 2 && fgetc(f) == EOF,
		   "and exactly those bytes follow the header");
		fclose(f);
	} else {
		tap_skip(4, "no WAV file");
	}
	s = samples;
	n = s ? find_notes(s, 2 * EV3_SPEAKER_RATE, got, 8) : 0;
	is_int(n, 4, "four notes in the recording");
	for (unsigned i = 0; i < n && i < 4; i++) {
		in_range(got[i].hz, want[i].hz * 0.995, want[i].hz * 1.005, "note %u: %.2f Hz", i + 1, got[i].hz);
		/* from the first rising edge to the end of the last high part: within one period */
		in_range(got[i].ms, want[i].ms - 1000.0 / want[i].hz, want[i].ms + 1.0, "note %u: %.2f ms", i + 1,
			 got[i].ms);
	}
	free(samples);
	card_and_serial();
	return tap_done();
}

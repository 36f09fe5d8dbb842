/*
 * app.c — hello: the brick says hello on its display (a title in the
 * medium font, a rule, the battery in the small font, a framed box), plays a
 * short tune (A4, C#5, E5, then A5 held until stopped) and logs the
 * battery's voltage and current before and during the tune.  It reads a
 * greeting from the SD card (/ev3rt/res/hello.txt) and prints it and the
 * battery to the default serial port.
 */
#include <stdio.h>
#include "ev3api.h"
#include "app.h"

#define GREETING "/ev3rt/res/hello.txt"

/* The greeting and the battery line on the serial port (when one is connected). */
static void greet_serial(const char *battery)
{
	FILE *serial = ev3_serial_open_file(EV3_SERIAL_DEFAULT);
	memfile_t memfile;

	if (serial == NULL)
		return;
	if (ev3_memfile_load(GREETING, &memfile) == E_OK) {
		fprintf(serial, "%.*s", (int)memfile.filesz, (const char *)memfile.buffer);
		ev3_memfile_free(&memfile);
	} else {
		fprintf(serial, "hello (no %s)\n", GREETING);
	}
	fprintf(serial, "%s\n", battery);
	fflush(serial);
}

static const struct { uint16_t hz; int32_t ms; } tune[] = {
	{ (uint16_t)NOTE_A4, 200 }, { (uint16_t)NOTE_CS5, 200 }, { (uint16_t)NOTE_E5, 200 },
};

void main_task(intptr_t exinf)
{
	char battery[32];
	int32_t font_w, font_h;

	tslp_tsk(100);      /* the analog driver's first battery samples */
	snprintf(battery, sizeof(battery), "battery %d mV, %d mA", ev3_battery_voltage_mV(),
		 ev3_battery_current_mA());
	syslog(LOG_NOTICE, "hello: %s", battery);
	greet_serial(battery);

	ev3_lcd_set_font(EV3_FONT_MEDIUM);
	ev3_font_get_size(EV3_FONT_MEDIUM, &font_w, &font_h);
	ev3_lcd_draw_string("Hello EV3!", (EV3_LCD_WIDTH - 10 * font_w) / 2, 4);
	ev3_lcd_draw_line(0, 4 + font_h + 2, EV3_LCD_WIDTH - 1, 4 + font_h + 2);
	ev3_lcd_set_font(EV3_FONT_SMALL);
	ev3_lcd_draw_string(battery, 2, 30);
	ev3_lcd_fill_rect(40, 60, 98, 40, EV3_LCD_BLACK);
	ev3_lcd_fill_rect(42, 62, 94, 36, EV3_LCD_WHITE);
	ev3_lcd_draw_string("ev3lx", 74, 76);

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

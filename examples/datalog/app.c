/*
 * app.c — datalog: the SD card and the serial port the EV3RT way.
 *
 * Reads its settings from the card (/ev3rt/res/datalog.txt: "samples N" and
 * "period_ms P"), lists the resource directory, then writes N lines of CSV
 * (sample, time and whether ENTER is pressed) to the default serial port
 * every P ms.  Without
 * the settings file it logs why and uses 5 samples every 100 ms.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "ev3api.h"
#include "app.h"

#define SETTINGS "/ev3rt/res/datalog.txt"

static void read_settings(int *samples, int *period_ms)
{
	memfile_t memfile;
	char text[128];
	const char *s;
	ER ercd = ev3_memfile_load(SETTINGS, &memfile);

	if (ercd != E_OK) {
		syslog(LOG_NOTICE, "datalog: no %s (%d), defaults", SETTINGS, ercd);
		return;
	}
	snprintf(text, sizeof(text), "%.*s", (int)memfile.filesz, (const char *)memfile.buffer);
	ev3_memfile_free(&memfile);
	if ((s = strstr(text, "samples ")) != NULL)
		*samples = atoi(s + 8);
	if ((s = strstr(text, "period_ms ")) != NULL)
		*period_ms = atoi(s + 10);
}

static void list_resources(void)
{
	fileinfo_t info;
	ER_ID dirid = ev3_sdcard_opendir("/ev3rt/res");

	if (dirid < 0) {
		syslog(LOG_NOTICE, "datalog: cannot list /ev3rt/res (%d)", dirid);
		return;
	}
	while (ev3_sdcard_readdir(dirid, &info) == E_OK)
		syslog(LOG_NOTICE, "datalog: file %s %lu bytes%s", info.name, (unsigned long)info.size,
		       info.is_dir ? " (dir)" : "");
	ev3_sdcard_closedir(dirid);
}

void main_task(intptr_t exinf)
{
	int samples = 5, period_ms = 100;
	FILE *out;
	SYSTIM t0, t;

	read_settings(&samples, &period_ms);
	list_resources();
	syslog(LOG_NOTICE, "datalog: %d samples every %d ms", samples, period_ms);
	out = ev3_serial_open_file(EV3_SERIAL_DEFAULT);
	if (out == NULL) {
		syslog(LOG_NOTICE, "datalog: no serial port");
		ext_tsk();
	}
	fprintf(out, "sample,t_ms,enter\n");
	get_tim(&t0);
	for (int i = 0; i < samples; i++) {
		get_tim(&t);
		fprintf(out, "%d,%lu,%d\n", i, (unsigned long)(t - t0), ev3_button_is_pressed(ENTER_BUTTON) ? 1 : 0);
		tslp_tsk(period_ms);
	}
	syslog(LOG_NOTICE, "datalog: done, %d lines", samples);
	ext_tsk();
}

/*
 * app.c — files: an EV3RT app that uses the C library's file calls on the
 * SD card as EV3RT apps do (newlib over FatFs on the brick): fopen, open,
 * mkdir, rename, remove, unlink, stat, opendir, with absolute ("/ev3rt/...")
 * and relative paths; then plays a short tone and writes a line to the
 * default serial port, for ev3sim's output tests.  Each step logs a NOTICE
 * "files: STEP ok" or "files: STEP failed (errno)".
 */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "ev3api.h"
#include "app.h"

/* Logs the outcome of one step: ok is its success. */
static void step(const char *what, bool ok)
{
	if (ok)
		syslog(LOG_NOTICE, "files: %s ok", what);
	else
		syslog(LOG_NOTICE, "files: %s failed (%d)", what, errno);
}

/* Writes text to path with stdio; true if all of it was written. */
static bool write_text(const char *path, const char *text)
{
	FILE *f = fopen(path, "w");

	if (f == NULL)
		return false;
	fputs(text, f);
	return fclose(f) == 0;
}

/* The files of the card's /ev3rt/files directory: how many opendir lists. */
static int listed(void)
{
	DIR *d = opendir("/ev3rt/files");
	struct dirent *e;
	int n = 0;

	if (d == NULL)
		return -1;
	while ((e = readdir(d)) != NULL)
		n += e->d_name[0] != '.';
	closedir(d);
	return n;
}

void main_task(intptr_t exinf)
{
	struct stat st;
	FILE *serial;
	char buf[32] = "";
	int fd;

	(void)exinf;
	step("mkdir /ev3rt", mkdir("/ev3rt", 0777) == 0 || errno == EEXIST);
	step("mkdir /ev3rt/files", mkdir("/ev3rt/files", 0777) == 0);
	step("fopen /ev3rt/files/log.txt", write_text("/ev3rt/files/log.txt", "logged\n"));
	step("fopen relative", write_text("ev3rt/files/relative.txt", "relative\n"));
	step("fopen /top.txt", write_text("/top.txt", "top\n"));
	fd = open("/ev3rt/files/raw.bin", O_WRONLY | O_CREAT | O_TRUNC, 0666);
	step("open", fd >= 0 && write(fd, "raw", 3) == 3 && close(fd) == 0);
	step("rename", rename("/top.txt", "/ev3rt/files/moved.txt") == 0);
	step("stat", stat("/ev3rt/files/moved.txt", &st) == 0 && st.st_size == 4);
	step("read back", (fd = open("/ev3rt/files/log.txt", O_RDONLY)) >= 0 &&
	     read(fd, buf, sizeof(buf) - 1) == 7 && close(fd) == 0 && strcmp(buf, "logged\n") == 0);
	step("write_text gone.txt", write_text("/ev3rt/files/gone.txt", "x"));
	step("remove", remove("/ev3rt/files/gone.txt") == 0);
	step("unlink", unlink("/ev3rt/files/raw.bin") == 0);
	syslog(LOG_NOTICE, "files: listed %d", listed());
	/* the card's root is the top: ".." above it stays out of the host's directories */
	step("escape", write_text("/../escaped.txt", "escaped\n"));
	step("escape relative", write_text("../escaped.txt", "escaped\n"));

	ev3_speaker_set_volume(50);
	ev3_speaker_play_tone(NOTE_A4, 200);
	if ((serial = ev3_serial_open_file(EV3_SERIAL_DEFAULT)) != NULL) {
		fprintf(serial, "files: done\r\n");
		fflush(serial);
	}
	syslog(LOG_NOTICE, "files: done");
}

/*
 * app.c — heap: what an EV3RT app does with malloc.  It reads the colour
 * sensor into a malloc'd rgb_raw_t and the motor counts into calloc'd
 * memory, grows a buffer with realloc, frees a strdup'd copy, and allocates
 * until the heap is full; each outcome goes to the log.
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "app.h"

/* Bytes malloc gives in 64 KiB pieces before it returns NULL (freed again). */
static size_t bytes_until_full(void)
{
	enum { PIECE = 64 * 1024, MAX_PIECES = 64 };
	void *pieces[MAX_PIECES];
	size_t n = 0, total;

	while (n < MAX_PIECES && (pieces[n] = malloc(PIECE)) != NULL)
		n++;
	total = n * (size_t)PIECE;
	while (n > 0)
		free(pieces[--n]);
	return total;
}

void main_task(intptr_t unused)
{
	rgb_raw_t *rgb = malloc(sizeof(*rgb));
	int32_t *counts = calloc(2, sizeof(*counts));
	char *text = malloc(8), *grown, *copy;
	void *aligned = NULL;
	size_t first, second;

	ev3_sensor_config(EV3_PORT_1, COLOR_SENSOR);
	ev3_motor_config(EV3_PORT_A, LARGE_MOTOR);
	syslog(LOG_NOTICE, "heap: calloc'd counts %ld %ld", (long)counts[0], (long)counts[1]);
	ev3_color_sensor_get_rgb_raw(EV3_PORT_1, rgb);
	syslog(LOG_NOTICE, "heap: rgb into malloc'd memory %u %u %u", rgb->r, rgb->g, rgb->b);
	counts[0] = ev3_motor_get_counts(EV3_PORT_A);
	syslog(LOG_NOTICE, "heap: lcd from malloc'd text %d", (int)ev3_lcd_draw_string(strcpy(text, "heap"), 0, 0));

	grown = realloc(text, 4000);
	memset(grown + 4, 'x', 3995);
	grown[3999] = '\0';
	syslog(LOG_NOTICE, "heap: realloc kept \"%.4s\" and grew to %u", grown, (unsigned)strlen(grown));
	copy = strdup("a copy the C library made");
	syslog(LOG_NOTICE, "heap: strdup %s", copy);
	free(copy);
	syslog(LOG_NOTICE, "heap: posix_memalign 16 %d, 64 %d", posix_memalign(&aligned, 16, 100),
	       posix_memalign(&aligned, 64, 100) == ENOMEM);
	free(aligned);

	first = bytes_until_full();
	second = bytes_until_full();
	syslog(LOG_NOTICE, "heap: full after %u KiB, again after %u KiB", (unsigned)(first / 1024),
	       (unsigned)(second / 1024));
	free(grown);
	free(counts);
	free(rgb);
	syslog(LOG_NOTICE, "heap: done");
}

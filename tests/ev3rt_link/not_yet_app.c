/*
 * not_yet_app.c — an EV3RT app calling the functions of the group ev3lx
 * provided last (the LCD).  It must compile without a warning; it links now
 * (make ev3rt-link-check: while a group is missing, the link fails naming
 * each call).
 */
#include <stdio.h>
#include "ev3api.h"

void main_task(intptr_t exinf);

void main_task(intptr_t exinf)
{
	memfile_t file = { NULL, 0, 0 };
	image_t image;

	ev3_lcd_draw_string("hello", 0, 0);
	ev3_image_load(&file, &image);
	(void)exinf;
}

int main(void)
{
	main_task(0);
	return 0;
}

/*
 * not_yet_app.c — an EV3RT app calling one function of every group ev3lx
 * does not provide yet.  It must compile without a warning and fail to link,
 * the linker naming each call (make ev3rt-link-check).
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

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
	int16_t axes[3];
	FILE *bt;

	ev3_lcd_draw_string("hello", 0, 0);
	ev3_image_load(&file, &image);
	ev3_memfile_load("/ev3rt/x.wav", &file);
	bt = ev3_serial_open_file(EV3_SERIAL_BT);
	if (ev3_bluetooth_is_connected() && bt)
		fprintf(bt, "hi\n");
	ht_nxt_accel_sensor_measure(EV3_PORT_1, axes);
	(void)exinf;
}

int main(void)
{
	main_task(0);
	return 0;
}

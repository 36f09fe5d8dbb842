/*
 * ev3api_fs.h — files on the SD card, serial ports and Bluetooth (included
 * by ev3api.h), EV3RT's interface.  Not provided yet: every call is
 * EV3API_NOT_YET (an app using one compiles and fails to link, naming the
 * call).
 */
#ifndef EV3API_FS_H
#define EV3API_FS_H

#include <stdint.h>
#include <stdio.h>
#include "kernel.h"
#include "ev3api_not_yet.h"

#define TMAX_FILENAME_LEN 255

/* A file read into memory. */
typedef struct {
	void *buffer;
	uint32_t filesz;
	uint32_t buffersz;
} memfile_t;

typedef struct {
	uint32_t size;
	uint16_t date, time;
	bool_t is_dir, is_readonly, is_hidden;
	char name[TMAX_FILENAME_LEN + 1];
} fileinfo_t;

typedef enum {
	EV3_SERIAL_DEFAULT = 0, EV3_SERIAL_UART = 1, EV3_SERIAL_BT = 2, EV3_SERIAL_USB_CDC = 3
} serial_port_t;

ER ev3_memfile_load(const char *path, memfile_t *p_memfile) EV3API_NOT_YET(files, ev3_memfile_load);
ER ev3_memfile_free(memfile_t *p_memfile) EV3API_NOT_YET(files, ev3_memfile_free);
ER_ID ev3_sdcard_opendir(const char *path) EV3API_NOT_YET(files, ev3_sdcard_opendir);
ER ev3_sdcard_readdir(ID dirid, fileinfo_t *p_fileinfo) EV3API_NOT_YET(files, ev3_sdcard_readdir);
ER ev3_sdcard_closedir(ID dirid) EV3API_NOT_YET(files, ev3_sdcard_closedir);

FILE *ev3_serial_open_file(serial_port_t port) EV3API_NOT_YET(serial, ev3_serial_open_file);
bool_t ev3_bluetooth_is_connected(void) EV3API_NOT_YET(bluetooth, ev3_bluetooth_is_connected);
bool_t ev3_usb_cdc_is_connected(void) EV3API_NOT_YET(serial, ev3_usb_cdc_is_connected);

#endif /* EV3API_FS_H */

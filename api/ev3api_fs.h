/*
 * ev3api_fs.h — files on the SD card, serial ports and Bluetooth (included
 * by ev3api.h), EV3RT's interface.  The SD card is a host directory and the
 * serial port a host file or pseudo-terminal under ev3sim (--sd, --serial);
 * Bluetooth and USB CDC are not provided: their streams are NULL (logged)
 * and they are never connected.  docs/api.md gives the error codes.
 */
#ifndef EV3API_FS_H
#define EV3API_FS_H

#ifdef __cplusplus
extern "C" {
#endif

#include <stdint.h>
#include <stdio.h>
#include "kernel.h"

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

ER ev3_memfile_load(const char *path, memfile_t *p_memfile);
ER ev3_memfile_free(memfile_t *p_memfile);
ER_ID ev3_sdcard_opendir(const char *path);
ER ev3_sdcard_readdir(ID dirid, fileinfo_t *p_fileinfo);
ER ev3_sdcard_closedir(ID dirid);

FILE *ev3_serial_open_file(serial_port_t port);
bool_t ev3_bluetooth_is_connected(void);
bool_t ev3_usb_cdc_is_connected(void);

#ifdef __cplusplus
}
#endif

#endif /* EV3API_FS_H */

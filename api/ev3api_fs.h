/*
 * ev3api_fs.h — files on the SD card, serial ports and Bluetooth (included
 * by ev3api.h), EV3RT's interface.  Under ev3sim the SD card is a host
 * directory (--sd), the serial port a host file or pseudo-terminal
 * (--serial), and Bluetooth's and USB's far ends programs on Unix sockets
 * (--bt, --bt-master, --usb); every port gives a stream, connected or not.
 * docs/api.md gives the error codes.
 *
 * EV3RT 1.x (the HRP3 profile, EV3LX_KERNEL_HRP3) numbers the ports
 * differently — 3 is the Bluetooth SPP master's, and there is no USB CDC —
 * and gives the SPP master as API calls (public source:
 * ev3rt-git/ev3rt-hrp3-sdk, common/ev3api/src/ev3api_fs.h).
 */
#ifndef EV3API_FS_H
#define EV3API_FS_H

#ifdef __cplusplus
extern "C" {
#endif

#include <stdint.h>
#include <stdio.h>
#include "kernel.h"

/* The HRP3 profile's binding of a call to its EV3RT 1.x form is ev3lx's
 * host kernel's (rtos_stub/include/kernel.h); a real HRP2 kernel's kernel.h
 * has no such profile, and the calls keep their HRP2 form. */
#ifndef EV3LX_HRP3_SVC
#define EV3LX_HRP3_SVC(name)
#endif

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

#ifdef EV3LX_KERNEL_HRP3
typedef enum {
	EV3_SERIAL_DEFAULT = 0, EV3_SERIAL_UART = 1, EV3_SERIAL_BT = 2, EV3_SERIAL_SPP_MASTER = 3
} serial_port_t;

/* A Bluetooth device's address. */
typedef uint8_t ev3_bt_addr_t[6];
#else
typedef enum {
	EV3_SERIAL_DEFAULT = 0, EV3_SERIAL_UART = 1, EV3_SERIAL_BT = 2, EV3_SERIAL_USB_CDC = 3
} serial_port_t;
#endif

ER ev3_memfile_load(const char *path, memfile_t *p_memfile);
ER ev3_memfile_free(memfile_t *p_memfile);
ER_ID ev3_sdcard_opendir(const char *path);
ER ev3_sdcard_readdir(ID dirid, fileinfo_t *p_fileinfo);
ER ev3_sdcard_closedir(ID dirid);

FILE *ev3_serial_open_file(serial_port_t port) EV3LX_HRP3_SVC(ev3_serial_open_file);
bool_t ev3_bluetooth_is_connected(void);
bool_t ev3_usb_cdc_is_connected(void);

#ifdef EV3LX_KERNEL_HRP3
/* The SPP master back to idle, its link closed: E_OK. */
ER ev3_spp_master_reset(void);
/* Starts connecting to the service (name prefix service) of the device at
 * addr with PIN pin: E_OK started, E_CTX if the master is not idle (an
 * attempt under way, or connected), E_MACV / E_PAR for bad arguments. */
ER ev3_spp_master_connect(ev3_bt_addr_t addr, const char *pin, const char *service);
/* Whether the master's link to the remote service is up. */
bool_t ev3_spp_master_is_connected(void);
#endif

#ifdef __cplusplus
}
#endif

#endif /* EV3API_FS_H */

/*
 * brick_io.h — the simulated brick's SD card and serial port: the provider
 * of the API's storage and serial service calls (ev3api_brick_io.h).  Host
 * only.
 *
 * The SD card is a host directory: every path is resolved inside it (".."
 * never climbs above it, a symbolic link leading out of it is refused with
 * E_PAR).  The serial port (EV3_SERIAL_DEFAULT and EV3_SERIAL_UART, one
 * line) is a host path: a regular file receives what the brick writes
 * (reading it finds its end at once); a pseudo-terminal, FIFO or other
 * character device carries both directions, reads never blocking the
 * simulation.  Without a card or a port the calls return E_OBJ.
 */
#ifndef EV3SIM_BRICK_IO_H
#define EV3SIM_BRICK_IO_H

#include "kernel.h"
#include "rtos_cfg.h"

/* The DEF_SVC rows (INCLUDE it in the configuration). */
extern const struct rtos_cfg brick_io_cfg;

/* Before boot: the card's directory (NULL: no card) and the serial port's
 * path (NULL: not connected).  E_OBJ (and a message in err) if either cannot
 * be opened.  Replaces an earlier setup. */
ER brick_io_setup(const char *sd_dir, const char *serial_path, char *err, size_t errlen);

/* After brick_io_setup: the serial port is serial_log's polled UART model
 * (serial_log.h), output only, so each byte a task writes costs it the
 * port's time as on the brick. */
void brick_io_serial_to_uart(void);

/* The errno of the first write to the serial port's host file that failed
 * since brick_io_setup (the app saw E_OBJ), 0 if none did; kept after the
 * teardown, so that the command line can report it. */
int brick_io_serial_write_errno(void);

/* How brick_io_card_path treats the path's last component. */
enum brick_io_card_use {
	BRICK_IO_CARD_EXISTING,     /* followed, and must exist (stat, opendir, reading) */
	BRICK_IO_CARD_CREATE,       /* followed if it exists, else a new name in an existing directory */
	BRICK_IO_CARD_ENTRY,        /* the entry itself, not followed (mkdir, remove, rename) */
};

/* The host path (malloc'd) of an app's card path, absolute or relative to
 * the card's root as EV3RT's FatFs sees both: E_OK; E_OBJ without a card;
 * E_PAR for an empty or too long path, a ".." above the root or a symbolic
 * link out of the card; E_NOEXS if it (or its directory) is not there;
 * E_NOMEM. */
ER brick_io_card_path(const char *path, enum brick_io_card_use use, char **host);

/* After brick_io_setup: Bluetooth SPP's far end is a Unix socket at path,
 * to which a PC program connects as it would pair with the brick; while it
 * is connected, ev3_bluetooth_is_connected is true and EV3_SERIAL_BT (and
 * SIO_PORT_BT) carry its bytes; it may disconnect and connect again.  E_OK,
 * or E_PAR / E_OBJ with the reason in err. */
ER brick_io_bt_listen(const char *path, char *err, size_t errlen);

/* After brick_io_setup: USB CDC's far end (the PC the brick is plugged
 * into) is a Unix socket at path, as brick_io_bt_listen's for Bluetooth:
 * while a program is connected, ev3_usb_cdc_is_connected is true and
 * EV3_SERIAL_USB_CDC (and SIO_PORT_USB_CDC) carry its bytes. */
ER brick_io_usb_listen(const char *path, char *err, size_t errlen);

/* After brick_io_setup: the remote slave the brick's Bluetooth SPP master
 * (SIO_PORT_SPP_MASTER_TEST) connects to is a program listening on a Unix
 * socket at path (another ev3sim's --bt among them); the socket need not
 * exist yet, each connection attempt looks for it.  E_OK, or E_PAR with
 * the reason in err. */
ER brick_io_bt_master(const char *path, char *err, size_t errlen);

/* Closes what brick_io_setup opened (directories the app left open too). */
void brick_io_teardown(void);

#endif /* EV3SIM_BRICK_IO_H */

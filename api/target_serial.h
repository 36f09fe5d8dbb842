/*
 * target_serial.h — the EV3's serial ports as the TOPPERS serial interface
 * numbers them (public source: ev3rt-git/ev3rt-hrp2,
 * target/ev3_gcc/target_serial.h).  Apps name them in serial_rea_dat /
 * serial_wri_dat (syssvc/serial.h); EV3RT's sample apps reach this header
 * through target_test.h.
 */
#ifndef TOPPERS_TARGET_SERIAL_H
#define TOPPERS_TARGET_SERIAL_H

#define SIO_PORT_UART             (1)  /* sensor port 1 as a UART */
#define SIO_PORT_BT               (2)  /* Bluetooth SPP */
#define SIO_PORT_LCD              (3)  /* the LCD console */
#define SIO_PORT_SPP_MASTER_TEST  (4)  /* Bluetooth SPP, master side */
#define SIO_PORT_USB_CDC          (5)  /* USB CDC (virtual COM port) */

#define TNUM_PORT 5

#endif /* TOPPERS_TARGET_SERIAL_H */

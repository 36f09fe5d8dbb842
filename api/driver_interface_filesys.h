/*
 * driver_interface_filesys.h — the file numbers EV3RT gives its serial
 * ports (public source: ev3rt-git/ev3rt-hrp2,
 * target/ev3_gcc/pil/include/driver_interface_filesys.h): fdopen(n, mode)
 * on one of them is that port's stream, as ev3_serial_open_file gives it.
 * The card's files never get these numbers.
 */
#ifndef EV3RT_DRIVER_INTERFACE_FILESYS_H
#define EV3RT_DRIVER_INTERFACE_FILESYS_H

#define SIO_STD_FILENO                  (3)  /* EV3_SERIAL_DEFAULT */
#define SIO_UART_FILENO                 (4)  /* SIO_PORT_UART, EV3_SERIAL_UART */
#define SIO_BT_FILENO                   (5)  /* SIO_PORT_BT, EV3_SERIAL_BT */
#define SIO_PORT_SPP_MASTER_TEST_FILENO (6)  /* SIO_PORT_SPP_MASTER_TEST */
#define SIO_USB_CDC_FILENO              (7)  /* SIO_PORT_USB_CDC, EV3_SERIAL_USB_CDC */

#endif /* EV3RT_DRIVER_INTERFACE_FILESYS_H */

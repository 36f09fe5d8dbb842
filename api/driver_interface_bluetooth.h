/*
 * driver_interface_bluetooth.h — the Bluetooth part of EV3RT's platform
 * interface layer: the SPP master, with which the brick connects to a
 * remote slave (public source: ev3rt-git/ev3rt-hrp2,
 * target/ev3_gcc/pil/include/driver_interface_bluetooth.h and
 * drivers/bluetooth/src/bluetooth_dri.c).  Once connected, the link is
 * SIO_PORT_SPP_MASTER_TEST (syssvc/serial.h), or a stream from
 * fdopen(SIO_PORT_SPP_MASTER_TEST_FILENO, ...).  In ev3sim the slave is
 * the program behind `ev3sim run --bt-master PATH`.
 */
#ifndef EV3RT_DRIVER_INTERFACE_BLUETOOTH_H
#define EV3RT_DRIVER_INTERFACE_BLUETOOTH_H

#include <stdint.h>
#include "kernel.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Tries to connect to the slave at Bluetooth address addr with PIN pin (1 to
 * 16 characters), waiting until the attempt ends, as EV3RT's does: E_OK
 * whether or not it connected (serial_ref_por(SIO_PORT_SPP_MASTER_TEST)
 * says which); E_CTX while another task's attempt is under way or from a
 * non-task context, E_MACV for unreadable arguments, E_PAR for a bad PIN.
 */
ER spp_master_test_connect(const uint8_t addr[6], const char *pin) throw();

#ifdef __cplusplus
}
#endif

#endif /* EV3RT_DRIVER_INTERFACE_BLUETOOTH_H */

/*
 * nxt_iic_bus.h — between the ports model (brick.c) and the NXT I2C bus
 * model (nxt_iic.c).  Host only, internal to src/ev3.
 */
#ifndef HOST_SIM_EV3_NXT_IIC_BUS_H
#define HOST_SIM_EV3_NXT_IIC_BUS_H

#include <stdbool.h>
#include "host_sim/devices/nxt_iic.h"

/* Puts a slave of kind on input port's bus (replacing any); false if out of watch slots. */
bool nxt_iic_bus_attach(unsigned port, enum nxt_iic_kind kind, const struct nxt_iic_scene *scene);
/* Takes the slave off the bus and stops watching the port's pins. */
void nxt_iic_bus_detach(unsigned port);
/* Drives the connector side of pins 5 and 6 from the bus: plugged, the sensor's pull-ups and
 * its SDA; unplugged, nothing (the caller's defaults). */
void nxt_iic_bus_apply(unsigned port, bool plugged);

#endif /* HOST_SIM_EV3_NXT_IIC_BUS_H */

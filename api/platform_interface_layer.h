/*
 * platform_interface_layer.h — EV3RT's platform interface layer (PIL), the
 * interface between EV3RT's API libraries and its core services (public
 * source: ev3rt-git/ev3rt-hrp2, target/ev3_gcc/pil/include/).  SDK
 * libraries include it for what ev3api.h does not give: the Bluetooth SPP
 * master (driver_interface_bluetooth.h) and the file numbers of the serial
 * ports (driver_interface_filesys.h).  EV3RT's other PIL groups (LCD, brick,
 * sound) are the core's own interface to its drivers; ev3lx's API reaches
 * its drivers through the hacks' service calls instead, so they are not here.
 */
#ifndef EV3RT_PLATFORM_INTERFACE_LAYER_H
#define EV3RT_PLATFORM_INTERFACE_LAYER_H

/* The PIL's version: 8, named "Beta 7-2" (the oldest PIL an app may be built
 * for), in EV3RT's core "Beta 7-3". */
#define PIL_VERSION        (8U)
#define PIL_VERSION_STRING "Beta 7-2"
#define CSL_VERSION_STRING "Beta 7-3"

#include "driver_interface_bluetooth.h"
#include "driver_interface_filesys.h"

#endif /* EV3RT_PLATFORM_INTERFACE_LAYER_H */

/*
 * spp_link.h — the brick as Bluetooth SPP master: connect to a remote
 * slave, see whether the link is up, and talk over it as a stdio stream.
 */
#pragma once

#ifdef __cplusplus
extern "C" {
#endif

#include <stdio.h>
#include "ev3api.h"

/* One connection attempt to the slave at addr with PIN pin; returns when it ends. */
extern void spp_link_connect(const uint8_t addr[6], const char *pin);

/* Whether the link to the slave is up. */
extern bool_t spp_link_is_connected(void);

/* The link as an unbuffered stream (NULL if the platform has none). */
extern FILE *spp_link_open_file(void);

#ifdef __cplusplus
}
#endif

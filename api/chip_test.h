/*
 * chip_test.h — the AM1808's test definitions: its serial ports
 * (EV3RT: target_test.h -> chip_test.h -> target_serial.h).
 */
#ifndef TOPPERS_CHIP_TEST_H
#define TOPPERS_CHIP_TEST_H

#include "target_serial.h"

#endif /* TOPPERS_CHIP_TEST_H */

/*
 * target_test.h — the target's test definitions, which every EV3RT sample
 * app's app.h includes (public source: ev3rt-git/ev3rt-hrp2,
 * target/ev3_gcc/target_test.h).
 */
#ifndef TOPPERS_TARGET_TEST_H
#define TOPPERS_TARGET_TEST_H

#include "chip_test.h"

#endif /* TOPPERS_TARGET_TEST_H */

/*
 * target_kernel.h — the EV3 target's part of the kernel interface, which
 * HRP2's kernel.h includes: EV3RT's platform header, ev3.h (public source:
 * ev3rt-git/ev3rt-hrp2, target/ev3_gcc/target_kernel.h).
 */
#ifndef TOPPERS_TARGET_KERNEL_H
#define TOPPERS_TARGET_KERNEL_H

#include "ev3.h"

#endif /* TOPPERS_TARGET_KERNEL_H */

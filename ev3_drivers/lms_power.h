/* SPDX-License-Identifier: GPL-2.0 WITH Linux-syscall-note */
/*
 * lms_power.h - user interface of d_power (/dev/lms_power): the EV3's battery type and power
 * pins, as LEGO's lms2012 d_power defines it:
 *   read   two characters: "1\r" when a rechargeable pack is fitted (its sense pin reads low),
 *          "0\r" for six AA cells; every read from offset 0 samples the pin again;
 *   write  exactly one byte: non-zero drives the test pin high, zero drives it low
 *          (-EINVAL for any other length);
 *   ioctl  accepted and ignored (LEGO's user space issues ioctl 0), returns 0.
 * No mmap.
 */
#ifndef LMS_POWER_H
#define LMS_POWER_H

#define LMS_POWER_DEVICE_NAME	"lms_power"
#define LMS_POWER_READ_SIZE	2	/* "1\r" or "0\r" */
#define LMS_POWER_RECHARGEABLE	'1'
#define LMS_POWER_ALKALINE	'0'

#endif /* LMS_POWER_H */

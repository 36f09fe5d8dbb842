/* SPDX-License-Identifier: GPL-2.0 */
/*
 * ev3_uart_uapi.h - the user interface of ev3_uart, the line discipline
 * for LEGO EV3 UART sensors: once a sensor has introduced itself,
 * /dev/ev3_uart_<tty> exists; read() waits for the next data frame and
 * returns one struct ev3_uart_reading; EV3_UART_INFO describes the sensor
 * and EV3_UART_SET_MODE selects a mode.
 */
#ifndef EV3_UART_UAPI_H
#define EV3_UART_UAPI_H

#include <linux/ioctl.h>
#include <linux/types.h>

#define EV3_UART_MAX_MODES	8
#define EV3_UART_NAME_LEN	12

struct ev3_uart_reading {
	__u8 mode;		/* the mode the frame was sent in */
	__u8 format;		/* 0 8-bit, 1 16-bit, 2 32-bit integers, 3 IEEE floats */
	__u8 datasets;		/* values in the frame */
	__u8 reserved;
	__s32 value[8];		/* integers sign-extended; floats as their bits */
	__u32 frames;		/* data frames received so far */
};

struct ev3_uart_info {
	__u8 type;		/* 29 colour, 30 ultrasonic, 32 gyro, 33 infrared */
	__u8 modes;
	__u8 views;
	__u8 mode;		/* the mode selected now */
	__u32 speed;		/* baud after the handshake */
	char name[EV3_UART_MAX_MODES][EV3_UART_NAME_LEN];
};

#define EV3_UART_INFO		_IOR('e', 1, struct ev3_uart_info)
#define EV3_UART_SET_MODE	_IOW('e', 2, int)

#endif /* EV3_UART_UAPI_H */

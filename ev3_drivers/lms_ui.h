/* SPDX-License-Identifier: GPL-2.0 WITH Linux-syscall-note */
/*
 * lms_ui.h - user interface of d_ui (/dev/lms_ui): the EV3 brick's six buttons and its two
 * bicolour LEDs.
 *
 * Interface-compatible with LEGO's lms2012 d_ui where LEGO defines one:
 *   mmap   struct lms_ui, whose first six bytes are LEGO's UI (pressed[] in LEGO's button
 *          order, 1 while a button is held down, debounced); the rest is our extension;
 *   write  byte 0 selects the LED pattern of both LEDs, '0'..'9' as LEGO's LEDPATTERNS
 *          (further bytes are ignored); -EINVAL for any other byte;
 * and, beyond LEGO's driver:
 *   read   click events (a press followed by its release), struct lms_ui_click each, oldest
 *          first: blocks until at least one is queued (-EAGAIN with O_NONBLOCK), returns as
 *          many whole events as fit in the buffer (-EINVAL if not even one fits); events are
 *          removed only once copied, so -EFAULT loses none.  All readers share one queue;
 *   poll   EPOLLIN while a click is queued; EPOLLOUT always (the LEDs never block).
 *
 * A state must hold for debounce_ms (module parameter, 20 ms by default) to count: contact
 * bounce never produces extra presses, releases or clicks.
 */
#ifndef LMS_UI_H
#define LMS_UI_H

#ifdef __KERNEL__
#include <linux/types.h>
#else
#include <stdint.h>
#endif

#define LMS_UI_DEVICE_NAME	"lms_ui"

/* Buttons, in LEGO's order (lms2012 button codes minus one). */
#define LMS_UI_BUTTON_UP	0
#define LMS_UI_BUTTON_ENTER	1
#define LMS_UI_BUTTON_DOWN	2
#define LMS_UI_BUTTON_RIGHT	3
#define LMS_UI_BUTTON_LEFT	4
#define LMS_UI_BUTTON_BACK	5
#define LMS_UI_BUTTONS		6

/* LED patterns: the byte written.  Flash: 500 ms on, 500 ms off; pulse: two 100 ms blinks
 * per second.  Both LEDs show the same pattern. */
#define LMS_UI_LED_OFF			'0'
#define LMS_UI_LED_GREEN		'1'
#define LMS_UI_LED_RED			'2'
#define LMS_UI_LED_ORANGE		'3'	/* red and green together */
#define LMS_UI_LED_GREEN_FLASH		'4'
#define LMS_UI_LED_RED_FLASH		'5'
#define LMS_UI_LED_ORANGE_FLASH		'6'
#define LMS_UI_LED_GREEN_PULSE		'7'
#define LMS_UI_LED_RED_PULSE		'8'
#define LMS_UI_LED_ORANGE_PULSE		'9'

/* What read() returns for each click, 8 bytes. */
struct lms_ui_click {
	uint8_t button;			/* LMS_UI_BUTTON_* */
	uint8_t reserved;		/* 0 */
	uint16_t held_ms;		/* press to release, saturated at 65535 */
	uint32_t seq;			/* 1 for the first click after load, +1 each (gap: dropped) */
};

/* The shared page (mmap, offset 0, at most LMS_UI_MAP_SIZE bytes). */
struct lms_ui {
	uint8_t pressed[LMS_UI_BUTTONS];	/* LEGO's UI: 1 while held down (debounced) */
	uint8_t led;				/* the LED pattern shown, '0'..'9' */
	uint8_t reserved;
	uint32_t clicks;			/* seq of the newest click queued */
	uint32_t dropped;			/* clicks lost because the queue was full */
	uint32_t bounces;			/* edges that did not last debounce_ms */
	uint32_t presses[LMS_UI_BUTTONS];	/* debounced presses of each button */
};

#define LMS_UI_CLICK_QUEUE	16	/* clicks kept until read */
#define LMS_UI_MAP_SIZE		4096	/* one page */

#endif /* LMS_UI_H */

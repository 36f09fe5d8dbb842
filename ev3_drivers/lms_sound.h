/* SPDX-License-Identifier: GPL-2.0 WITH Linux-syscall-note */
/*
 * lms_sound.h - user interface of d_sound (/dev/lms_sound), LEGO's lms2012 sound protocol.
 *
 *   write  byte 0 is the command:
 *          BREAK    [0]                          stop whatever plays; returns 0
 *          TONE     [1][level][freq lo, hi][ms lo, hi]  a tone of freq Hz (clamped to
 *                   250..10000) at level 0..100; ms = 0 plays until BREAK; returns 0
 *          PLAY     [2][level]                   start 8 kHz PCM playback; returns 2
 *          REPEAT   [3]...                       ignored (user space loops itself); returns 0
 *          SERVICE  [4][s0]...[sN-1]             queue N unsigned 8-bit samples (N <= 252) in
 *                   the next free slot of three: returns N, or 0 while all slots are full
 *          (-EINVAL for another command or a short TONE/PLAY)
 *   read   the text "lms_sound\r"
 *   mmap   one page whose byte 0 is the status: user space writes BUSY before TONE/PLAY;
 *          the driver writes OK when a timed tone ends, PCM runs dry, or on BREAK.
 * Playback goes on after the file is closed (user space opens, writes, closes per command).
 */
#ifndef LMS_SOUND_H
#define LMS_SOUND_H

#define LMS_SOUND_DEVICE_NAME	"lms_sound"
#define LMS_SOUND_MAP_SIZE	4096

#define LMS_SOUND_BREAK		0
#define LMS_SOUND_TONE		1
#define LMS_SOUND_PLAY		2
#define LMS_SOUND_REPEAT	3
#define LMS_SOUND_SERVICE	4

#define LMS_SOUND_OK		0	/* status byte values (lms2012 RESULT) */
#define LMS_SOUND_BUSY		1

#define LMS_SOUND_SLOTS		3
#define LMS_SOUND_SLOT_SAMPLES	252
#define LMS_SOUND_RATE		8000
#define LMS_SOUND_MIN_FREQ	250
#define LMS_SOUND_MAX_FREQ	10000
#define LMS_SOUND_MAX_LEVEL	100

#endif /* LMS_SOUND_H */

/*
 * ev3api_speaker.h — the speaker (included by ev3api.h), EV3RT's interface,
 * over d_sound (sound_hack.h).  Tones are played by the driver itself
 * (eHRPWM0 makes the square wave, its one-shot timer ends a timed tone), so
 * a call returns at once; a file's samples are fed to the driver from a
 * work item, so play_file returns at once too.
 * Errors: E_CTX from non-task context, E_OBJ when d_sound is not loaded.
 */
#ifndef EV3API_SPEAKER_H
#define EV3API_SPEAKER_H

#ifdef __cplusplus
extern "C" {
#endif

#include <stdint.h>
#include "kernel.h"
#include "ev3api_fs.h"
#include "ev3api_not_yet.h"

/* duration_ms of a tone or file that plays until ev3_speaker_stop */
#define SOUND_MANUAL_STOP (-1)

/* Notes C4..B6 in Hz, equal temperament with A4 = 440 Hz. */
#define NOTE_C4  (261.63)
#define NOTE_CS4 (277.18)
#define NOTE_D4  (293.66)
#define NOTE_DS4 (311.13)
#define NOTE_E4  (329.63)
#define NOTE_F4  (349.23)
#define NOTE_FS4 (369.99)
#define NOTE_G4  (392.00)
#define NOTE_GS4 (415.30)
#define NOTE_A4  (440.00)
#define NOTE_AS4 (466.16)
#define NOTE_B4  (493.88)
#define NOTE_C5  (523.25)
#define NOTE_CS5 (554.37)
#define NOTE_D5  (587.33)
#define NOTE_DS5 (622.25)
#define NOTE_E5  (659.25)
#define NOTE_F5  (698.46)
#define NOTE_FS5 (739.99)
#define NOTE_G5  (783.99)
#define NOTE_GS5 (830.61)
#define NOTE_A5  (880.00)
#define NOTE_AS5 (932.33)
#define NOTE_B5  (987.77)
#define NOTE_C6  (1046.50)
#define NOTE_CS6 (1108.73)
#define NOTE_D6  (1174.66)
#define NOTE_DS6 (1244.51)
#define NOTE_E6  (1318.51)
#define NOTE_F6  (1396.91)
#define NOTE_FS6 (1479.98)
#define NOTE_G6  (1567.98)
#define NOTE_GS6 (1661.22)
#define NOTE_A6  (1760.00)
#define NOTE_AS6 (1864.66)
#define NOTE_B6  (1975.53)


/* Volume 0..100 (above 100: 100) for the next tone; default 10 (EV3RT's).  A playing tone keeps its volume. */
ER ev3_speaker_set_volume(uint8_t volume);
/* Plays frequency Hz (250..10000, clamped) for duration ms (up to 65535) or, with
 * SOUND_MANUAL_STOP (any negative duration), until ev3_speaker_stop; replaces what plays.
 * A duration of 0 plays nothing. */
ER ev3_speaker_play_tone(uint16_t frequency, int32_t duration);
/* Plays a RIFF WAV file in memory (PCM, mono, 8000 Hz, 8 bits: else E_NOSPT; not a WAV: E_PAR)
 * at the volume, for duration ms or, with SOUND_MANUAL_STOP (any negative duration), to its end;
 * 0 plays nothing.  The memory must stay loaded while it plays.  E_MACV for memory the task may
 * not read. */
ER ev3_speaker_play_file(const memfile_t *file, int32_t duration);
/* Stops what plays. */
ER ev3_speaker_stop(void);

#ifdef __cplusplus
}
#endif

#endif /* EV3API_SPEAKER_H */

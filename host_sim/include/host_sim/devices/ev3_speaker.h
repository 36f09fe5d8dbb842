/*
 * ev3_speaker.h — the EV3's speaker: eHRPWM0 output B through the audio
 * amplifier, enabled by GP6_15 (high = on).  Host only.
 *
 * What the speaker plays is the PWM output averaged over each sample
 * period of the recording (a box filter standing in for the amplifier's and
 * the speaker's low-pass): at a 64 kHz PCM carrier that is the duty cycle,
 * a tone's square wave keeps its edges.  A sample is the fraction of the
 * period the output was high, 0..32767, while the amplifier is on, and 0
 * while it is off.  The waveform's phase starts where its setting last
 * changed (the counter's own phase is not tracked).
 */
#ifndef HOST_SIM_DEVICES_EV3_SPEAKER_H
#define HOST_SIM_DEVICES_EV3_SPEAKER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "kernel.h"
#include "host_sim/board.h"
#include "host_sim/gpio.h"

#define EV3_SPEAKER_AMP_PIN   HS_GPIO(6, 15)
#define EV3_SPEAKER_RATE      32000U   /* recording sample rate, Hz */
#define EV3_SPEAKER_FULL      32767

/* The board device (listed in ev3_board_devices). */
extern const struct hs_device ev3_speaker_device;

/* Starts recording from now (dropping an earlier recording): E_OK, E_OBJ without a board. */
ER ev3_speaker_record(void);
/* The recording up to now: *samples (valid until the next call; after the
 * board shuts down, until the next boot), returns their number. */
size_t ev3_speaker_samples(const int16_t **samples);
/* A recording's consumer: takes n samples in order (a block of at most
 * EV3_SPEAKER_RATE, valid during the call). */
typedef void (*ev3_speaker_sink_t)(const int16_t *samples, size_t n, void *ctx);
/* Starts recording from now, as ev3_speaker_record, but streamed: every
 * second's samples go to sink as soon as they are rendered and only the
 * second being filled is held (an hour's recording is never in memory);
 * ev3_speaker_samples gives that unfinished second.  E_OK, E_OBJ without a
 * board. */
ER ev3_speaker_record_to(ev3_speaker_sink_t sink, void *ctx);
/* Renders up to now and hands the samples the sink has not had to it. */
void ev3_speaker_flush(void);
/* Whether the amplifier is on now. */
bool ev3_speaker_amp_on(void);

#endif /* HOST_SIM_DEVICES_EV3_SPEAKER_H */

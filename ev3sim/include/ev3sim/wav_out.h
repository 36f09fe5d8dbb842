/*
 * wav_out.h — `ev3sim run --audio`: what the speaker plays, streamed to a
 * 16-bit mono WAV file as the run goes (host_sim's ev3_speaker_record_to),
 * so that a run of an hour holds a second of it in memory, not 230 MB.
 * The header goes first with the largest sizes (what a reader of a stream
 * takes as "to the end"); the end writes the real sizes into it when the
 * file can seek (a FIFO cannot).  Host only.
 */
#ifndef EV3SIM_WAV_OUT_H
#define EV3SIM_WAV_OUT_H

#include <stddef.h>
#include "kernel.h"

/* Opens path (ev3sim_open_output's rules: a FIFO with no reader is refused)
 * and starts recording the speaker into it; call after the boot.  E_OK, or
 * E_SYS with "cannot write PATH: reason" in err. */
ER ev3sim_wav_begin(const char *path, char *err, size_t errlen);

/* Writes what was played up to now, the sizes, and closes the file; call
 * before the shutdown.  E_OK, or E_SYS with "cannot write PATH completely:
 * reason" in err if any write failed (a full disk, a reader gone). */
ER ev3sim_wav_end(char *err, size_t errlen);

#endif /* EV3SIM_WAV_OUT_H */

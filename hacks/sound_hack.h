/*
 * sound_hack.h — d_sound's interface on the RTOS: extended service calls
 * (function codes SOUND_FN_FIRST.. are d_sound's) and the configuration fragment that
 * defines them.  Plain TOPPERS C: applications and the api include it.
 *
 * SOUND_FN_WRITE is write() of one command (lms_sound.h); before a TONE or
 * PLAY it sets the status byte to BUSY, as LEGO's user space does through
 * its mapping, so that SOUND_FN_STATUS reads BUSY until the driver ends
 * the sound.
 *
 * Every call returns a TOPPERS code:
 *   E_PAR   an empty or too long command, or one the driver refuses; a level above 100
 *   E_MACV  a command buffer the calling task may not read
 *   E_CTX   called from non-task context
 *   E_OBJ   the driver is not loaded (its module_init failed)
 */
#ifndef EV3LX_SOUND_HACK_H
#define EV3LX_SOUND_HACK_H

#include "kernel.h"
#include "rtos_cfg.h"
#include "hack_interface.h"

/* The function codes this module owns: SOUND_FN_FIRST .. + SOUND_FN_COUNT - 1
 * (EV3LX_FNCD_BASE moves every module's range, -DSOUND_FN_FIRST=n this one; boot rejects ranges
 * that overlap another module's). */
#ifndef SOUND_FN_FIRST
#define SOUND_FN_FIRST (EV3LX_FNCD_BASE + 71)
#endif
#define SOUND_FN_COUNT 8
#define SOUND_FN_LAST  (SOUND_FN_FIRST + SOUND_FN_COUNT - 1)

#define SOUND_FN_WRITE    (SOUND_FN_FIRST + 0)  /* (const uint8_t *cmd, uint_t len): write(), returns its count */
#define SOUND_FN_STATUS   (SOUND_FN_FIRST + 1)  /* (): the status byte, LMS_SOUND_OK or LMS_SOUND_BUSY */
#define SOUND_FN_PLAY_PCM (SOUND_FN_FIRST + 2)  /* (const uint8_t *samples, uint_t len, uint_t level): PCM playback */

/* The rest needs the driver's ABI header: not for a configuration's names (cfg/ev3lx.cfg). */
#ifndef EV3LX_CFG_NAMES_ONLY
#include "lms_sound.h"
#define SOUND_MAX_COMMAND (1 + LMS_SOUND_SLOT_SAMPLES)

/* The DEF_SVC rows (INCLUDE it in the application's configuration). */
extern HACK_INTERFACE const struct rtos_cfg sound_hack_cfg;

/* Writes one command; returns what write() returned (bytes taken) or an error code. */
static inline ER_UINT sound_svc_write(const uint8_t *cmd, uint_t len)
{
	return cal_svc(SOUND_FN_WRITE, (intptr_t)cmd, (intptr_t)len, 0, 0, 0);
}

/*
 * Plays len unsigned 8-bit 8 kHz samples at level 0..100: PLAY, then the
 * samples written slot by slot (SERVICE) from a work item every 10 ms, as
 * LEGO's user space loops; returns at once.  The buffer must stay valid
 * until the status is OK again (the end, an underrun, or any other command,
 * which also stops the feeding).
 */
static inline ER sound_svc_play_pcm(const uint8_t *samples, uint_t len, uint_t level)
{
	return (ER)cal_svc(SOUND_FN_PLAY_PCM, (intptr_t)samples, (intptr_t)len, (intptr_t)level, 0, 0);
}

/* The status byte: LMS_SOUND_BUSY while a sound plays, else LMS_SOUND_OK. */
static inline ER_UINT sound_svc_status(void)
{
	return cal_svc(SOUND_FN_STATUS, 0, 0, 0, 0, 0);
}

#endif /* EV3LX_CFG_NAMES_ONLY */
#endif /* EV3LX_SOUND_HACK_H */

/*
 * sound_svc.c — d_sound's interface on the RTOS: the module's extended
 * service calls (sound_hack.h) and its configuration fragment.  Commands reach
 * the driver through its write(), so its own checks guard them; the status
 * byte is read through the driver's mmap.
 * The driver is in sound_hack.c.
 */
#include "hack_svc.h"
#include "sound_hack.h"
#include "sound_module.h"

static ER sound_hack_check(void)
{
	if (sns_ctx())
		return E_CTX;
	return sound_file ? E_OK : E_OBJ;
}

/* SOUND_FN_WRITE: write() of one command, BUSY set first for TONE and PLAY. */
ER_UINT svc_sound_write(intptr_t cmd, intptr_t len, intptr_t p3, intptr_t p4,
			       intptr_t p5, ID cdmid)
{
	const u8 __user *buf = (const u8 __user *)cmd;
	ssize_t ret;
	u8 op;
	ER ercd = sound_hack_check();

	if (ercd != E_OK)
		return ercd;
	if (len <= 0 || len > SOUND_MAX_COMMAND)
		return E_PAR;
	if (get_user(op, buf))
		return E_MACV;
	cancel_delayed_work_sync(&feeder.work);	/* a new command replaces a buffer's playback */
	if (op == LMS_SOUND_TONE || op == LMS_SOUND_PLAY)
		sound_status[0] = LMS_SOUND_BUSY;
	ret = lx_dev_write(sound_file, (const char __user *)buf, (size_t)len, NULL);
	if (ret < 0) {
		if (op == LMS_SOUND_TONE || op == LMS_SOUND_PLAY)
			sound_status[0] = LMS_SOUND_OK;
		return lx_errno_to_er(ret);
	}
	return (ER_UINT)ret;
}

/* SOUND_FN_PLAY_PCM: PLAY at level, then the buffer's samples fed slot by slot. */
ER_UINT svc_sound_play_pcm(intptr_t samples, intptr_t len, intptr_t level, intptr_t p4,
				 intptr_t p5, ID cdmid)
{
	u8 play[2] = { LMS_SOUND_PLAY, (u8)level };
	loff_t off = 0;
	ssize_t ret;
	ER ercd = sound_hack_check();

	if (ercd != E_OK)
		return ercd;
	if (len <= 0 || level < 0 || level > LMS_SOUND_MAX_LEVEL)
		return E_PAR;
	if (prb_mem((const void *)samples, (SIZE)len, TSK_SELF, TPM_READ) != E_OK)
		return E_MACV;
	cancel_delayed_work_sync(&feeder.work);
	sound_status[0] = LMS_SOUND_BUSY;
	ret = kernel_write(sound_file, play, sizeof(play), &off);
	if (ret < 0) {
		sound_status[0] = LMS_SOUND_OK;
		return lx_errno_to_er(ret);
	}
	feeder.data = (const u8 *)samples;
	feeder.len = (size_t)len;
	feeder.pos = 0;
	sound_feed(&feeder.work.work);
	return E_OK;
}

/* SOUND_FN_STATUS: the status byte. */
ER_UINT svc_sound_status(intptr_t p1, intptr_t p2, intptr_t p3, intptr_t p4,
				intptr_t p5, ID cdmid)
{
	ER ercd = sound_hack_check();

	return ercd != E_OK ? ercd : (ER_UINT)READ_ONCE(sound_status[0]);
}

static const struct rtos_svc_cfg sound_svcs[] = {
	{ SOUND_FN_WRITE,  svc_sound_write,  1024 },
	{ SOUND_FN_STATUS, svc_sound_status, 256 },
	{ SOUND_FN_PLAY_PCM, svc_sound_play_pcm, 1024 },
};

const struct rtos_cfg sound_hack_cfg = {
	.name = "sound_hack",
	.svcs = RTOS_TABLE(sound_svcs),
	.svc_first = SOUND_FN_FIRST, .svc_count = SOUND_FN_COUNT,
};

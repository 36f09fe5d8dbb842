/*
 * sound_hack.c — d_sound on the RTOS: the Linux driver source included
 * byte-for-byte, then its interface as extended service calls
 * (sound_hack.h).  Commands reach the driver through its write(), so its
 * own checks guard them; the status byte is read through the driver's mmap.
 */
#define KBUILD_MODNAME "d_sound"
#include "driver_common.h"

/* Renames: the driver's module_init/exit become plain pointers, called by ours below. */
#pragma push_macro("module_init")
#pragma push_macro("module_exit")
#undef module_init
#undef module_exit
#define module_init(fn) static int (*const sound_driver_init)(void) = fn
#define module_exit(fn) static void (*const sound_driver_exit)(void) = fn

#include "d_sound.c"

#undef module_init
#undef module_exit
#pragma pop_macro("module_init")
#pragma pop_macro("module_exit")

#include <linux/workqueue.h>
#include "sound_hack.h"

#define FEED_PERIOD_MS	10	/* the three slots hold 94.5 ms of samples */

static struct file *sound_file;		/* /dev/lms_sound */
static volatile u8 *sound_status;	/* byte 0 of its mapping */

/* PCM playback of a caller's buffer: SERVICE writes from a work item, as LEGO's user space loops. */
static struct {
	const u8 *data;
	size_t len, pos;
	struct delayed_work work;
} feeder;

/* Queues samples while the driver has free slots; again in FEED_PERIOD_MS while playing. */
static void sound_feed(struct work_struct *work)
{
	u8 cmd[SOUND_MAX_COMMAND];
	loff_t off = 0;

	while (feeder.pos < feeder.len && READ_ONCE(sound_status[0]) == LMS_SOUND_BUSY) {
		size_t n = min_t(size_t, feeder.len - feeder.pos, LMS_SOUND_SLOT_SAMPLES);
		ssize_t ret;

		cmd[0] = LMS_SOUND_SERVICE;
		memcpy(cmd + 1, feeder.data + feeder.pos, n);
		ret = kernel_write(sound_file, cmd, n + 1, &off);
		if (ret <= 0)
			break;		/* every slot full */
		feeder.pos += ret;
	}
	if (feeder.pos < feeder.len && READ_ONCE(sound_status[0]) == LMS_SOUND_BUSY)
		schedule_delayed_work(&feeder.work, msecs_to_jiffies(FEED_PERIOD_MS));
}

/* Loads d_sound, then opens its device and maps the status page. */
static int __init sound_hack_init(void)
{
	void *map;
	int ret;

	sound_file = NULL;
	sound_status = NULL;
	INIT_DELAYED_WORK(&feeder.work, sound_feed);
	feeder.data = NULL;
	feeder.len = feeder.pos = 0;
	ret = sound_driver_init();
	if (ret)
		return ret;
	ret = lx_dev_open("/dev/" LMS_SOUND_DEVICE_NAME, O_RDWR, &sound_file);
	if (!ret)
		ret = lx_dev_mmap(sound_file, LMS_SOUND_MAP_SIZE, &map);
	if (ret) {
		pr_err("sound_hack: cannot open d_sound's device (%d)\n", ret);
		lx_dev_close(sound_file);
		sound_file = NULL;
		sound_driver_exit();
		return ret;
	}
	sound_status = map;
	return 0;
}
module_init(sound_hack_init);

/* Closes the device (the service calls then answer E_OBJ) and unloads d_sound. */
static void __exit sound_hack_exit(void)
{
	struct file *file = sound_file;

	cancel_delayed_work_sync(&feeder.work);
	WRITE_ONCE(sound_file, NULL);
	sound_status = NULL;
	lx_dev_close(file);
	sound_driver_exit();
}
module_exit(sound_hack_exit);

static ER sound_hack_check(void)
{
	if (sns_ctx())
		return E_CTX;
	return sound_file ? E_OK : E_OBJ;
}

/* SOUND_FN_WRITE: write() of one command, BUSY set first for TONE and PLAY. */
static ER_UINT svc_sound_write(intptr_t cmd, intptr_t len, intptr_t p3, intptr_t p4,
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
static ER_UINT svc_sound_play_pcm(intptr_t samples, intptr_t len, intptr_t level, intptr_t p4,
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
static ER_UINT svc_sound_status(intptr_t p1, intptr_t p2, intptr_t p3, intptr_t p4,
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

/*
 * sound_hack.c — d_sound on the RTOS (the paper's Fig. 5 pattern): the Linux
 * driver source included byte-for-byte, then the module's Linux side: its init and
 * exit, the device it opens and maps, and the work item that feeds a
 * buffer's samples to the driver
 * (sound_module.h).  Only Linux headers: the service calls and the
 * configuration fragment are sound_svc.c.
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
#include "sound_module.h"

#define FEED_PERIOD_MS	10	/* the three slots hold 94.5 ms of samples */

struct file *sound_file;		/* /dev/lms_sound */
volatile u8 *sound_status;	/* byte 0 of its mapping */

struct sound_feeder feeder;

/* Queues samples while the driver has free slots; again in FEED_PERIOD_MS while playing. */
void sound_feed(struct work_struct *work)
{
	u8 cmd[1 + LMS_SOUND_SLOT_SAMPLES];
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

/*
 * sound_module.h — what the d_sound module shares between its two translation
 * units: the hack file (sound_hack.c, with the driver) defines it, the service
 * calls (sound_svc.c) use it.  Linux types only; hidden in the module.
 */
#ifndef EV3LX_SOUND_MODULE_H
#define EV3LX_SOUND_MODULE_H

#include <linux/types.h>
#include <linux/fs.h>
#include <linux/workqueue.h>
#include "lms_sound.h"

/* PCM playback of a caller's buffer: SERVICE writes from a work item, as LEGO's user space loops. */
struct sound_feeder {
	const u8 *data;
	size_t len, pos;
	struct delayed_work work;
};

extern struct file *sound_file;		/* /dev/lms_sound, NULL while d_sound is not up */
extern volatile u8 *sound_status;	/* byte 0 of its mapping */
extern struct sound_feeder feeder;

/* The feeder's work: queues samples while the driver has free slots, again later while playing. */
void sound_feed(struct work_struct *work);

#endif /* EV3LX_SOUND_MODULE_H */

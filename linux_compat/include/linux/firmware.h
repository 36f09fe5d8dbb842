/*
 * linux/firmware.h — request_firmware / release_firmware (Linux's
 * drivers/base/firmware_loader), served from a table of blobs the board or
 * a hack registers with lx_firmware_add (linux_compat/firmware.h) instead of
 * files under /lib/firmware.  A name not in the table fails with -ENOENT and
 * the message Linux prints for a missing file.
 */
#ifndef _LINUX_FIRMWARE_H
#define _LINUX_FIRMWARE_H

#include <linux/types.h>

struct device;

struct firmware {
	size_t size;
	const u8 *data;
	void *priv;		/* the table entry it came from */
};

/* The registered blob name as *fw (its data not copied: the table's); 0,
 * -ENOENT (not registered, logged), -EINVAL (no fw or name) or -ENOMEM. */
int request_firmware(const struct firmware **fw, const char *name, struct device *device);
/* As request_firmware, without the message when the name is not registered. */
int firmware_request_nowarn(const struct firmware **fw, const char *name, struct device *device);
/* Gives back what request_firmware returned (NULL is ignored). */
void release_firmware(const struct firmware *fw);

#endif

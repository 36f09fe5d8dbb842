/*
 * linux_compat/firmware.h — the firmware table request_firmware serves
 * (linux/firmware.h): the board or a hack registers each blob under the
 * file name its driver asks for.
 */
#ifndef _LINUX_COMPAT_FIRMWARE_H
#define _LINUX_COMPAT_FIRMWARE_H

#include <linux/types.h>

/* Registers size bytes at data (kept by the caller while registered) as
 * firmware name (copied up to LX_FIRMWARE_NAME_MAX - 1 characters).
 * 0, -EEXIST (name taken), -ENOSPC (table full) or -EINVAL. */
int lx_firmware_add(const char *name, const void *data, size_t size);
/* Removes name from the table: 0, -ENOENT, or -EBUSY while a driver holds it. */
int lx_firmware_remove(const char *name);

#define LX_FIRMWARE_NAME_MAX	48
#define LX_FIRMWARE_ENTRIES	8

#endif

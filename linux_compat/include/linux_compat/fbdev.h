/*
 * linux_compat/fbdev.h — what stands in for the MMU under a frame buffer
 * mapping.  On Linux, deferred I/O write-protects the pages of the mapping:
 * the first store to a page after an update faults (page_mkwrite), which
 * lists the page and schedules the driver's deferred_io.  Without an MMU
 * nothing traps the store, so whoever writes through the pointer
 * lx_dev_mmap returned reports it, and linux_compat then does what the fault
 * handler does.
 */
#ifndef _LINUX_COMPAT_FBDEV_H
#define _LINUX_COMPAT_FBDEV_H

#include <linux/fs.h>
#include <linux/types.h>

/* Reports a write of len bytes at offset of the frame memory mapped from
 * file (/dev/fbN): 0 (also when the driver has no deferred I/O, whose
 * memory is the display), -EBADF (not a frame buffer file), -EINVAL (range
 * outside the frame memory).  Process context. */
int lx_fb_mmap_written(struct file *file, unsigned long offset, size_t len);

/* true if file is an open /dev/fbN (fbmem.c). */
bool lx_fb_file(struct file *file);

#endif /* _LINUX_COMPAT_FBDEV_H */

/*
 * linux/fb.h — the frame buffer subsystem as Linux 6.1 defines it for
 * drivers, with the user-space ABI of uapi/linux/fb.h (screen info
 * structures and the FBIO* ioctls), implemented by linux_compat/src/fbmem.c
 * and fb_defio.c.
 *
 * register_framebuffer adds /dev/fbN (major 29, minor N, the lowest free
 * of FB_MAX); its file operations are fbmem's: open/release call fb_open/
 * fb_release, read/write call the driver's fb_read/fb_write or copy from/to
 * screen_buffer (fb_sys_read/fb_sys_write), ioctl answers FBIOGET_VSCREENINFO,
 * FBIOPUT_VSCREENINFO (through fb_check_var/fb_set_par), FBIOGET_FSCREENINFO,
 * FBIOBLANK and passes the others to fb_ioctl (-ENOTTY without one), mmap
 * maps the frame memory (fb_mmap if the driver has one).  With deferred I/O
 * (info->fbdefio and fb_deferred_io_init), the first write to a page of the
 * mapping after an update schedules the driver's deferred_io after
 * fbdefio->delay jiffies with the written pages; see linux_compat/fbdev.h for
 * how a write through the mapping is reported without an MMU.
 */
#ifndef _LINUX_FB_H
#define _LINUX_FB_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux/device.h>
#include <linux/fs.h>
#include <linux/ioctl.h>
#include <linux/list.h>
#include <linux/mm_types.h>
#include <linux/module.h>
#include <linux/mutex.h>
#include <linux/workqueue.h>

/* ---- the user-space ABI (uapi/linux/fb.h) ---- */

#define FB_MAX			32
#define FBIOGET_VSCREENINFO	0x4600
#define FBIOPUT_VSCREENINFO	0x4601
#define FBIOGET_FSCREENINFO	0x4602
#define FBIOPAN_DISPLAY		0x4606
#define FBIOBLANK		0x4611

#define FB_TYPE_PACKED_PIXELS	0
#define FB_VISUAL_MONO01	0
#define FB_VISUAL_MONO10	1
#define FB_VISUAL_TRUECOLOR	2
#define FB_VISUAL_PSEUDOCOLOR	3
#define FB_ACCEL_NONE		0
#define FB_ACTIVATE_NOW		0

#define FB_BLANK_UNBLANK	0
#define FB_BLANK_NORMAL		1
#define FB_BLANK_POWERDOWN	4

struct fb_fix_screeninfo {
	char id[16];
	unsigned long smem_start;
	__u32 smem_len;
	__u32 type;
	__u32 type_aux;
	__u32 visual;
	__u16 xpanstep;
	__u16 ypanstep;
	__u16 ywrapstep;
	__u32 line_length;
	unsigned long mmio_start;
	__u32 mmio_len;
	__u32 accel;
	__u16 capabilities;
	__u16 reserved[2];
};

struct fb_bitfield {
	__u32 offset;
	__u32 length;
	__u32 msb_right;
};

struct fb_var_screeninfo {
	__u32 xres;
	__u32 yres;
	__u32 xres_virtual;
	__u32 yres_virtual;
	__u32 xoffset;
	__u32 yoffset;
	__u32 bits_per_pixel;
	__u32 grayscale;
	struct fb_bitfield red;
	struct fb_bitfield green;
	struct fb_bitfield blue;
	struct fb_bitfield transp;
	__u32 nonstd;
	__u32 activate;
	__u32 height;
	__u32 width;
	__u32 accel_flags;
	__u32 pixclock;
	__u32 left_margin;
	__u32 right_margin;
	__u32 upper_margin;
	__u32 lower_margin;
	__u32 hsync_len;
	__u32 vsync_len;
	__u32 sync;
	__u32 vmode;
	__u32 rotate;
	__u32 colorspace;
	__u32 reserved[4];
};

/* ---- the driver side ---- */

struct fb_info;

struct fb_ops {
	struct module *owner;
	int (*fb_open)(struct fb_info *info, int user);
	int (*fb_release)(struct fb_info *info, int user);
	ssize_t (*fb_read)(struct fb_info *info, char __user *buf, size_t count, loff_t *ppos);
	ssize_t (*fb_write)(struct fb_info *info, const char __user *buf, size_t count, loff_t *ppos);
	int (*fb_check_var)(struct fb_var_screeninfo *var, struct fb_info *info);
	int (*fb_set_par)(struct fb_info *info);
	int (*fb_setcolreg)(unsigned int regno, unsigned int red, unsigned int green, unsigned int blue,
			    unsigned int transp, struct fb_info *info);
	int (*fb_blank)(int blank, struct fb_info *info);
	int (*fb_pan_display)(struct fb_var_screeninfo *var, struct fb_info *info);
	int (*fb_ioctl)(struct fb_info *info, unsigned int cmd, unsigned long arg);
	int (*fb_mmap)(struct fb_info *info, struct vm_area_struct *vma);
	void (*fb_destroy)(struct fb_info *info);
};

/* A page of the mapping written since the last deferred_io call. */
struct fb_deferred_io_pageref {
	struct page *page;
	unsigned long offset;           /* in the frame memory, page-aligned */
	struct list_head list;
};

struct fb_deferred_io {
	unsigned long delay;            /* jiffies from the first write to deferred_io */
	bool sort_pagereflist;
	struct mutex lock;
	struct list_head pagereflist;
	void (*first_io)(struct fb_info *info);
	void (*deferred_io)(struct fb_info *info, struct list_head *pagelist);
};

#define FBINFO_DEFAULT		0
#define FBINFO_VIRTFB		0x0004

struct fb_info {
	int node;                       /* N of /dev/fbN, -1 while unregistered */
	int flags;
	struct mutex lock;              /* held around ioctl and open/release */
	struct fb_var_screeninfo var;
	struct fb_fix_screeninfo fix;
	const struct fb_ops *fbops;
	struct device *device;
	struct fb_deferred_io *fbdefio;
	struct delayed_work deferred_work;
	struct fb_deferred_io_pageref *pagerefs;
	unsigned long npagerefs;
	union {
		char __iomem *screen_base;
		char *screen_buffer;
	};
	unsigned long screen_size;
	void *pseudo_palette;
	void *par;
	int lx_open_count;              /* ev3lx: opens, for unregister_framebuffer's check */
};

/* An fb_info with size bytes of driver data at info->par (zeroed), or NULL. */
struct fb_info *framebuffer_alloc(size_t size, struct device *dev);
/* Frees an fb_info from framebuffer_alloc (NULL is fine). */
void framebuffer_release(struct fb_info *info);
/* Adds /dev/fbN for info (see above): 0, -EINVAL, -ENXIO (FB_MAX taken), -ENOMEM, -EBUSY. */
int register_framebuffer(struct fb_info *fb_info);
/* Removes /dev/fbN; open files keep working on the fb_info until closed. */
void unregister_framebuffer(struct fb_info *fb_info);

/* Copies between user memory and screen_buffer at *ppos: bytes copied, 0 at the end, -EFAULT, -EFBIG. */
ssize_t fb_sys_read(struct fb_info *info, char __user *buf, size_t count, loff_t *ppos);
ssize_t fb_sys_write(struct fb_info *info, const char __user *buf, size_t count, loff_t *ppos);

/* Deferred I/O: sets up the page list and the delayed work (0 or -ENOMEM); cleanup flushes and frees it. */
int fb_deferred_io_init(struct fb_info *info);
void fb_deferred_io_cleanup(struct fb_info *info);
/* The deferred-I/O mmap (what fbmem uses when fbdefio is set). */
int fb_deferred_io_mmap(struct fb_info *info, struct vm_area_struct *vma);

#endif /* _LINUX_FB_H */

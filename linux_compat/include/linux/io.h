/* linux/io.h — memory-mapped I/O (asm/io.h) and the devres-free helpers. */
#ifndef _LINUX_IO_H
#define _LINUX_IO_H

#include <linux/types.h>
#include <linux/sizes.h>
#include <asm/io.h>
#include <asm/page.h>

#endif /* _LINUX_IO_H */

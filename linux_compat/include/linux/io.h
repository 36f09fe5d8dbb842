/* linux/io.h — memory-mapped I/O (asm/io.h) and devm_ioremap. */
#ifndef _LINUX_IO_H
#define _LINUX_IO_H

#include <linux/types.h>
#include <linux/sizes.h>
#include <asm/io.h>
#include <asm/page.h>

#include <linux/err.h>

struct device;

/* An error number as an __iomem pointer (IS_ERR/PTR_ERR read it back). */
#define IOMEM_ERR_PTR(err)	((__force void __iomem *)ERR_PTR(err))

/* Maps [offset, offset + size) for dev, unmapped when its driver unbinds
 * (linux_compat/src/devres.c); NULL on failure. */
void __iomem *devm_ioremap(struct device *dev, resource_size_t offset, resource_size_t size);

#endif /* _LINUX_IO_H */

/*
 * linux/nvmem-consumer.h — non-volatile memory cells as a kernel built
 * without CONFIG_NVMEM has them (Linux 6.1's include/linux/nvmem-consumer.h,
 * its !CONFIG_NVMEM branch): there is no provider, so every lookup and read
 * fails with -EOPNOTSUPP and a driver that needs a cell (the EV3's hardware
 * ID in its EEPROM) fails its probe with that error, as on such a kernel.
 */
#ifndef _LINUX_NVMEM_CONSUMER_H
#define _LINUX_NVMEM_CONSUMER_H

#include <linux/device.h>
#include <linux/err.h>
#include <linux/errno.h>

struct nvmem_cell;
struct nvmem_device;

static inline struct nvmem_cell *nvmem_cell_get(struct device *dev, const char *id)
{
	return ERR_PTR(-EOPNOTSUPP);
}
static inline struct nvmem_cell *devm_nvmem_cell_get(struct device *dev, const char *id)
{
	return ERR_PTR(-EOPNOTSUPP);
}
static inline void nvmem_cell_put(struct nvmem_cell *cell) { }
static inline void devm_nvmem_cell_put(struct device *dev, struct nvmem_cell *cell) { }
static inline void *nvmem_cell_read(struct nvmem_cell *cell, size_t *len)
{
	return ERR_PTR(-EOPNOTSUPP);
}
static inline int nvmem_cell_write(struct nvmem_cell *cell, void *buf, size_t len) { return -EOPNOTSUPP; }
static inline int nvmem_cell_read_u8(struct device *dev, const char *cell_id, u8 *val) { return -EOPNOTSUPP; }
static inline int nvmem_cell_read_u16(struct device *dev, const char *cell_id, u16 *val) { return -EOPNOTSUPP; }
static inline int nvmem_cell_read_u32(struct device *dev, const char *cell_id, u32 *val) { return -EOPNOTSUPP; }
static inline struct nvmem_device *nvmem_device_get(struct device *dev, const char *name)
{
	return ERR_PTR(-EOPNOTSUPP);
}
static inline void nvmem_device_put(struct nvmem_device *nvmem) { }

#endif /* _LINUX_NVMEM_CONSUMER_H */

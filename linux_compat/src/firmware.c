/*
 * firmware.c — request_firmware from the board's firmware table
 * (linux/firmware.h, linux_compat/firmware.h).
 */
#include <linux/firmware.h>
#include <linux/device.h>
#include <linux/errno.h>
#include <linux/slab.h>
#include <linux/string.h>
#include <linux/printk.h>
#include <linux_compat/firmware.h>

struct fw_entry {
	char name[LX_FIRMWARE_NAME_MAX];
	const void *data;
	size_t size;
	unsigned int users;
};

static struct fw_entry fw_table[LX_FIRMWARE_ENTRIES];

/* The table entry registered as name, or NULL. */
static struct fw_entry *fw_find(const char *name)
{
	for (unsigned int i = 0; i < LX_FIRMWARE_ENTRIES; i++)
		if (fw_table[i].data && !strcmp(fw_table[i].name, name))
			return &fw_table[i];
	return NULL;
}

int lx_firmware_add(const char *name, const void *data, size_t size)
{
	if (!name || !*name || !data)
		return -EINVAL;
	if (fw_find(name))
		return -EEXIST;
	for (unsigned int i = 0; i < LX_FIRMWARE_ENTRIES; i++) {
		struct fw_entry *e = &fw_table[i];

		if (e->data)
			continue;
		strscpy(e->name, name, sizeof(e->name));
		e->data = data;
		e->size = size;
		e->users = 0;
		return 0;
	}
	return -ENOSPC;
}

int lx_firmware_remove(const char *name)
{
	struct fw_entry *e = name ? fw_find(name) : NULL;

	if (!e)
		return -ENOENT;
	if (e->users)
		return -EBUSY;
	memset(e, 0, sizeof(*e));
	return 0;
}

/* request_firmware's work; warn says whether a missing name is logged. */
static int fw_request(const struct firmware **fw, const char *name, struct device *device, bool warn)
{
	struct fw_entry *e;
	struct firmware *f;

	if (!fw)
		return -EINVAL;
	*fw = NULL;
	if (!name || !*name)
		return -EINVAL;
	e = fw_find(name);
	if (!e) {
		if (warn) {
			if (device)
				dev_warn(device, "Direct firmware load for %s failed with error %d\n", name, -ENOENT);
			else
				pr_warn("Direct firmware load for %s failed with error %d\n", name, -ENOENT);
		}
		return -ENOENT;
	}
	f = kzalloc(sizeof(*f), GFP_KERNEL);
	if (!f)
		return -ENOMEM;
	f->size = e->size;
	f->data = e->data;
	f->priv = e;
	e->users++;
	*fw = f;
	return 0;
}

int request_firmware(const struct firmware **fw, const char *name, struct device *device)
{
	return fw_request(fw, name, device, true);
}

int firmware_request_nowarn(const struct firmware **fw, const char *name, struct device *device)
{
	return fw_request(fw, name, device, false);
}

void release_firmware(const struct firmware *fw)
{
	struct fw_entry *e;

	if (!fw)
		return;
	e = fw->priv;
	if (e && e->users)
		e->users--;
	kfree(fw);
}

/*
 * test_io.c — I/O memory: ioremap windows from the register model, every
 * accessor reaching the model with exactly its width and value, the SYSCFG
 * windows set at boot, and request_mem_region's overlap rules.
 */
#include "lx_test.h"
#include "fake_mmio.h"
#include <linux/io.h>
#include <linux/ioport.h>
#include <mach/da8xx.h>
#include <mach/hardware.h>

static bool last_access(unsigned width, bool write, uint32_t offset, uint32_t value)
{
	const struct fake_access *a;

	if (fake.nlog == 0)
		return false;
	a = &fake.log[fake.nlog - 1];
	return a->block == FAKE_DEV && a->width == width && a->write == write &&
	       a->offset == offset && a->value == value;
}

static void test_accessors(void)
{
	u8 __iomem *regs = ioremap(FAKE_DEV_PHYS, 0x100);
	u8 bytes[4];

	ok(regs == (void *)fake.mem[FAKE_DEV], "ioremap returns the model's window");
	ok(ioremap_nocache(FAKE_DEV_PHYS + 0x40, 4) == (void *)(fake.mem[FAKE_DEV] + 0x40),
	   "ioremap_nocache of a sub-range");
	ok(ioremap(0x12345000, 0x10) == NULL, "ioremap of an unmodelled range: NULL");
	ok(ioremap(FAKE_DEV_PHYS, 0) == NULL, "ioremap of nothing: NULL");

	iowrite32(0x11223344, regs + 0x10);
	ok(last_access(4, true, 0x10, 0x11223344), "iowrite32: one 32-bit write");
	is_int(ioread8(regs + 0x10), 0x44, "ioread8 reads the low byte (little-endian)");
	ok(last_access(1, false, 0x10, 0x44), "ioread8: one 8-bit read");
	is_int(ioread16(regs + 0x12), 0x1122, "ioread16 at +2");
	ok(last_access(2, false, 0x12, 0x1122), "ioread16: one 16-bit read");
	is_u64(ioread32(regs + 0x10), 0x11223344, "ioread32");
	ok(last_access(4, false, 0x10, 0x11223344), "ioread32: one 32-bit read");
	iowrite16(0xbeef, regs + 0x20);
	ok(last_access(2, true, 0x20, 0xbeef), "iowrite16: one 16-bit write");
	iowrite8(0x5a, regs + 0x23);
	ok(last_access(1, true, 0x23, 0x5a), "iowrite8: one 8-bit write");

	writel(0xcafef00d, regs + 0x30);
	ok(last_access(4, true, 0x30, 0xcafef00d), "writel");
	is_u64(readl(regs + 0x30), 0xcafef00d, "readl");
	writew(0x1234, regs + 0x34);
	ok(last_access(2, true, 0x34, 0x1234), "writew");
	is_int(readw(regs + 0x34), 0x1234, "readw");
	ok(last_access(2, false, 0x34, 0x1234), "readw width");
	writeb(0x77, regs + 0x36);
	ok(last_access(1, true, 0x36, 0x77), "writeb");
	is_int(readb(regs + 0x36), 0x77, "readb");
	writel_relaxed(1, regs + 0x38);
	ok(last_access(4, true, 0x38, 1), "writel_relaxed");
	is_int(readl_relaxed(regs + 0x38), 1, "readl_relaxed");
	__raw_writel(2, regs + 0x38);
	ok(last_access(4, true, 0x38, 2), "__raw_writel");
	__raw_writew(3, regs + 0x3c);
	ok(last_access(2, true, 0x3c, 3), "__raw_writew");
	__raw_writeb(4, regs + 0x3e);
	ok(last_access(1, true, 0x3e, 4), "__raw_writeb");
	is_int(__raw_readl(regs + 0x38) + __raw_readw(regs + 0x3c) + __raw_readb(regs + 0x3e), 9,
	       "__raw_readl/w/b");

	fake.nlog = 0;
	memcpy_toio(regs + 0x40, "\x01\x02\x03\x04", 4);
	ok(fake.nlog == 4 && fake.log[3].width == 1 && fake.log[3].offset == 0x43 && fake.log[3].value == 4,
	   "memcpy_toio: byte accesses");
	memcpy_fromio(bytes, regs + 0x40, 4);
	ok(memcmp(bytes, "\x01\x02\x03\x04", 4) == 0, "memcpy_fromio");
	memset_io(regs + 0x40, 0, 4);
	is_u64(ioread32(regs + 0x40), 0, "memset_io");
	iounmap(regs);

	ok(da8xx_syscfg0_base == (void *)fake.mem[FAKE_SYSCFG0], "da8xx_syscfg0_base mapped at boot");
	ok(da8xx_syscfg1_base == (void *)fake.mem[FAKE_SYSCFG1], "da8xx_syscfg1_base mapped at boot");
	writel(0x83e70b13, DA8XX_SYSCFG0_VIRT(DA8XX_KICK0_REG));
	ok(fake.log[fake.nlog - 1].block == FAKE_SYSCFG0 && fake.log[fake.nlog - 1].offset == 0x38,
	   "DA8XX_SYSCFG0_VIRT(KICK0) reaches SYSCFG0 + 0x38");
	ok(IO_ADDRESS(FAKE_DEV_PHYS + 8) == (unsigned long)(uintptr_t)(fake.mem[FAKE_DEV] + 8),
	   "IO_ADDRESS gives the window address");
}

static void test_regions(void)
{
	struct resource *a, *b;

	a = request_mem_region(DA8XX_GPIO_BASE, 0xd8, "d_pwm");
	ok(a != NULL, "request_mem_region claims a free range");
	ok(a && a->start == DA8XX_GPIO_BASE && a->end == DA8XX_GPIO_BASE + 0xd7 && resource_size(a) == 0xd8,
	   "with Linux's inclusive end");
	ok(a && strcmp(a->name, "d_pwm") == 0 && (a->flags & IORESOURCE_MEM) && (a->flags & IORESOURCE_BUSY),
	   "name and flags");
	ok(request_mem_region(DA8XX_GPIO_BASE, 0xd8, "d_analog") == NULL,
	   "the same range again: NULL (LEGO's second and third claims)");
	ok(request_mem_region(DA8XX_GPIO_BASE + 0xd7, 1, "x") == NULL, "overlapping the last byte: NULL");
	ok(request_mem_region(DA8XX_GPIO_BASE - 0x10, 0x11, "x") == NULL, "overlapping the first byte: NULL");
	ok(request_mem_region(DA8XX_GPIO_BASE + 0x10, 0x10, "x") == NULL, "inside: NULL");
	ok(request_mem_region(DA8XX_GPIO_BASE - 0x100, 0x1000, "x") == NULL, "covering it: NULL");
	b = request_mem_region(DA8XX_GPIO_BASE + 0xd8, 0x28, "next");
	ok(b != NULL, "the adjacent range is free");
	ok(request_mem_region(DA8XX_GPIO_BASE - 0x10, 0x10, "before") != NULL, "and the one just before");
	ok(request_mem_region(0x1000, 0, "empty") == NULL, "an empty range: NULL");
	ok(request_region(0x100, 8, "port") != NULL, "port regions are a separate tree");
	release_mem_region(DA8XX_GPIO_BASE, 0xd8);
	a = request_mem_region(DA8XX_GPIO_BASE, 0xd8, "d_analog");
	ok(a != NULL, "after release_mem_region the range can be claimed again");
	rtos_host_expect_bugs(true);
	release_mem_region(0x2000, 0x10);
	rtos_host_expect_bugs(false);
	ok(strstr(rtos_host_last_bug(), "nonexistent resource") != NULL, "releasing an unclaimed range warns");
}

static void test_regions_after_reboot(void)
{
	ok(request_mem_region(DA8XX_GPIO_BASE, 0xd8, "d_pwm") != NULL, "a new boot forgets the old claims");
}

int main(void)
{
	tap_plan(51);
	fake_mmio_install();
	ok(lx_test_run(test_accessors), "accessor task ran");
	ok(lx_test_run(test_regions), "region task ran");
	ok(lx_test_run(test_regions_after_reboot), "reboot task ran");
	rtos_host_set_mmio_handler(NULL);
	return tap_done();
}

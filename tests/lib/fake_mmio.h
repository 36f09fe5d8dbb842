/*
 * fake_mmio.h — a small register model for linux_compat's own tests (the
 * full AM1808 model is host_sim's).  Installed with
 * rtos_host_set_mmio_handler before rtos_host_boot, it serves:
 *   - the GPIO block at DA8XX_GPIO_BASE with DaVinci semantics: SET/CLR_DATA
 *     act on OUT_DATA, IN_DATA reads fake_gpio_in, SET/CLR_RIS/FAL_TRIG
 *     keep trigger masks, INTSTAT is write-1-to-clear, and fake_gpio_edge()
 *     latches an enabled edge and raises the bank line if BINTEN allows;
 *   - SYSCFG0/SYSCFG1 and a plain "device" block at FAKE_DEV_PHYS.
 * Every access is logged with its block, offset, width and value.
 */
#ifndef EV3LX_TESTS_FAKE_MMIO_H
#define EV3LX_TESTS_FAKE_MMIO_H

#include <stdbool.h>
#include <stdint.h>
#include <string.h>
#include "rtos_host.h"
#include "host_sim/gpio.h"

#define FAKE_DEV_PHYS		0x01f0d000UL
#define FAKE_BLOCK_SIZE		0x1000U
#define FAKE_LOG_MAX		512U

enum fake_block_id { FAKE_GPIO, FAKE_SYSCFG0, FAKE_SYSCFG1, FAKE_DEV, FAKE_NBLOCKS };

struct fake_access {
	enum fake_block_id block;
	uint32_t offset;
	unsigned width;
	bool write;
	uint32_t value;
};

struct fake_mmio {
	uint8_t mem[FAKE_NBLOCKS][FAKE_BLOCK_SIZE] __attribute__((aligned(8)));
	uint32_t gpio_in[5];        /* IN_DATA per bank pair */
	uint32_t rising[5], falling[5];
	struct fake_access log[FAKE_LOG_MAX];
	unsigned nlog;
};

static struct fake_mmio fake;

static const uintptr_t fake_phys[FAKE_NBLOCKS] = {
	0x01e26000UL, 0x01c14000UL, 0x01e2c000UL, FAKE_DEV_PHYS,
};

static inline int fake_block_of(const volatile void *addr, uint32_t *offset)
{
	uintptr_t a = (uintptr_t)addr;

	for (int b = 0; b < FAKE_NBLOCKS; b++) {
		uintptr_t base = (uintptr_t)fake.mem[b];

		if (a >= base && a < base + FAKE_BLOCK_SIZE) {
			*offset = (uint32_t)(a - base);
			return b;
		}
	}
	return -1;
}

static inline uint32_t fake_plain_read(int b, uint32_t off, unsigned width)
{
	uint32_t v = 0;

	memcpy(&v, &fake.mem[b][off], width);
	return v;
}

static inline void fake_plain_write(int b, uint32_t off, unsigned width, uint32_t v)
{
	memcpy(&fake.mem[b][off], &v, width);
}

static inline void fake_log(int b, uint32_t off, unsigned width, bool write, uint32_t v)
{
	if (fake.nlog < FAKE_LOG_MAX)
		fake.log[fake.nlog++] = (struct fake_access){ (enum fake_block_id)b, off, width, write, v };
}

static inline bool fake_claims(const volatile void *addr, void *ctx)
{
	uint32_t off;

	(void)ctx;
	return fake_block_of(addr, &off) >= 0;
}

/* GPIO register offsets inside a bank pair's block. */
#define FG_DIR 0x00
#define FG_OUT 0x04
#define FG_SET 0x08
#define FG_CLR 0x0c
#define FG_IN  0x10
#define FG_SRIS 0x14
#define FG_CRIS 0x18
#define FG_SFAL 0x1c
#define FG_CFAL 0x20
#define FG_STAT 0x24

/* Bank pair and register of a GPIO block offset, or -1 outside the bank pairs. */
static inline int fake_gpio_reg(uint32_t off, uint32_t *reg)
{
	if (off < HS_GPIO_PAIR_OFFSET(0) || off >= HS_GPIO_PAIR_OFFSET(0) + HS_GPIO_PAIRS * HS_GPIO_PAIR_STRIDE)
		return -1;
	*reg = (off - HS_GPIO_PAIR_OFFSET(0)) % HS_GPIO_PAIR_STRIDE;
	return (int)((off - HS_GPIO_PAIR_OFFSET(0)) / HS_GPIO_PAIR_STRIDE);
}

static inline uint32_t fake_read(const volatile void *addr, unsigned width, void *ctx)
{
	uint32_t off = 0, reg, v;
	int b = fake_block_of(addr, &off), pair;

	(void)ctx;
	if (b < 0 || off + width > FAKE_BLOCK_SIZE)
		return 0;
	v = fake_plain_read(b, off, width);
	if (b == FAKE_GPIO && width == 4 && (pair = fake_gpio_reg(off, &reg)) >= 0) {
		switch (reg) {
		case FG_SET: case FG_CLR:
			v = fake_plain_read(b, off - reg + FG_OUT, 4);
			break;
		case FG_IN:
			v = fake.gpio_in[pair];
			break;
		case FG_SRIS: case FG_CRIS:
			v = fake.rising[pair];
			break;
		case FG_SFAL: case FG_CFAL:
			v = fake.falling[pair];
			break;
		default:
			break;
		}
	}
	fake_log(b, off, width, false, v);
	return v;
}

static inline void fake_write(volatile void *addr, unsigned width, uint32_t v, void *ctx)
{
	uint32_t off = 0, reg, out;
	int b = fake_block_of(addr, &off), pair;

	(void)ctx;
	if (b < 0 || off + width > FAKE_BLOCK_SIZE)
		return;
	fake_log(b, off, width, true, v);
	if (b == FAKE_GPIO && width == 4 && (pair = fake_gpio_reg(off, &reg)) >= 0) {
		uint32_t out_off = off - reg + FG_OUT;

		switch (reg) {
		case FG_SET:
			out = fake_plain_read(b, out_off, 4) | v;
			fake_plain_write(b, out_off, 4, out);
			return;
		case FG_CLR:
			out = fake_plain_read(b, out_off, 4) & ~v;
			fake_plain_write(b, out_off, 4, out);
			return;
		case FG_IN:
			return;     /* read only */
		case FG_SRIS: fake.rising[pair] |= v; return;
		case FG_CRIS: fake.rising[pair] &= ~v; return;
		case FG_SFAL: fake.falling[pair] |= v; return;
		case FG_CFAL: fake.falling[pair] &= ~v; return;
		case FG_STAT:
			fake_plain_write(b, off, 4, fake_plain_read(b, off, 4) & ~v);
			return;
		default:
			break;
		}
	}
	fake_plain_write(b, off, width, v);
}

static inline void *fake_map(uintptr_t phys, SIZE size, void *ctx)
{
	(void)ctx;
	for (int b = 0; b < FAKE_NBLOCKS; b++)
		if (phys >= fake_phys[b] && phys + size <= fake_phys[b] + FAKE_BLOCK_SIZE)
			return fake.mem[b] + (phys - fake_phys[b]);
	return NULL;
}

static const struct rtos_host_mmio_ops fake_mmio_ops = {
	fake_claims, fake_read, fake_write, fake_map, NULL,
};

/* Clears the registers and the log and installs the model. */
static inline void fake_mmio_install(void)
{
	memset(&fake, 0, sizeof(fake));
	rtos_host_set_mmio_handler(&fake_mmio_ops);
}

/* The GPIO block's 32-bit register at a byte offset (no side effects, not logged). */
static inline uint32_t fake_gpio_peek(uint32_t off)
{
	return fake_plain_read(FAKE_GPIO, off, 4);
}

/* An edge on pin (rising or falling): latched in INTSTAT if that edge's
 * trigger is enabled; the bank line is raised if BINTEN enables the bank. */
static inline void fake_gpio_edge(unsigned pin, bool rising)
{
	unsigned pair = pin / 32, bank = pin / 16;
	uint32_t bit = HS_GPIO_PAIR_BIT(pin);
	uint32_t stat_off = HS_GPIO_PAIR_OFFSET(pin) + FG_STAT;

	if (rising)
		fake.gpio_in[pair] |= bit;
	else
		fake.gpio_in[pair] &= ~bit;
	if (!((rising ? fake.rising[pair] : fake.falling[pair]) & bit))
		return;
	fake_plain_write(FAKE_GPIO, stat_off, 4, fake_plain_read(FAKE_GPIO, stat_off, 4) | bit);
	if (fake_plain_read(FAKE_GPIO, HS_GPIO_BINTEN, 4) & (1U << bank))
		rtos_host_irq_raise(HS_GPIO_BANK_INTNO(bank));
}

/* Number of logged writes to a block offset, and the last value written. */
static inline unsigned fake_writes_to(enum fake_block_id block, uint32_t off, uint32_t *last)
{
	unsigned n = 0;

	for (unsigned i = 0; i < fake.nlog; i++) {
		if (fake.log[i].block == block && fake.log[i].offset == off && fake.log[i].write) {
			n++;
			if (last)
				*last = fake.log[i].value;
		}
	}
	return n;
}

#endif /* EV3LX_TESTS_FAKE_MMIO_H */

/*
 * regs.h — the simulated AM1808 register space: declaration tables and regions.
 *
 * A peripheral model declares its registers in one table, readable against
 * the TRM, and registers a region (a physical address range) with that
 * table and its context.  Every CPU access — sil_*_mem, readl/writel and
 * friends, or a plain volatile pointer access trapped on x86-64 — arrives
 * here with its exact width and is applied with the declared semantics,
 * calling the model's hooks.  Anything outside a declared register, at a
 * width the register does not allow, against the declared direction, or to
 * a region whose PSC module is not enabled, is a bug report (rtos_host_bug)
 * naming the address, width, value and virtual time.  Host only.
 *
 *   static const struct hs_reg my_regs[] = {
 *       { .name = "REVID",  .offset = 0x00, .kind = HS_RO,  .reset = 0x44830105 },
 *       { .name = "CTRL",   .offset = 0x04, .kind = HS_RW,  .mask = 0x0000000f,
 *         .after_write = my_ctrl_written },
 *       { .name = "STAT",   .offset = 0x08, .kind = HS_W1C, .mask = 0x3 },
 *       { .name = "DATA",   .offset = 0x10, .kind = HS_RW,  .count = 4, .stride = 4 },
 *   };
 *   hs_region_add(&(struct hs_region_cfg){ .name = "MYDEV", .phys = 0x01F0E000,
 *       .size = 0x1000, .regs = my_regs, .nregs = HS_ARRAY_SIZE(my_regs),
 *       .power = HS_PSC1_MODULE(17), .ctx = me });
 */
#ifndef HOST_SIM_REGS_H
#define HOST_SIM_REGS_H

#include <stdbool.h>
#include <stdint.h>
#include "t_stddef.h"
#include "rtos_host.h"

#define HS_ARRAY_SIZE(a) ((unsigned)(sizeof(a) / sizeof((a)[0])))

/* Access semantics of a register (applied to the bits of .mask; see hs_reg). */
enum hs_reg_kind {
	HS_RSVD = 0,    /* reserved: any access is a bug (so a zeroed row is never silently usable) */
	HS_RW,          /* read returns the value; write stores the .mask bits */
	HS_RO,          /* read returns the value; any write is a bug */
	HS_WO,          /* write stores the .mask bits; any read is a bug */
	HS_W1S,         /* write: the 1 bits of .mask set the value's bits; read returns the value */
	HS_W1C,         /* write: the 1 bits of .mask clear the value's bits; read returns the value */
	HS_COR,         /* read returns the value, then clears its .mask bits; any write is a bug */
};

/* Access widths, as a bit set for hs_reg.widths. */
#define HS_W8   0x1U
#define HS_W16  0x2U
#define HS_W32  0x4U

struct hs_reg;

/* Describes one CPU access to a register, handed to the hooks. */
struct hs_access {
	const struct hs_reg *reg;   /* the declaration */
	unsigned index;             /* element of a register array (0 for a single register) */
	uint32_t offset;            /* byte offset of this element in the region */
	unsigned width;             /* width of the CPU access in bytes: 1, 2 or 4 */
	bool write;                 /* direction */
	unsigned lane;              /* byte of the element the access starts at (0: its low byte) */
};

/*
 * Hooks.  ctx is the region's context (hs_region_cfg.ctx).
 * before_read runs before the value is returned; *value is the register's
 * stored value (or its alias target's) and the hook may update it — the
 * update persists, as for a status register whose bits the model computes.
 * A hook may call hs_access_stall_until() first (a device not ready yet).
 * after_write runs after the declared semantics were applied: old and
 * new_value are the stored value before and after, written the CPU's data.
 */
typedef void (*hs_before_read_fn)(void *ctx, const struct hs_access *a, uint32_t *value);
typedef void (*hs_after_write_fn)(void *ctx, const struct hs_access *a,
				  uint32_t old, uint32_t new_value, uint32_t written);

/*
 * Direct accesses, for a register a driver polls thousands of times a second:
 * the whole CPU access as one function that the access path calls in place of
 * its own (no hook call in between).  Only unlogged 32-bit accesses take it (a
 * narrower or logged one takes the hooks, so both must agree): read_direct
 * does what before_read and then reading the stored value do, write_direct
 * what storing data with the register's kind and then after_write do.  Their
 * argument is a struct hs_direct's base.
 */
struct hs_direct {
	struct rtos_host_mmio_route base;
	void *ctx;                  /* the region's context */
	uint32_t *value;            /* the register's stored value */
};
typedef uint32_t (*hs_read_direct_fn)(const struct rtos_host_mmio_route *rt);
typedef void (*hs_write_direct_fn)(const struct rtos_host_mmio_route *rt, uint32_t data);

/* The struct hs_direct whose base a direct access is given. */
static inline const struct hs_direct *hs_direct_of(const struct rtos_host_mmio_route *rt)
{
	return (const struct hs_direct *)(const void *)rt;
}

/* One row of a declaration table.  Zero fields take the defaults noted. */
struct hs_reg {
	const char *name;           /* TRM name; arrays get the element index appended ("CMR3") */
	uint32_t offset;            /* byte offset of (the first element) in the region */
	uint8_t width;              /* natural width in bytes: 1, 2 or 4 (0: 4) */
	uint8_t widths;             /* also allowed at .offset: HS_W8|HS_W16|HS_W32 (0: only .width);
	                             * a narrower access reads/writes the low bytes */
	enum hs_reg_kind kind;
	uint32_t reset;             /* value at reset */
	uint32_t mask;              /* bits the kind applies to (0: all bits of .width) */
	uint16_t count;             /* number of elements of a register array (0: 1) */
	uint16_t stride;            /* bytes between elements (0: .width) */
	const char *alias;          /* name of another register of the region whose stored value this
	                             * one reads and modifies (GPIO SET_DATA acts on OUT_DATA);
	                             * the alias must have the same count and stride, or count 1 */
	hs_before_read_fn before_read;
	hs_after_write_fn after_write;
	hs_read_direct_fn read_direct;      /* NULL: none (see struct hs_direct) */
	hs_write_direct_fn write_direct;
};

/* PSC module a region needs enabled to respond: PSC0 or PSC1 and the LPSC number. */
#define HS_NO_PSC            0U
#define HS_PSC0_MODULE(lpsc) (0x100U | (unsigned)(lpsc))
#define HS_PSC1_MODULE(lpsc) (0x200U | (unsigned)(lpsc))

struct hs_region_cfg {
	const char *name;           /* "GPIO", "ECAP0": used in traces, logs and bug reports */
	uintptr_t phys;             /* physical base address (page aligned) */
	uint32_t size;              /* bytes of address space decoded (multiple of 4 KiB) */
	const struct hs_reg *regs;
	unsigned nregs;
	unsigned power;             /* HS_NO_PSC or HS_PSCx_MODULE(n): dead while that module is not enabled */
	void *ctx;                  /* passed to the hooks */
};

struct hs_region;

/*
 * The power controller regions with a .power module consult (the SoC's PSC
 * model installs itself when created, so the register space needs no
 * knowledge of it): where the module's live flag is kept - true while it
 * may be accessed; its address stable for the process's life, and every
 * change of it reported with hs_space_power_changed (space_internal.h: the
 * accessors' route cache holds no power check) - and a word for its state in bug
 * reports.  Without a controller such regions are dead.
 */
struct hs_power_controller {
	const bool *(*live_flag)(unsigned power);
	const char *(*state_name)(unsigned power);
};
void hs_set_power_controller(const struct hs_power_controller *pc);

/* Registers a region: checks the table (overlaps, widths, aliases, offsets
 * inside size), sets every register to its reset value and makes the range
 * answer CPU accesses.  Returns NULL after a bug report if the table or the
 * range is invalid or overlaps another region.  Valid until hs_board_shutdown. */
struct hs_region *hs_region_add(const struct hs_region_cfg *cfg);

/* The region serving physical address phys, or NULL. */
struct hs_region *hs_region_find(uintptr_t phys);
/* The region registered under name, or NULL. */
struct hs_region *hs_region_by_name(const char *name);
const char *hs_region_name(const struct hs_region *r);
uintptr_t hs_region_phys(const struct hs_region *r);
void *hs_region_ctx(const struct hs_region *r);

/* The CPU-visible address of physical address phys (what ioremap returns), or NULL. */
volatile void *hs_region_window(uintptr_t phys);

/* Stored value of the register (array element) at offset, without hooks or
 * side effects — for models.  Reports a bug if offset is no register. */
uint32_t hs_reg_get(const struct hs_region *r, uint32_t offset);
/* Sets the stored value without hooks or side effects. */
void hs_reg_set(struct hs_region *r, uint32_t offset, uint32_t value);
/* Sets/clears bits of the stored value without hooks (value = value & ~clear | set). */
void hs_reg_update(struct hs_region *r, uint32_t offset, uint32_t clear, uint32_t set);
/* Where the stored value of the register (array element) at offset lives:
 * the word hs_reg_get reads and hs_reg_set writes, for a model that consults
 * a register on every event (a load instead of a lookup).  Writes through it
 * must keep to the register's width, as hs_reg_set does.  Valid until the
 * region is freed (hs_region_reset keeps it); NULL after a bug report if
 * offset is no register. */
uint32_t *hs_reg_value_ptr(struct hs_region *r, uint32_t offset);
/* Resets every register of the region to its declared reset value. */
void hs_region_reset(struct hs_region *r);

/* CPU accesses as the SoC sees them (what sil_host_read/write end in):
 * phys is a physical address; the access is checked, hooked, logged and
 * costs hs_board_cfg.access_ns of virtual CPU time. */
uint32_t hs_cpu_read(uintptr_t phys, unsigned width);
void hs_cpu_write(uintptr_t phys, unsigned width, uint32_t value);

/* From a before_read hook: the access in progress completes at virtual time
 * t_ns (> now).  The calling context spends the time (rtos_host_consume), so
 * device events due meanwhile fire first; the hook then reads the updated
 * state.  This is how a status poll on a busy device costs one access
 * instead of millions, and how a polling loop ends in virtual time. */
void hs_access_stall_until(uint64_t t_ns);

#endif /* HOST_SIM_REGS_H */

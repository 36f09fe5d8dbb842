/*
 * test_speed.c — speed sanity: tacho-like edge storms through the GPIO edge
 * detector, bank interrupt and an acknowledging ISR; and a driver polling a
 * slow device, where the stall helper makes each poll cost one access in
 * virtual time instead of spinning.  Generous wall-clock bounds, so it holds
 * under sanitizers and qemu too.
 */
#include <time.h>

#include "tap.h"
#include "sil.h"
#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/clock.h"
#include "host_sim/gpio.h"
#include "host_sim/regs.h"
#include "host_sim/scenario.h"

#define GPIO       0x01E26000U
#define PAIR2      (GPIO + HS_GPIO_PAIR_OFFSET(64U))
#define TACHO      HS_GPIO(5, 11)
#define TACHO_BIT  (1U << 27)
#define XDEV       0x01E00000U
#define EDGES      100000U

static unsigned isr_runs, edges;
static bool level;

static void edge(void *arg)
{
	(void)arg;
	level = !level;
	hs_gpio_set_input(TACHO, level);
	if (++edges < EDGES)
		hs_event_after(50000, edge, NULL);       /* 20 kHz of edges */
}

static void bank5_isr(intptr_t x)
{
	uint32_t st = sil_rew_mem(rtos_host_map_io(PAIR2 + 0x24, 4));

	(void)x;
	sil_wrw_mem(rtos_host_map_io(PAIR2 + 0x24, 4), st);
	isr_runs++;
}

/* A device whose transfer takes 8 us; STATUS bit 0 = done. */
static struct {
	uint64_t done_at;
	unsigned status_reads, transfers;
} xdev;

static void status_read(void *ctx, const struct hs_access *a, uint32_t *value)
{
	(void)ctx; (void)a;
	xdev.status_reads++;
	if (hs_now() < xdev.done_at)
		hs_access_stall_until(xdev.done_at);
	*value = hs_now() >= xdev.done_at ? 1U : 0U;
}

static void data_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	(void)ctx; (void)a; (void)old; (void)now; (void)written;
	xdev.done_at = hs_now() + 8000;
	xdev.transfers++;
}

static const struct hs_reg xdev_regs[] = {
	{ .name = "DATA",   .offset = 0x0, .kind = HS_WO, .after_write = data_written },
	{ .name = "STATUS", .offset = 0x4, .kind = HS_RO, .before_read = status_read },
};

/* Ten polled transfers every millisecond, like d_analog's ADC cycle. */
static void poll_task(intptr_t x)
{
	volatile uint32_t *data = rtos_host_map_io(XDEV, 8);

	(void)x;
	for (;;) {
		for (int i = 0; i < 10; i++) {
			sil_wrw_mem((uint32_t *)data, (uint32_t)i);
			while (!(sil_rew_mem((uint32_t *)data + 1) & 1U))
				;
		}
		dly_tsk(1);
	}
}

static const struct rtos_task_cfg tasks[] = { { 1, TA_ACT, 0, poll_task, 5, 8192, TDOM_KERNEL, "poll" } };
static const struct rtos_int_cfg ints[] = { { HS_GPIO_BANK_INTNO(5), TA_ENAINT, -3 } };
static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, HS_GPIO_BANK_INTNO(5), bank5_isr, 1 } };
static const struct rtos_cfg edge_cfg = { .name = "edges", .ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(isrs) };
static const struct rtos_cfg poll_cfg = { .name = "poll", .tasks = RTOS_TABLE(tasks) };

static const struct hs_region_cfg xdev_cfg = {
	.name = "XDEV", .phys = XDEV, .size = 0x1000, .regs = xdev_regs, .nregs = HS_ARRAY_SIZE(xdev_regs),
};

/* Adds the polled device before the kernel boots, as a board device would. */
static ER xdev_create(const struct hs_board_cfg *cfg, void **ctx)
{
	(void)cfg;
	*ctx = NULL;
	return hs_region_add(&xdev_cfg) ? E_OK : E_SYS;
}

static const struct hs_device xdev_device = { .name = "xdev", .create = xdev_create };
static const struct hs_device *const poll_devices[] = { &xdev_device, NULL };

int main(void)
{
	struct hs_scenario scn = { .rtos = &edge_cfg };
	struct hs_scenario pscn = { .rtos = &poll_cfg, .board = &(struct hs_board_cfg){ .devices = poll_devices } };
	clock_t c0;
	double secs;

	tap_plan(5);
	if (hs_sim_boot(&scn) != E_OK)
		tap_bail_out("boot failed");
	sil_wrw_mem(rtos_host_map_io(GPIO + 0x08, 4), 1U << 5);
	sil_wrw_mem(rtos_host_map_io(PAIR2 + 0x14, 4), TACHO_BIT);
	sil_wrw_mem(rtos_host_map_io(PAIR2 + 0x1C, 4), TACHO_BIT);
	c0 = clock();
	hs_event_after(1000, edge, NULL);
	hs_sim_run_for((uint64_t)EDGES * 50000U + 1000000U);
	secs = (double)(clock() - c0) / CLOCKS_PER_SEC;
	is_int(isr_runs, EDGES, "every edge ran the ISR");
	tap_diag("%u edges with ISR in %.2f s of CPU (%.0f edges/s)", EDGES, secs, EDGES / (secs > 0 ? secs : 1e-9));
	ok(secs < 30.0, "100000 edges in under 30 s of CPU");
	hs_sim_shutdown();

	if (hs_sim_boot(&pscn) != E_OK)
		tap_bail_out("boot failed");
	c0 = clock();
	hs_sim_run_for(1000000000ULL);
	secs = (double)(clock() - c0) / CLOCKS_PER_SEC;
	/* dly_tsk(1) waits at least 1 ms, rounded up to the 200-us tick: one cycle per 1.2 ms. */
	in_range(xdev.transfers, 8300, 8350, "1 s of virtual time: ten 8-us transfers per 1.2-ms cycle");
	ok(xdev.status_reads == xdev.transfers, "each transfer's status poll is one stalled access (%u reads)", xdev.status_reads);
	tap_diag("%u polled transfers in %.2f s of CPU", xdev.transfers, secs);
	ok(secs < 30.0, "in under 30 s of CPU");
	hs_sim_shutdown();
	return tap_done();
}

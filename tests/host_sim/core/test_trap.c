/*
 * test_trap.c — plain pointer accesses (volatile struct members and
 * pointers, 8/16/32-bit, loads with zero and sign extension, stores of
 * registers and immediates) are trapped and emulated with exactly the
 * semantics, register log and virtual timing of the accessor path; a fault
 * in the window outside any register is reported; faults elsewhere still
 * reach the previous handler (ASan's or the default).  SKIP where trapping
 * is unavailable (qemu-arm user mode).
 */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "tap.h"
#include "sil.h"
#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/clock.h"
#include "host_sim/gpio.h"
#include "host_sim/intc.h"
#include "host_sim/regs.h"
#include "host_sim/scenario.h"
#include "host_sim/trace.h"

#define GPIO_PHYS  0x01E26000U
#define TDEV_PHYS  0x01E00000U
#define TACHO      HS_GPIO(5, 11)
#define TACHO_BIT  (1U << 27)
#define MOTOR_BIT  (1U << 31)

struct gpio_pair {
	uint32_t dir, out_data, set_data, clr_data, in_data;
	uint32_t set_ris_trig, clr_ris_trig, set_fal_trig, clr_fal_trig, intstat;
};

struct gpio_regs {
	uint32_t revid, reserved, binten, reserved2;
	struct gpio_pair pair[5];
};

struct tdev_regs {
	uint8_t b8;
	uint8_t pad0;
	uint16_t h16;
	uint32_t narrow;
};

static const struct hs_reg tdev_regs[] = {
	{ .name = "B8",     .offset = 0x0, .width = 1, .kind = HS_RW },
	{ .name = "H16",    .offset = 0x2, .width = 2, .kind = HS_RW },
	{ .name = "NARROW", .offset = 0x4, .kind = HS_RW, .widths = HS_W8 | HS_W16 },
};

/* The accesses a driver makes, through plain volatile pointers. */
static __attribute__((noinline)) long through_pointers(volatile struct gpio_regs *g, volatile struct tdev_regs *t)
{
	long sum = 0;
	uint32_t d;
	int16_t sh;
	int8_t sb;

	g->binten = 1U << 5;
	g->pair[2].set_ris_trig = TACHO_BIT;
	d = g->pair[1].dir;
	g->pair[1].dir = d & ~MOTOR_BIT;
	g->pair[1].set_data = MOTOR_BIT;
	sum += g->pair[1].in_data;
	hs_gpio_set_input(TACHO, 1);
	d = g->pair[2].intstat;
	g->pair[2].intstat = d;
	sum += d;
	t->b8 = 0x85;
	sum += t->b8;
	sb = *(volatile int8_t *)&t->b8;
	sum += sb;
	t->h16 = 0x8001;
	sum += t->h16;
	sh = *(volatile int16_t *)&t->h16;
	sum += sh;
	t->narrow = 0x11223344;
	*((volatile uint8_t *)t + 4) = 0xAA;
	sum += *(volatile uint16_t *)(volatile void *)((volatile uint8_t *)t + 4);
	sum += t->narrow;
	return sum;
}

/* The same accesses through the accessors. */
static __attribute__((noinline)) long through_accessors(volatile struct gpio_regs *g, volatile struct tdev_regs *t)
{
	long sum = 0;
	uint32_t d;

	sil_wrw_mem((uint32_t *)&g->binten, 1U << 5);
	sil_wrw_mem((uint32_t *)&g->pair[2].set_ris_trig, TACHO_BIT);
	d = sil_rew_mem((uint32_t *)&g->pair[1].dir);
	sil_wrw_mem((uint32_t *)&g->pair[1].dir, d & ~MOTOR_BIT);
	sil_wrw_mem((uint32_t *)&g->pair[1].set_data, MOTOR_BIT);
	sum += sil_rew_mem((uint32_t *)&g->pair[1].in_data);
	hs_gpio_set_input(TACHO, 1);
	d = sil_rew_mem((uint32_t *)&g->pair[2].intstat);
	sil_wrw_mem((uint32_t *)&g->pair[2].intstat, d);
	sum += d;
	sil_wrb_mem((uint8_t *)&t->b8, 0x85);
	sum += sil_reb_mem((uint8_t *)&t->b8);
	sum += (int8_t)sil_reb_mem((uint8_t *)&t->b8);
	sil_wrh_mem((uint16_t *)&t->h16, 0x8001);
	sum += sil_reh_mem((uint16_t *)&t->h16);
	sum += (int16_t)sil_reh_mem((uint16_t *)&t->h16);
	sil_wrw_mem((uint32_t *)&t->narrow, 0x11223344);
	sil_wrb_mem((uint8_t *)&t->narrow, 0xAA);
	sum += sil_reh_mem((uint16_t *)&t->narrow);
	sum += sil_rew_mem((uint32_t *)&t->narrow);
	return sum;
}

static const struct rtos_cfg cfg = { .name = "trap" };

/* ---- Trapped accesses in a task preempted by ISRs that trap too ---- */
static volatile struct gpio_regs *task_gpio;
static bool task_pointers;
static unsigned task_loops, isr_loops;
static uint32_t task_sum, isr_sum;

static void tick(void *arg)
{
	(void)arg;
	hs_intc_raise(60);
	hs_event_after(10000, tick, NULL);
}

static void busy_isr(intptr_t x)
{
	(void)x;
	isr_sum += task_pointers ? task_gpio->pair[2].in_data : sil_rew_mem((uint32_t *)&task_gpio->pair[2].in_data);
	isr_loops++;
}

static void busy_task(intptr_t x)
{
	(void)x;
	for (;;) {
		if (task_pointers) {
			task_gpio->pair[1].set_data = MOTOR_BIT;
			task_sum += task_gpio->pair[1].out_data;
			task_gpio->pair[1].clr_data = MOTOR_BIT;
		} else {
			sil_wrw_mem((uint32_t *)&task_gpio->pair[1].set_data, MOTOR_BIT);
			task_sum += sil_rew_mem((uint32_t *)&task_gpio->pair[1].out_data);
			sil_wrw_mem((uint32_t *)&task_gpio->pair[1].clr_data, MOTOR_BIT);
		}
		task_loops++;
		/* Other work between accesses: the run can stop here (rtos_stub
		 * never pauses a task inside a register access). */
		sil_dly_nse(200);
	}
}

static const struct rtos_task_cfg busy_tasks[] = { { 1, TA_ACT, 0, busy_task, 5, 8192, TDOM_KERNEL, "busy" } };
static const struct rtos_int_cfg busy_ints[] = { { 60, TA_ENAINT, -2 } };
static const struct rtos_isr_cfg busy_isrs[] = { { TA_NULL, 0, 60, busy_isr, 1 } };
static const struct rtos_cfg busy_cfg = { .name = "busy", .tasks = RTOS_TABLE(busy_tasks),
	.ints = RTOS_TABLE(busy_ints), .isrs = RTOS_TABLE(busy_isrs) };

/* Runs the busy task for 1 ms with pointer or accessor accesses; returns a digest. */
static uint64_t run_busy(bool pointers)
{
	struct hs_scenario scn = { .rtos = &busy_cfg };
	uint64_t digest;

	task_pointers = pointers;
	task_loops = isr_loops = 0;
	task_sum = isr_sum = 0;
	if (hs_sim_boot(&scn) != E_OK)
		return 0;
	task_gpio = rtos_host_map_io(GPIO_PHYS, sizeof(*task_gpio));
	hs_gpio_set_input(TACHO, 1);
	hs_event_after(1000, tick, NULL);
	hs_sim_run_for(1000000);
	digest = ((uint64_t)task_loops << 40) ^ ((uint64_t)isr_loops << 20) ^ task_sum ^ ((uint64_t)isr_sum << 8);
	tap_diag("%s: %u task loops, %u ISR runs", pointers ? "pointers" : "accessors", task_loops, isr_loops);
	hs_sim_shutdown();
	return digest;
}
static volatile uintptr_t bad_address = 16;

struct run {
	long sum;
	uint64_t end;
	char *log;
	size_t len;
};

/* Boots a fresh board, runs one variant with the register log on, shuts down. */
static bool run_variant(bool pointers, struct run *r)
{
	struct hs_scenario scn = { .rtos = &cfg };
	volatile struct gpio_regs *g;
	volatile struct tdev_regs *t;
	FILE *log;

	if (hs_sim_boot(&scn) != E_OK)
		return false;
	if (!hs_board_traps_pointers() && pointers) {
		hs_sim_shutdown();
		return false;
	}
	hs_region_add(&(struct hs_region_cfg){ .name = "TDEV", .phys = TDEV_PHYS, .size = 0x1000,
		.regs = tdev_regs, .nregs = HS_ARRAY_SIZE(tdev_regs) });
	g = rtos_host_map_io(GPIO_PHYS, sizeof(*g));
	t = rtos_host_map_io(TDEV_PHYS, sizeof(*t));
	log = open_memstream(&r->log, &r->len);
	hs_trace_reglog("*", log);
	r->sum = pointers ? through_pointers(g, t) : through_accessors(g, t);
	r->end = hs_now();
	hs_trace_reglog(NULL, NULL);
	fclose(log);
	hs_sim_shutdown();
	return true;
}

int main(void)
{
	struct run acc = { 0 }, ptr = { 0 };
	struct hs_scenario scn = { .rtos = &cfg };
	volatile uint32_t *hole;
	uint32_t v;
	pid_t pid;
	int status;

	tap_plan(8);
	if (hs_sim_boot(&scn) != E_OK)
		tap_bail_out("boot failed");
	if (!hs_board_traps_pointers()) {
		char why[200];

		snprintf(why, sizeof(why), "%s", hs_board_trap_unavailable_reason());
		hs_sim_shutdown();
		tap_skip(8, why);
		return tap_done();
	}
	hs_sim_shutdown();

	ok(run_variant(false, &acc) && run_variant(true, &ptr), "both variants ran");
	if (!acc.log || !ptr.log)
		tap_bail_out("no register log to compare");
	is_int(ptr.sum, acc.sum, "pointer accesses read the same values as the accessors");
	ok(ptr.len > 0 && ptr.len == acc.len && memcmp(ptr.log, acc.log, ptr.len) == 0,
	   "the register logs are identical (widths, values, order, virtual times)");
	if (ptr.len != acc.len || memcmp(ptr.log, acc.log, ptr.len) != 0)
		tap_diag("accessors:\n%s\npointers:\n%s", acc.log, ptr.log);
	is_u64(ptr.end, acc.end, "and end at the same virtual time");
	ok(strstr(ptr.log, "R2 TDEV.H16") && strstr(ptr.log, "W1 TDEV.NARROW") && strstr(ptr.log, "R1 TDEV.B8"),
	   "8- and 16-bit accesses keep their width");
	free(acc.log);
	free(ptr.log);

	/* Tasks switched and ISRs nested in the middle of trapped accesses. */
	{
		uint64_t da = run_busy(false), dp = run_busy(true);

		ok(da != 0 && da == dp, "a task preempted by trapping ISRs: same loops, ISR runs and values");
	}

	/* A pointer into the window space where no register is: reported loudly. */
	if (hs_sim_boot(&scn) != E_OK)
		tap_bail_out("boot failed");
	hole = (volatile uint32_t *)((volatile uint8_t *)rtos_host_map_io(GPIO_PHYS, 4) + 0x200);
	rtos_host_expect_bugs(true);
	v = *hole;
	ok(v == 0 && strstr(rtos_host_last_bug(), "GPIO+0x200): no register there"),
	   "a trapped access outside the registers is reported");
	rtos_host_expect_bugs(false);

	/* A fault outside the windows still reaches the previous handler (ASan or default). */
	fflush(stdout);
	pid = fork();
	if (pid == 0) {
		close(1);
		close(2);
		*(volatile int *)bad_address = 1;
		_exit(0);
	}
	waitpid(pid, &status, 0);
	ok((WIFSIGNALED(status) && WTERMSIG(status) == SIGSEGV) || (WIFEXITED(status) && WEXITSTATUS(status) != 0),
	   "a fault outside the windows is not swallowed");
	hs_sim_shutdown();
	return tap_done();
}

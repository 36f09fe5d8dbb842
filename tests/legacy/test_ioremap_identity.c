/*
 * test_ioremap_identity.c — in the configurations with the target's types
 * (arm926 under qemu-arm, and host32: 32-bit pointers) ioremap() of a peripheral returns
 * its physical address, as on the brick, whose peripherals are identity
 * mapped; a plain pointer made from the physical address reaches the same
 * register.  Elsewhere (64-bit hosts) the window space mirrors the
 * peripheral range at another address and the test says so.
 */
#include "tap.h"
#include "sil.h"
#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"
#include <linux/io.h>

#define GPIO_PHYS     0x01E26000U
#define GPIO_DIR01    0x10U          /* DIR01: banks 0 and 1 direction (AM1808 TRM, GPIO registers) */
#define EHRPWM1_PHYS  0x01F02000U

static volatile bool done;

/* ioremap may sleep: a task maps, as a driver's init does. */
static void test_task(intptr_t exinf)
{
	void __iomem *gpio = ioremap(GPIO_PHYS, 0x100);
	void __iomem *pwm = ioremap(EHRPWM1_PHYS, 0x2854);

	(void)exinf;
	if (sizeof(void *) != 4 || !hs_board_traps_pointers()) {
		tap_skip(3, "a 64-bit host: the window space mirrors the peripherals elsewhere");
	} else {
		ok((uintptr_t)gpio == GPIO_PHYS, "ioremap(GPIO) is the physical address (%p)", (void *)gpio);
		ok((uintptr_t)pwm == EHRPWM1_PHYS, "ioremap(eHRPWM1, 0x2854 bytes) too (%p)", (void *)pwm);
		writel(0x5A5A0000U, (char __iomem *)gpio + GPIO_DIR01);
		ok(*(volatile uint32_t *)(uintptr_t)(GPIO_PHYS + GPIO_DIR01) == 0x5A5A0000U,
		   "a plain pointer made from the physical address reads what writel wrote");
	}
	iounmap(pwm);
	iounmap(gpio);
	done = true;
}

int main(void)
{
	const struct rtos_task_cfg tasks[] = {
		{ 1, TA_ACT, 0, test_task, 8, 64 * 1024, TDOM_KERNEL, "ioremap_test" },
	};
	const struct rtos_cfg cfg = { .name = "ioremap_identity", .tasks = tasks, .ntasks = 1 };
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	struct hs_scenario scn = { .rtos = &cfg, .board = &board, .seed = 1 };

	tap_plan(4);
	if (hs_sim_boot(&scn) != E_OK)
		tap_bail_out(rtos_host_boot_error());
	hs_sim_run_for(10000000ULL);
	ok(done, "the test task ran to its end");
	hs_sim_shutdown();
	return tap_done();
}

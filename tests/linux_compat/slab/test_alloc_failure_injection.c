/*
 * test_alloc_failure_injection.c — allocation-failure injection
 * (linux_compat/fault_inject.h), and the four EV3 drivers' inits driven
 * through it: the brick boots with d_pwm, d_analog, d_uart and d_ui once for
 * every allocation their inits make, that allocation failing; each boot and
 * shutdown must leave the pool as a clean one does (nothing leaks), report no
 * bug, and the failing module must be the only one missing.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_host.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"
#include <linux_compat/config.h>
#include <linux_compat/fault_inject.h>
#include <linux_compat/heap.h>
#include <linux_compat/devfs.h>
#include <linux/slab.h>
#include "pwm_hack.h"
#include "analog_hack.h"
#include "uart_hack.h"
#include "ui_hack.h"

#define MS	1000000ULL
#define MAX_ALLOCS	64

struct boot_result {
	unsigned long attempts;      /* allocations the inits attempted */
	unsigned long injected;
	size_t in_use_after;         /* pool bytes still allocated after shutdown */
	unsigned int devices;        /* /dev nodes present after the inits */
	uint_t bugs;
};

static const char *const dev_names[] = {
	"/dev/lms_pwm", "/dev/lms_motor", "/dev/lms_analog", "/dev/lms_dcm", "/dev/lms_uart", "/dev/lms_ui",
};

/* Boots the brick with the four drivers, lets the inits run, shuts down. */
static void boot_once(struct boot_result *r)
{
	static const struct rtos_cfg *const includes[] = {
		&linux_compat_cfg, &pwm_hack_cfg, &analog_hack_cfg, &uart_hack_cfg, &ui_hack_cfg, NULL,
	};
	static const struct rtos_cfg cfg = { .name = "alloc_faults", .includes = includes };
	static struct hs_board_cfg board;
	struct hs_scenario scn = { .rtos = &cfg, .board = &board, .seed = 1 };
	struct lx_heap_stats st;
	uint_t bugs_before = rtos_host_bug_count();
	unsigned int i;

	memset(r, 0, sizeof(*r));
	board.devices = ev3_board_devices;
	rtos_host_expect_bugs(true);
	if (hs_sim_boot(&scn) != E_OK) {
		rtos_host_expect_bugs(false);
		r->bugs = 1;
		return;
	}
	hs_sim_run_for(50 * MS);
	r->attempts = lx_alloc_attempts();
	r->injected = lx_alloc_injected_failures();
	for (i = 0; i < sizeof(dev_names) / sizeof(dev_names[0]); i++)
		r->devices += lx_dev_exists(dev_names[i]);
	hs_sim_shutdown();
	rtos_host_expect_bugs(false);
	lx_heap_get_stats(&st);
	r->in_use_after = st.in_use;
	r->bugs = rtos_host_bug_count() - bugs_before;
}

static void test_injection_modes(void)
{
	void *p[8];
	unsigned int i, failed = 0, failed_again = 0;

	lx_heap_reset();
	lx_fail_alloc_nth(3);
	for (i = 0; i < 5; i++)
		p[i] = kmalloc(16, GFP_ATOMIC);
	ok(p[0] && p[1] && !p[2] && p[3] && p[4], "nth=3: exactly the third allocation fails");
	is_int((int)lx_alloc_attempts(), 5, "attempts are counted");
	for (i = 0; i < 5; i++)
		kfree(p[i]);

	lx_fail_alloc_random(50, 1234, -1);
	lx_heap_reset();
	for (i = 0; i < 8; i++) {
		p[i] = kmalloc(16, GFP_ATOMIC);
		failed |= (p[i] == NULL) << i;
		kfree(p[i]);
	}
	lx_heap_reset();
	for (i = 0; i < 8; i++) {
		p[i] = kmalloc(16, GFP_ATOMIC);
		failed_again |= (p[i] == NULL) << i;
		kfree(p[i]);
	}
	ok(failed != 0 && failed != 0xFF, "probability 50%%: some fail, some succeed (mask %#x)", failed);
	is_int((int)failed_again, (int)failed, "same seed, same failures after a reset");
	lx_fail_alloc_random(100, 7, 2);
	lx_heap_reset();
	for (i = 0, failed = 0; i < 5; i++) {
		p[i] = kmalloc(16, GFP_ATOMIC);
		failed += p[i] == NULL;
		kfree(p[i]);
	}
	is_int((int)failed, 2, "times=2 limits the failures per boot");
	lx_fail_alloc_off();
	lx_heap_reset();
}

int main(void)
{
	struct boot_result clean, r;
	unsigned long n;
	unsigned int leaks = 0, bugs = 0, wrong_devices = 0;

	tap_plan(11);
	test_injection_modes();

	lx_fail_alloc_off();
	boot_once(&clean);
	ok(clean.devices == 6 && clean.bugs == 0, "clean boot: 6 device nodes, no bug");
	ok(clean.attempts > 0 && clean.attempts <= MAX_ALLOCS, "the inits make %lu allocations", clean.attempts);

	for (n = 1; n <= clean.attempts && n <= MAX_ALLOCS; n++) {
		lx_fail_alloc_nth(n);
		boot_once(&r);
		if (r.in_use_after != clean.in_use_after) {
			leaks++;
			tap_diag("allocation %lu failing: %lu bytes left after shutdown (clean: %lu)", n,
				 (unsigned long)r.in_use_after, (unsigned long)clean.in_use_after);
		}
		if (r.bugs != 0) {
			bugs++;
			tap_diag("allocation %lu failing: %u bug(s), last: %s", n, r.bugs, rtos_host_last_bug());
		}
		if (r.injected != 1 || r.devices >= clean.devices) {
			wrong_devices++;
			tap_diag("allocation %lu failing: injected %lu, %u device nodes", n, r.injected, r.devices);
		}
	}
	lx_fail_alloc_off();
	is_int((int)leaks, 0, "no boot with a failing allocation leaks (%lu boots)", clean.attempts);
	is_int((int)bugs, 0, "no boot with a failing allocation reports a bug");
	is_int((int)wrong_devices, 0, "each failure removes devices of the module whose init failed");
	boot_once(&r);
	ok(r.devices == 6 && r.in_use_after == clean.in_use_after, "injection off: a clean boot again");
	return tap_done();
}

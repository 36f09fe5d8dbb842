/*
 * test_module_dup.c — two modules with one KBUILD_MODNAME, as two .ko files
 * built from one driver: Linux loads the first and refuses the second with
 * -EEXIST ("module is already loaded"); here the second's init and exit are
 * never called, it is logged, lx_module_find names the loaded one, a
 * parameter set before boot reaches it whichever it is, and the next boot
 * refuses the other again.
 */
#define KBUILD_MODNAME "dup"
#include "tap.h"
#include "lx_core_test.h"
#include "rtos_test.h"
#include <linux/module.h>
#include <linux/moduleparam.h>
#include <linux_compat/modparam.h>
#include <linux/init.h>
#include <linux/errno.h>
#include <linux/time64.h>
#include <kernel.h>

static int first_inits, second_inits, first_exits, second_exits;
static int HwId = 1, second_HwId = 1, seen_HwId;

module_param(HwId, int, 0);

static int __init first_init(void)
{
	first_inits++;
	seen_HwId = HwId;
	return 0;
}

static void __exit first_exit(void)
{
	first_exits++;
}

module_init(first_init);
module_exit(first_exit);
MODULE_LICENSE("GPL");

/* The same name from another translation unit (another module object). */
static struct module second_mod = { .name = KBUILD_MODNAME };
static int second_init(void)	{ second_inits++; seen_HwId = second_HwId; return 0; }
static void second_exit(void)	{ second_exits++; }
static const struct lx_initcall second_init_call = { &second_mod, second_init, NULL, LX_INITCALL_DEVICE };
static const struct lx_initcall second_exit_call = { &second_mod, NULL, second_exit, LX_INITCALL_DEVICE };
static const struct lx_initcall *const second_ptrs[2] __used __section(LX_INITCALL_SECTION) =
	{ &second_init_call, &second_exit_call };
static const struct lx_module_param second_param = { KBUILD_MODNAME, "HwId", LX_PARAM_int, &second_HwId, 0 };
static const struct lx_module_param *const second_param_ptr __used __section(LX_MODULE_PARAM_SECTION) =
	&second_param;

static struct module *loaded, *refused;
static int refused_result;

static void main_task(intptr_t exinf)
{
	(void)exinf;
	loaded = lx_module_find(KBUILD_MODNAME);
	refused = loaded == THIS_MODULE ? &second_mod : THIS_MODULE;
	refused_result = refused->init_result;
}

int main(void)
{
	static const struct rtos_task_cfg tasks[] = { LXC_TASK(1, main_task, 8, true) };

	tap_plan(9);
	is_int(lx_module_param_set(KBUILD_MODNAME, "HwId", "4"), E_OK, "HwId=4 set before boot");
	for (int boot = 0; boot < 2; boot++) {
		if (!lxc_boot(tasks, 1, NULL, 0, NULL, 0))
			return tap_done();
		rtos_host_run_for(5 * NSEC_PER_MSEC);
		rtos_host_shutdown();
	}
	is_int(first_inits + second_inits, 2, "one init of the two per boot, two boots");
	ok(first_inits == 2 || second_inits == 2, "the same module loads at each boot");
	ok(loaded == THIS_MODULE || loaded == &second_mod, "lx_module_find names the loaded module");
	is_int(refused_result, -EEXIST, "the other one is refused with -EEXIST");
	is_int(refused->state, MODULE_STATE_UNFORMED, "and is uninitialised again after shutdown");
	is_int(first_exits + second_exits, 2, "one exit per boot: the refused module's exit is never called");
	ok((first_inits == 2) == (first_exits == 2), "the exit called is the loaded module's");
	ok(seen_HwId == 4 && HwId == 4 && second_HwId == 4,
	   "the parameter set before boot reaches both modules of the name: the loaded one's init saw it");
	return tap_done();
}

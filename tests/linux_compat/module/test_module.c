/*
 * test_module.c — module_init/module_exit run by the worker at boot in the
 * documented order (initcall level, then module name), a failing init's exit
 * is never called, lx_modules_exit runs exits in reverse, THIS_MODULE and
 * references, and module parameters of every type set before boot, from
 * the configuration or from the boot command line.
 */
#define KBUILD_MODNAME "lxtest"
#include "tap.h"
#include "lx_core_test.h"
#include "rtos_test.h"
#include <linux/module.h>
#include <linux/moduleparam.h>
#include <linux/init.h>
#include <linux/errno.h>
#include <linux/time64.h>
#include <linux_compat/sched.h>
#include <kernel.h>
#include <linux_compat/modparam.h>

static char *HwId = "in";
static int count = 3;
static unsigned int ucount;
static bool enable;
static bool quiet = true;
static short s_val;
static unsigned short us_val;
static long l_val;
static unsigned long ul_val;
static unsigned char b_val;
static int renamed_var;

module_param(HwId, charp, 0);
MODULE_PARM_DESC(HwId, "hardware id");
module_param(count, int, 0444);
module_param(ucount, uint, 0);
module_param(enable, bool, 0);
module_param(quiet, invbool, 0);
module_param(s_val, short, 0);
module_param(us_val, ushort, 0);
module_param(l_val, long, 0);
module_param(ul_val, ulong, 0);
module_param(b_val, byte, 0);
module_param_named(speed, renamed_var, int, 0);

static bool init_in_worker;
static char seen_hwid[8];
static int seen_count;

static int __init lxtest_init(void)
{
	rt_log("init:lxtest");
	init_in_worker = !sns_ctx() && lx_current_tskid() == LX_WORKER_TSKID;
	snprintf(seen_hwid, sizeof(seen_hwid), "%s", HwId);
	seen_count = count;
	return 0;
}

static void __exit lxtest_exit(void)
{
	rt_log("exit:lxtest");
}

module_init(lxtest_init);
module_exit(lxtest_exit);
MODULE_LICENSE("GPL");
MODULE_AUTHOR("ev3lx");
MODULE_DESCRIPTION("module table test");
MODULE_SUPPORTED_DEVICE("none");
MODULE_VERSION("1.0");
MODULE_ALIAS("lxtest-alias");

/* Other modules of the image, as separate translation units would register them. */
#define FAKE_MODULE(var, modname, initfn, exitfn, lvl)					\
	static struct module var = { .name = modname };					\
	static const struct lx_initcall var##_init = { &var, initfn, NULL, lvl };	\
	static const struct lx_initcall var##_exit = { &var, NULL, exitfn, lvl };	\
	static const struct lx_initcall *const var##_ptrs[2]				\
		__used __section(LX_INITCALL_SECTION) = { &var##_init, &var##_exit }

static int zeta_init(void)	{ rt_log("init:zeta"); return 0; }
static void zeta_exit(void)	{ rt_log("exit:zeta"); }
static int alpha_init(void)	{ rt_log("init:alpha"); return -ENODEV; }
static void alpha_exit(void)	{ rt_log("exit:alpha"); }
static int core_init(void)	{ rt_log("init:core_mod"); return 0; }
static void core_exit(void)	{ rt_log("exit:core_mod"); }

FAKE_MODULE(zeta_mod, "zeta", zeta_init, zeta_exit, LX_INITCALL_DEVICE);
FAKE_MODULE(alpha_mod, "alpha", alpha_init, alpha_exit, LX_INITCALL_DEVICE);
FAKE_MODULE(core_mod, "core_mod", core_init, core_exit, LX_INITCALL_CORE);

static bool ref_ok;
static char init_log[160];
static ER late_set;

static void main_task(intptr_t exinf)
{
	(void)exinf;
	memcpy(init_log, rt_log_text(), min(strlen(rt_log_text()), sizeof(init_log) - 1));
	late_set = lx_module_param_set("lxtest", "count", "9");
	ref_ok = try_module_get(THIS_MODULE) && module_refcount(THIS_MODULE) == 1 &&
		 !try_module_get(&alpha_mod);
	module_put(THIS_MODULE);
	rt_log_reset();
	lx_modules_exit();
}

int main(void)
{
	static const struct rtos_task_cfg tasks[] = { LXC_TASK(1, main_task, 8, true) };
	char buf[32];

	tap_plan(26);
	is_int(lx_module_param_set("lxtest", "HwId", "04"), E_OK, "charp parameter set before boot");
	is_int(lx_module_param_set("lxtest", "count", "-17"), E_OK, "int parameter");
	is_int(lx_module_param_set("lxtest", "ucount", "0x20"), E_OK, "uint parameter (hex)");
	is_int(lx_module_param_set("lxtest", "enable", "Y"), E_OK, "bool parameter");
	is_int(lx_module_param_set("lxtest", "quiet", "Y"), E_OK, "invbool parameter (Y stores false)");
	ok(lx_module_param_set("lxtest", "s_val", "-300") == E_OK &&
	   lx_module_param_set("lxtest", "us_val", "65535") == E_OK &&
	   lx_module_param_set("lxtest", "l_val", "-100000") == E_OK &&
	   lx_module_param_set("lxtest", "ul_val", "4000000000") == E_OK &&
	   lx_module_param_set("lxtest", "b_val", "255") == E_OK, "short, ushort, long, ulong, byte parameters");
	is_int(lx_module_param_set("lxtest", "speed", "12"), E_OK, "module_param_named: set by its public name");
	is_int(lx_module_param_set("lxtest", "b_val", "256"), E_PAR, "a byte out of range is rejected (E_PAR)");
	is_int(lx_module_param_set("lxtest", "count", "12x"), E_PAR, "malformed text is rejected (E_PAR)");
	is_int(lx_module_param_set("lxtest", "nosuch", "1"), E_NOEXS, "an unknown parameter is E_NOEXS");
	is_int(lx_module_param_set("d_nosuch", "HwId", "1"), E_NOEXS, "an unknown module is E_NOEXS");
	is_int(lx_module_param_set(NULL, "HwId", "1"), E_PAR, "NULL arguments are E_PAR");
	ok(count == -17 && ucount == 32 && enable && !quiet && s_val == -300 && us_val == 65535 &&
	   l_val == -100000 && ul_val == 4000000000UL && b_val == 255 && renamed_var == 12 &&
	   strcmp(HwId, "04") == 0, "every variable holds its parsed value");
	ok(lx_module_param_get("lxtest", "quiet", buf, sizeof(buf)) == E_OK && strcmp(buf, "Y") == 0,
	   "lx_module_param_get formats an invbool back (Y)");

	rt_log_reset();
	if (!lxc_boot(tasks, 1, NULL, 0, NULL, 0))
		return tap_done();
	rtos_host_run_for(5 * NSEC_PER_MSEC);
	rtos_host_shutdown();

	is_str(init_log, "init:core_mod init:alpha init:lxtest init:zeta",
	       "inits run by level, then by module name, whatever the link order");
	ok(init_in_worker, "module_init runs in task context, in the worker task");
	is_str(seen_hwid, "04", "the init saw the configured charp parameter");
	is_int(seen_count, -17, "...and the configured int parameter");
	is_int(late_set, E_OBJ, "setting a parameter after init is E_OBJ");
	is_int(alpha_mod.state, MODULE_STATE_UNFORMED, "state reset by lx_modules_exit");
	ok(ref_ok, "try_module_get/module_put on THIS_MODULE; a failed module refuses references");
	is_str(rt_log_text(), "exit:zeta exit:lxtest exit:core_mod",
	       "lx_modules_exit runs exits in reverse init order, never the failed module's");
	is_str(THIS_MODULE->name, "lxtest", "THIS_MODULE is the module named by KBUILD_MODNAME");
	ok(lx_module_find("zeta") == &zeta_mod && lx_module_find("none") == NULL, "lx_module_find");

	/* The boot loader's command line: module words set parameters, others are skipped. */
	rtos_host_set_boot_args("console=ttyS1,115200  lxtest.count=41 lxtest.HwId=bt lxtest.nosuch=1 quiet d_nosuch.x=2");
	if (!lxc_boot(tasks, 1, NULL, 0, NULL, 0))
		return tap_done();
	rtos_host_run_for(5 * NSEC_PER_MSEC);
	rtos_host_shutdown();
	rtos_host_set_boot_args(NULL);
	ok(seen_count == 41 && strcmp(seen_hwid, "bt") == 0,
	   "module.param=value boot arguments are set before the module's init");
	ok(count == 41 && strcmp(HwId, "bt") == 0, "...and the other words of the command line are left alone");
	return tap_done();
}

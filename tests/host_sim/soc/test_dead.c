/*
 * test_dead.c — a driver that forgets a step sees a dead peripheral and the
 * run says so: an unpowered module (PSC), a pin not muxed to GPIO, a SYSCFG
 * write without the kick unlock.  Also the boot states (what Linux leaves
 * versus TRM reset) and the model-side watchers of PSC and SYSCFG.
 */
#include <string.h>

#include "tap.h"
#include "sil.h"
#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/gpio.h"
#include "host_sim/psc.h"
#include "host_sim/scenario.h"
#include "host_sim/syscfg.h"

#define GPIO       0x01E26000U
#define PAIR(n)    (GPIO + HS_GPIO_PAIR_OFFSET(32U * (n)))
#define SYSCFG0    0x01C14000U
#define KICK0R     (SYSCFG0 + 0x38)
#define KICK1R     (SYSCFG0 + 0x3C)
#define PINMUX(n)  (SYSCFG0 + 0x120 + 4 * (n))
#define CFGCHIP1   (SYSCFG0 + HS_SYSCFG0_CFGCHIP(1))
#define PSC1       0x01E27000U
#define MDCTL(n)   (PSC1 + 0xA00 + 4 * (n))
#define MDSTAT(n)  (PSC1 + 0x800 + 4 * (n))
#define PTCMD      (PSC1 + 0x120)
#define PTSTAT     (PSC1 + 0x128)

#define MOTOR      HS_GPIO(3, 15)     /* PINMUX7[3:0] */
#define MOTOR_BIT  (1U << 31)

static uint32_t rd(uint32_t phys)
{
	return sil_rew_mem(rtos_host_map_io(phys, 4));
}

static void wr(uint32_t phys, uint32_t v)
{
	sil_wrw_mem(rtos_host_map_io(phys, 4), v);
}

static struct {
	unsigned n;
	uint32_t offset, old, now;
} sys_log;

static struct {
	unsigned n;
	enum hs_psc_state old, now;
} psc_log;

static void sys_watch(void *ctx, uint32_t offset, uint32_t old, uint32_t now)
{
	(void)ctx;
	sys_log.n++;
	sys_log.offset = offset;
	sys_log.old = old;
	sys_log.now = now;
}

static void psc_watch(void *ctx, unsigned module, enum hs_psc_state old, enum hs_psc_state now)
{
	(void)ctx; (void)module;
	psc_log.n++;
	psc_log.old = old;
	psc_log.now = now;
}

#define EXPECT_BUG(code, needle, ...) do { \
	uint_t before_ = rtos_host_bug_count(); \
	code; \
	ok(rtos_host_bug_count() == before_ + 1U && strstr(rtos_host_last_bug(), (needle)) != NULL, __VA_ARGS__); \
	if (rtos_host_bug_count() != before_ + 1U || !strstr(rtos_host_last_bug(), (needle))) \
		tap_diag("  bugs %u -> %u, last: %s", before_, rtos_host_bug_count(), rtos_host_last_bug()); \
} while (0)

static const struct rtos_cfg cfg = { .name = "dead" };

int main(void)
{
	struct hs_scenario warm = { .rtos = &cfg };
	struct hs_scenario cold = { .rtos = &cfg, .board = &(struct hs_board_cfg){ .cold_reset = true } };

	tap_plan(23);

	/* ---- What Linux leaves ---- */
	if (hs_sim_boot(&warm) != E_OK)
		tap_bail_out("boot failed");
	ok(hs_psc_enabled(HS_PSC1_MODULE(HS_LPSC1_GPIO)) && hs_psc_enabled(HS_PSC1_MODULE(HS_LPSC1_UART1)) &&
	   hs_psc_enabled(HS_PSC0_MODULE(HS_LPSC0_SPI0)) && hs_psc_enabled(HS_PSC0_MODULE(HS_LPSC0_UART0)),
	   "Linux leaves GPIO, UART0/1 and SPI0 powered");
	ok(!hs_psc_enabled(HS_PSC1_MODULE(HS_LPSC1_EHRPWM)) && !hs_psc_enabled(HS_PSC1_MODULE(HS_LPSC1_ECAP)),
	   "eHRPWM and eCAP are off until a driver powers them");
	ok(hs_syscfg_unlocked(), "SYSCFG0 is left unlocked");
	is_int(hs_syscfg_pinmux_field(7, 0), 8, "the EV3's GPIO pins are muxed to GPIO");

	/* Watchers */
	ok(hs_syscfg_watch(sys_watch, NULL) > 0 && hs_psc_watch(HS_PSC1_MODULE(HS_LPSC1_EHRPWM), psc_watch, NULL) > 0,
	   "watchers registered");
	wr(CFGCHIP1, rd(CFGCHIP1) | HS_CFGCHIP1_TBCLKSYNC);
	ok(hs_syscfg_tbclksync() && sys_log.n == 1 && sys_log.offset == HS_SYSCFG0_CFGCHIP(1) && sys_log.now == HS_CFGCHIP1_TBCLKSYNC,
	   "TBCLKSYNC set: the SYSCFG watcher sees CFGCHIP1 change");
	wr(MDCTL(17), 3);
	wr(PTCMD, 1);
	ok(psc_log.n == 1 && psc_log.old == HS_PSC_SWRSTDISABLE && psc_log.now == HS_PSC_ENABLE,
	   "the PSC watcher sees eHRPWM enabled");
	is_int(rd(PTSTAT), 0, "PTSTAT: no transition in progress");
	is_int(rd(MDSTAT(17)) & 0x3F, 3, "MDSTAT17: Enable");

	/* Lock, then write: dropped and reported */
	wr(KICK0R, 0);
	wr(KICK1R, 0);
	ok(!hs_syscfg_unlocked(), "writing 0 to the kick registers locks");
	rtos_host_expect_bugs(true);
	EXPECT_BUG(wr(PINMUX(7), 0), "SYSCFG0.PINMUX[7] (0x01c1413c)", "a PINMUX write while locked is reported");
	is_int(hs_syscfg_pinmux_field(7, 0), 8, "and dropped");
	wr(KICK0R, HS_KICK0_UNLOCK);
	wr(KICK1R, HS_KICK1_UNLOCK);

	/* A pin that is not muxed to GPIO does not move */
	wr(PINMUX(7), rd(PINMUX(7)) & ~0xFU);
	wr(PAIR(1) + 0x00, rd(PAIR(1) + 0x00) & ~MOTOR_BIT);       /* DIR: output */
	EXPECT_BUG(wr(PAIR(1) + 0x08, MOTOR_BIT), "GP3_15, an output pin whose PINMUX7[3:0] is 0, not GPIO (8)",
		   "driving an output pin muxed elsewhere is reported");
	ok(!hs_gpio_level(MOTOR) && !hs_gpio_soc_output(MOTOR, NULL), "and the pin stays undriven");
	wr(PINMUX(7), rd(PINMUX(7)) | 0x8U);
	ok(hs_gpio_level(MOTOR) && hs_gpio_soc_output(MOTOR, NULL), "muxing it to GPIO connects the driven level");

	/* Powering GPIO down kills it */
	hs_psc_force(HS_PSC1_MODULE(HS_LPSC1_GPIO), HS_PSC_DISABLE);
	EXPECT_BUG((void)rd(PAIR(1) + 0x10), "GPIO is not powered (PSC1 module 3 is Disable", "GPIO access with GPIO off");
	rtos_host_expect_bugs(false);
	hs_sim_shutdown();

	/* ---- TRM reset ---- */
	if (hs_sim_boot(&cold) != E_OK)
		tap_bail_out("cold boot failed");
	ok(!hs_syscfg_unlocked() && !hs_psc_enabled(HS_PSC1_MODULE(HS_LPSC1_GPIO)), "cold: SYSCFG locked, GPIO off");
	rtos_host_expect_bugs(true);
	EXPECT_BUG((void)rd(PAIR(0) + 0x10), "GPIO is not powered", "cold: a driver that skips the PSC sees a dead GPIO");
	wr(MDCTL(3), 3);
	wr(PTCMD, 1);
	is_int(rd(PAIR(0) + 0x00), 0xFFFFFFFF, "after MDCTL3 = Enable and PTCMD.GO the GPIO answers");
	EXPECT_BUG(wr(PINMUX(7), 0x8U), "while SYSCFG0 is locked", "cold: pinmux without unlock is reported");
	wr(KICK0R, HS_KICK0_UNLOCK);
	wr(KICK1R, HS_KICK1_UNLOCK);
	wr(PINMUX(7), 0x8U);
	is_int(hs_syscfg_pinmux_field(7, 0), 8, "with the unlock it takes effect");
	wr(PAIR(1) + 0x08, MOTOR_BIT);
	wr(PAIR(1) + 0x00, ~MOTOR_BIT);
	ok(hs_gpio_level(MOTOR), "and the pin is driven");
	is_int(rtos_host_bug_count(), 2, "two bugs in the cold run, both expected");
	rtos_host_expect_bugs(false);
	hs_sim_shutdown();
	return tap_done();
}

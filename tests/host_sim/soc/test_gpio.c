/*
 * test_gpio.c — GPIO pins: external drive, pulls and SoC output resolved
 * into IN_DATA; SET/CLR_DATA acting on OUT_DATA; edges enabled by the
 * trigger registers setting INTSTAT and raising the bank interrupt through
 * BINTEN, delivered to the ISR in order at the virtual time of the edge;
 * watchers; and the AINTC register view of the same line.
 */
#include <string.h>

#include "tap.h"
#include "sil.h"
#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/clock.h"
#include "host_sim/gpio.h"
#include "host_sim/intc.h"
#include "host_sim/scenario.h"
#include "host_sim/trace.h"

#define GPIO       0x01E26000U
#define BINTEN     (GPIO + HS_GPIO_BINTEN)
#define PAIR(n)    (GPIO + HS_GPIO_PAIR_OFFSET(32U * (n)))
#define DIR        HS_GPIO_DIR
#define OUT_DATA   HS_GPIO_OUT_DATA
#define SET_DATA   HS_GPIO_SET_DATA
#define CLR_DATA   HS_GPIO_CLR_DATA
#define IN_DATA    HS_GPIO_IN_DATA
#define SET_RIS    HS_GPIO_SET_RIS_TRIG
#define CLR_RIS    HS_GPIO_CLR_RIS_TRIG
#define SET_FAL    HS_GPIO_SET_FAL_TRIG
#define CLR_FAL    HS_GPIO_CLR_FAL_TRIG
#define INTSTAT    HS_GPIO_INTSTAT
#define AINTC      0xFFFEE000U

#define TACHO      HS_GPIO(5, 11)     /* bank 5: pair 2, bit 27 */
#define TACHO_BIT  (1U << 27)
#define OTHER      HS_GPIO(5, 8)
#define OTHER_BIT  (1U << 24)
#define MOTOR      HS_GPIO(3, 15)     /* bank 3: pair 1, bit 31 */
#define MOTOR_BIT  (1U << 31)

static struct {
	unsigned n;
	uint64_t t[16];
	uint32_t stat[16];
} isr_log;

static struct {
	unsigned n;
	struct hs_pin_state last;
} watch_log;

static uint32_t rd(uint32_t phys)
{
	return sil_rew_mem(rtos_host_map_io(phys, 4));
}

static void wr(uint32_t phys, uint32_t v)
{
	sil_wrw_mem(rtos_host_map_io(phys, 4), v);
}

/* The bank 5 ISR, like a driver's: read INTSTAT, acknowledge it. */
static void bank5_isr(intptr_t x)
{
	uint64_t now = hs_now();
	uint32_t st = rd(PAIR(2) + INTSTAT);

	(void)x;
	if (isr_log.n < 16U) {
		isr_log.t[isr_log.n] = now;
		isr_log.stat[isr_log.n] = st;
		isr_log.n++;
	}
	wr(PAIR(2) + INTSTAT, st);
}

static void motor_watch(void *ctx, unsigned pin, const struct hs_pin_state *st)
{
	(void)ctx; (void)pin;
	watch_log.n++;
	watch_log.last = *st;
}

static void tacho_high(void *arg) { (void)arg; hs_gpio_set_input(TACHO, 1); }
static void tacho_low(void *arg)  { (void)arg; hs_gpio_set_input(TACHO, 0); }
static void other_high(void *arg) { (void)arg; hs_gpio_set_input(OTHER, 1); }

static const struct rtos_int_cfg ints[] = { { HS_GPIO_BANK_INTNO(5), TA_ENAINT, -3 } };
static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, HS_GPIO_BANK_INTNO(5), bank5_isr, 1 } };
static const struct rtos_cfg cfg = { .name = "gpio", .ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(isrs) };

int main(void)
{
	struct hs_scenario scn = { .rtos = &cfg };
	struct hs_signal *sig;
	uint64_t t0;
	bool lvl;

	tap_plan(37);
	if (hs_sim_boot(&scn) != E_OK)
		tap_bail_out("boot failed");

	/* Inputs */
	is_int(rd(PAIR(2) + DIR), 0xFFFFFFFF, "all pins are inputs at reset");
	hs_gpio_drive(TACHO, HS_EXT_HIGH);
	ok(rd(PAIR(2) + IN_DATA) & TACHO_BIT, "a driven-high input reads 1");
	hs_gpio_drive(TACHO, HS_EXT_FLOAT);
	ok(!(rd(PAIR(2) + IN_DATA) & TACHO_BIT), "a floating input reads 0");
	hs_gpio_drive(TACHO, HS_EXT_PULL_UP);
	ok(rd(PAIR(2) + IN_DATA) & TACHO_BIT, "a pulled-up input reads 1");
	hs_gpio_drive(TACHO, HS_EXT_LOW);
	is_int(rd(PAIR(2) + INTSTAT), 0, "edges without triggers set no status");

	/* Outputs, SET/CLR_DATA and watchers */
	ok(hs_gpio_watch(MOTOR, motor_watch, NULL) > 0, "watch a motor pin");
	hs_gpio_drive(MOTOR, HS_EXT_PULL_DOWN);
	wr(PAIR(1) + SET_DATA, MOTOR_BIT);
	is_int(rd(PAIR(1) + OUT_DATA), MOTOR_BIT, "SET_DATA sets OUT_DATA bits");
	ok(!(rd(PAIR(1) + IN_DATA) & MOTOR_BIT), "still an input: the pull-down wins");
	wr(PAIR(1) + DIR, rd(PAIR(1) + DIR) & ~MOTOR_BIT);
	ok(rd(PAIR(1) + IN_DATA) & MOTOR_BIT, "output enabled: IN_DATA reads the driven 1");
	ok(watch_log.last.soc_drives && watch_log.last.soc_level && watch_log.last.level,
	   "the watcher sees the SoC driving high");
	wr(PAIR(1) + CLR_DATA, MOTOR_BIT);
	ok(!hs_gpio_level(MOTOR) && rd(PAIR(1) + OUT_DATA) == 0, "CLR_DATA clears it");
	is_int(rd(PAIR(1) + SET_DATA), 0, "SET_DATA reads OUT_DATA");
	wr(PAIR(1) + DIR, rd(PAIR(1) + DIR) | MOTOR_BIT);
	ok(!watch_log.last.soc_drives, "floating again: the watcher sees no SoC drive");
	is_int(watch_log.n, 5, "one watcher call per change (pull, OUT_DATA, DIR, CLR_DATA, DIR)");

	/* hs_gpio_drive on an output pin (the SoC side decides) and on an input (the drive does) */
	wr(PAIR(1) + DIR, rd(PAIR(1) + DIR) & ~MOTOR_BIT);
	hs_gpio_drive(MOTOR, HS_EXT_HIGH);
	ok(watch_log.last.soc_drives && !watch_log.last.level && watch_log.last.contention,
	   "an external high against the SoC's low: contention, the SoC's level");
	ok(hs_gpio_soc_output_or_level(MOTOR, &lvl) && !lvl, "the SoC drives it, low");
	wr(PAIR(1) + DIR, rd(PAIR(1) + DIR) | MOTOR_BIT);
	ok(watch_log.last.level && !watch_log.last.contention, "an input again: the external high");
	ok(!hs_gpio_soc_output_or_level(MOTOR, &lvl) && lvl, "not driven by the SoC: its level, high");
	hs_gpio_drive(MOTOR, HS_EXT_LOW);
	ok(!watch_log.last.soc_drives && !watch_log.last.level && !hs_gpio_level(MOTOR) &&
	   !(rd(PAIR(1) + IN_DATA) & MOTOR_BIT) && watch_log.n == 9,
	   "an input follows its drive, the watcher told of each change");

	/* Edge -> INTSTAT -> bank interrupt -> ISR */
	wr(PAIR(2) + SET_RIS, TACHO_BIT);
	wr(PAIR(2) + SET_FAL, TACHO_BIT);
	is_int(rd(PAIR(2) + SET_FAL), TACHO_BIT, "trigger registers read back");
	hs_gpio_set_input(TACHO, 1);
	is_int(rd(PAIR(2) + INTSTAT), TACHO_BIT, "an enabled edge sets INTSTAT with BINTEN off");
	ok(isr_log.n == 0 && !hs_intc_pending(HS_GPIO_BANK_INTNO(5)), "but raises no interrupt");
	wr(PAIR(2) + INTSTAT, TACHO_BIT);
	is_int(rd(PAIR(2) + INTSTAT), 0, "INTSTAT is write-1-to-clear");
	wr(BINTEN, 1U << 5);

	t0 = hs_now();
	hs_event_at(t0 + 1000000, tacho_low, NULL);
	hs_event_at(t0 + 2000000, tacho_high, NULL);
	hs_event_at(t0 + 2000000, other_high, NULL);
	hs_sim_run_for(3000000);
	is_int(isr_log.n, 2, "falling edge, then two rising edges at one instant: two ISR runs");
	is_u64(isr_log.t[0], t0 + 1000000, "the first ISR runs at the edge's virtual time");
	is_int(isr_log.stat[0], TACHO_BIT, "and sees its pin in INTSTAT");
	is_u64(isr_log.t[1], t0 + 2000000, "the second ISR runs at the second edge's time");
	is_int(isr_log.stat[1], TACHO_BIT, "OTHER has no trigger: only the tacho bit");
	is_int(rd(PAIR(2) + INTSTAT), 0, "the ISR acknowledged");

	wr(PAIR(2) + SET_RIS, OTHER_BIT);
	wr(PAIR(2) + CLR_FAL, TACHO_BIT);
	isr_log.n = 0;
	t0 = hs_now();
	hs_event_at(t0 + 500000, tacho_low, NULL);
	hs_sim_run_for(1000000);
	is_int(isr_log.n, 0, "CLR_FAL_TRIG disables the falling edge");
	hs_gpio_set_input(OTHER, 0);
	hs_event_at(hs_now() + 1000, tacho_high, NULL);
	hs_event_at(hs_now() + 1000, other_high, NULL);
	hs_sim_run_for(10000);
	/* The first edge's ISR starts before the second event of the same instant
	 * runs; that edge is pending when the first ISR (two 50-ns accesses) ends. */
	ok(isr_log.n == 2 && isr_log.stat[0] == TACHO_BIT && isr_log.stat[1] == OTHER_BIT &&
	   isr_log.t[1] == isr_log.t[0] + 100, "two edges at one instant: ISRs in event order, back to back");

	/* AINTC register view */
	is_int(rd(AINTC + 0x300 + 4) & (1U << (47 - 32)), 1U << (47 - 32), "ESR2 shows line 47 enabled");
	wr(AINTC + 0x02C, 47);        /* EICR */
	ok(!rtos_host_irq_enabled(47), "EICR disables the line in the kernel");
	isr_log.n = 0;
	hs_gpio_set_input(TACHO, 0);
	hs_gpio_set_input(TACHO, 1);
	hs_sim_run_for(1000);
	ok(isr_log.n == 0 && (rd(AINTC + 0x200 + 4) & (1U << 15)), "disabled: SRSR2 shows it pending, no ISR");
	is_int(rd(AINTC + 0x904), 0x80000000, "HIPIR2: nothing enabled is pending");
	wr(AINTC + 0x028, 47);        /* EISR */
	hs_sim_run_for(1000);
	is_int(isr_log.n, 1, "EISR enables it and the pending request is delivered");

	sig = hs_trace_find("gpio", "GP5_11");
	ok(sig && hs_signal_value(sig) == 1 && hs_signal_changes(sig) > 6, "the pin has a trace signal");
	hs_sim_shutdown();
	return tap_done();
}

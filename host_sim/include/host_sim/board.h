/*
 * board.h — the simulated AM1808 as the EV3 boots it.  Host only.
 *
 * hs_board_init creates the core regions (AINTC, GPIO, TIMER64P3, SYSCFG0/1,
 * PSC0/1, PLLC0/1) at their physical addresses, then the peripheral models
 * listed in the configuration (eHRPWM, eCAP, SPI0 with the ADC, UARTs: see
 * host_sim/devices/), and installs the register-access handler in rtos_stub,
 * so ioremap/readl/sil_*_mem reach the models.  The state is the one U-Boot
 * and Linux leave behind (GPIO, UARTs and SPI0 powered; eHRPWM and eCAP not).
 *
 * The one sequence (scenario.h's hs_sim_boot does all of it):
 *   hs_board_init(&board);     regions and handler, before any driver code runs
 *   rtos_host_boot(&cfg);      ATT_INI routines may already ioremap and access registers
 *   hs_board_start();          models begin their own activity (events on the virtual clock)
 *   ... rtos_host_run_for(...) ...
 *   rtos_host_shutdown();
 *   hs_board_shutdown();       closes traces, frees regions and models
 */
#ifndef HOST_SIM_BOARD_H
#define HOST_SIM_BOARD_H

#include <stdbool.h>
#include <stdint.h>
#include "t_stddef.h"

/* Physical base addresses (AM1808 / DA850 memory map). */
#define HS_PSC0_BASE       0x01C10000U
#define HS_PLLC0_BASE      0x01C11000U
#define HS_SYSCFG0_BASE    0x01C14000U
#define HS_SPI0_BASE       0x01C41000U
#define HS_UART0_BASE      0x01C42000U
#define HS_UART1_BASE      0x01D0C000U
#define HS_PLLC1_BASE      0x01E1A000U
#define HS_GPIO_BASE       0x01E26000U
#define HS_PSC1_BASE       0x01E27000U
#define HS_SYSCFG1_BASE    0x01E2C000U
#define HS_EHRPWM0_BASE    0x01F00000U
#define HS_EHRPWM1_BASE    0x01F02000U
#define HS_ECAP0_BASE      0x01F06000U
#define HS_ECAP1_BASE      0x01F07000U
#define HS_TIMER64P3_BASE  0x01F0D000U
#define HS_TIMER64P1_BASE  0x01C21000U
#define HS_TIMER64P1_INPUT_HZ HS_OSCIN_HZ  /* TIMER64P0/P1 count the 24 MHz oscillator */
#define HS_TIMER64P1_TINT12 23U            /* AINTC lines of TIMER64P1's period interrupts */
#define HS_TIMER64P1_TINT34 24U
#define HS_AINTC_BASE      0xFFFEE000U

/* Clocks of the modelled board (EV3: 24 MHz crystal, PLL0 300 MHz, PLL1 132 MHz as LEGO sets it). */
#define HS_OSCIN_HZ        24000000U
#define HS_PLL0_SYSCLK2_HZ 150000000U   /* SPI0, UART0 */
#define HS_PLL1_SYSCLK2_HZ 132000000U   /* ASYNC3 domain as LEGO sets it: UART1, eHRPWM, eCAP, TIMER64P2/3 */

/* A peripheral model the board creates: E's device models provide these. */
struct hs_board_cfg;
struct hs_device {
	const char *name;
	/* Creates the model: registers its regions, watches pins, declares trace
	 * signals; *ctx receives its state.  Returns E_OK or an error (boot fails). */
	ER   (*create)(const struct hs_board_cfg *cfg, void **ctx);
	/* Called by hs_board_start after rtos_host_boot: schedule initial events. May be NULL. */
	void (*start)(void *ctx);
	/* Frees the model (hs_board_shutdown). May be NULL. */
	void (*destroy)(void *ctx);
};

struct hs_board_cfg {
	/* Peripheral models to create, NULL-terminated (e.g. the table the
	 * devices headers provide: ev3_board_devices); NULL: core peripherals only. */
	const struct hs_device *const *devices;
	/* Virtual CPU time one register access costs; 0: HS_ACCESS_NS_DEFAULT. */
	uint32_t access_ns;
	/* true: everything at TRM reset (PSC modules off, SYSCFG locked) instead
	 * of the state Linux and U-Boot leave. */
	bool cold_reset;
	/* true: do not trap plain pointer accesses; windows are then reachable
	 * only through the accessors (sil_*_mem, readl...). */
	bool no_trap;
	/* true: no check that GPIO pins used as outputs are muxed to GPIO. */
	bool no_pinmux_check;
};

#define HS_ACCESS_NS_DEFAULT 50U

/* Creates the board (see the sequence above); cfg may be NULL for the
 * defaults.  Returns E_OK, E_OBJ if a board exists, or a device's error. */
ER hs_board_init(const struct hs_board_cfg *cfg);

/* Adds one more peripheral model to the running board (create, and start
 * too if hs_board_start already ran). */
ER hs_board_add_device(const struct hs_device *dev);

/* Starts the models' own activity; call after rtos_host_boot. */
void hs_board_start(void);

/* Destroys models and regions and uninstalls the handler.  Harmless twice. */
void hs_board_shutdown(void);

/* true between hs_board_init and hs_board_shutdown. */
bool hs_board_active(void);

/* The configuration in effect (defaults filled in); NULL without a board. */
const struct hs_board_cfg *hs_board_config(void);

/* true if plain pointer accesses to windows are trapped and emulated here
 * (x86-64 Linux); false means accessor path only (e.g. under qemu-arm). */
bool hs_board_traps_pointers(void);
/* Why trapping is unavailable (for SKIP messages), or "" if it is available. */
const char *hs_board_trap_unavailable_reason(void);

#endif /* HOST_SIM_BOARD_H */

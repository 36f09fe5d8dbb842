/*
 * gpio.h — the AM1808 GPIO pins as models see them.  Host only.
 *
 * Pins are numbered as DaVinci does: HS_GPIO(bank, bit) = 16*bank + bit, so
 * GP5_11 is 91.  Each pin has an SoC side (DIR/OUT_DATA through the
 * registers, effective only while the pin is muxed to GPIO) and an external
 * side a model drives (strongly, weakly through a pull, or not at all).  The
 * resolved level feeds IN_DATA and the edge detectors: an edge enabled by
 * SET_RIS_TRIG/SET_FAL_TRIG sets INTSTAT and, if BINTEN enables the bank,
 * raises the bank interrupt (bank b: AINTC system interrupt 42 + b).
 * Changing a pin is O(1) plus the watchers (motors make thousands of tacho
 * edges per second).
 */
#ifndef HOST_SIM_GPIO_H
#define HOST_SIM_GPIO_H

#include <stdbool.h>
#include <stdint.h>

#define HS_GPIO(bank, bit)  ((unsigned)(bank) * 16U + (unsigned)(bit))
#define HS_GPIO_BANKS       9U
#define HS_GPIO_NPINS       (HS_GPIO_BANKS * 16U)
#define HS_GPIO_BANK_INTNO(bank) (42U + (unsigned)(bank))

/* Register layout (AM1808 TRM, GPIO chapter): BINTEN, then one block per
 * pair of banks (32 pins) at HS_GPIO_PAIR_OFFSET, in which a pin is bit
 * HS_GPIO_PAIR_BIT of every register. */
#define HS_GPIO_BINTEN            0x08U
#define HS_GPIO_PAIR_STRIDE       0x28U
#define HS_GPIO_PAIRS             ((HS_GPIO_NPINS + 31U) / 32U)
#define HS_GPIO_PAIR_OFFSET(pin)  (0x10U + HS_GPIO_PAIR_STRIDE * ((unsigned)(pin) / 32U))
#define HS_GPIO_PAIR_BIT(pin)     (1U << ((unsigned)(pin) % 32U))
#define HS_GPIO_DIR               0x00U   /* offsets in a pair's block; DIR bit 1 = input */
#define HS_GPIO_OUT_DATA          0x04U
#define HS_GPIO_SET_DATA          0x08U
#define HS_GPIO_CLR_DATA          0x0CU
#define HS_GPIO_IN_DATA           0x10U
#define HS_GPIO_SET_RIS_TRIG      0x14U
#define HS_GPIO_CLR_RIS_TRIG      0x18U
#define HS_GPIO_SET_FAL_TRIG      0x1CU
#define HS_GPIO_CLR_FAL_TRIG      0x20U
#define HS_GPIO_INTSTAT           0x24U

/* What the outside world does to a pin. */
enum hs_pin_ext {
	HS_EXT_FLOAT = 0,   /* nothing connected: the pin reads 0 unless the SoC drives it */
	HS_EXT_LOW,         /* driven low */
	HS_EXT_HIGH,        /* driven high */
	HS_EXT_PULL_DOWN,   /* weak pull: loses against the SoC's output */
	HS_EXT_PULL_UP,
};

struct hs_pin_state {
	bool soc_drives;        /* DIR bit 0 and the pin muxed to GPIO: the SoC drives soc_level */
	bool soc_level;         /* OUT_DATA bit */
	bool muxed_gpio;        /* PINMUX selects GPIO for this pin (or unknown: assumed) */
	enum hs_pin_ext ext;
	bool level;             /* resolved level: what IN_DATA reads */
	bool contention;        /* SoC and the outside drive opposite levels */
};

/* A watcher: called after the pin's SoC side, external side or level changed. */
typedef void (*hs_pin_watch_fn)(void *ctx, unsigned pin, const struct hs_pin_state *st);

/* The outside world drives pin (the external side).  Triggers edges. */
void hs_gpio_drive(unsigned pin, enum hs_pin_ext ext);
/* Shorthand: drive high (level != 0) or low. */
void hs_gpio_set_input(unsigned pin, int level);

/* Resolved level of the pin (0 or 1). */
bool hs_gpio_level(unsigned pin);
/* Full state of the pin. */
void hs_gpio_state(unsigned pin, struct hs_pin_state *st);
/* true if the SoC drives the pin; *level receives the driven level. */
bool hs_gpio_soc_output(unsigned pin, bool *level);
/* hs_gpio_soc_output, with *level the resolved level (hs_gpio_level) when
 * the SoC does not drive the pin: one call for a model that needs either. */
bool hs_gpio_soc_output_or_level(unsigned pin, bool *level);

/* Calls fn on every change of pin; returns a handle > 0, or 0 if out of slots. */
int hs_gpio_watch(unsigned pin, hs_pin_watch_fn fn, void *ctx);
/* Removes a watcher (harmless for 0 or an unknown handle). */
void hs_gpio_unwatch(int handle);

/* Muxes pin to GPIO (SYSCFG0 PINMUXn, unlock not needed): what the board code
 * does for the pins a driver expects muxed.  No effect where host_sim does not
 * know the pin's mux field (banks 0, 7, 8). */
void hs_gpio_mux_as_gpio(unsigned pin);

/* Pin name "GP<bank>_<bit>" into buf (at least 8 bytes); returns buf. */
const char *hs_gpio_name(unsigned pin, char *buf);
/* Pin number for a name like "GP5_11", or -1. */
int hs_gpio_parse(const char *name);

#endif /* HOST_SIM_GPIO_H */

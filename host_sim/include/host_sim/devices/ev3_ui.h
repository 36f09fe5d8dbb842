/*
 * ev3_ui.h — the EV3 brick's user interface: six buttons and two bicolour
 * LEDs on GPIO pins.  Host only.  docs/host-sim-devices.md ("Brick buttons
 * and LEDs").
 *
 * Pins (ev3_ui_pins) follow ev3dev's EV3 board support as far as we know it,
 * NOT from LEGO's published sources: check them against the EV3 schematic before relying
 * on them.  A button connects its pin to 3.3 V (pressed = high; a pull-down
 * holds it low when released); an LED colour is lit while the SoC drives its
 * pin high.  The board leaves the ten pins muxed to GPIO, as U-Boot/Linux
 * board code does on the brick.
 *
 * Buttons change now (ev3_ui_button_set) or at scenario times (ev3_ui_button_at,
 * ev3_ui_click_at), with optional contact bounce; traces: "ui.btn_<name>"
 * (1 = pressed contact) and "ui.led_left"/"ui.led_right" (an ev3_ui_color).
 */
#ifndef HOST_SIM_DEVICES_EV3_UI_H
#define HOST_SIM_DEVICES_EV3_UI_H

#include <stdbool.h>
#include <stdint.h>
#include "kernel.h"
#include "host_sim/board.h"

/* The buttons, in LEGO's order (d_ui's lms_ui.h uses the same). */
enum ev3_ui_button {
	EV3_UI_BUTTON_UP = 0,
	EV3_UI_BUTTON_ENTER,
	EV3_UI_BUTTON_DOWN,
	EV3_UI_BUTTON_RIGHT,
	EV3_UI_BUTTON_LEFT,
	EV3_UI_BUTTON_BACK,
	EV3_UI_BUTTONS
};

enum ev3_ui_led { EV3_UI_LED_LEFT = 0, EV3_UI_LED_RIGHT, EV3_UI_LEDS };

/* What an LED shows: its red and green halves (1 = red, 2 = green, 3 = both). */
enum ev3_ui_color {
	EV3_UI_LED_OFF = 0,
	EV3_UI_LED_RED = 1,
	EV3_UI_LED_GREEN = 2,
	EV3_UI_LED_ORANGE = 3,
};

struct ev3_ui_pins {
	unsigned button[EV3_UI_BUTTONS];   /* HS_GPIO(bank, bit), by enum ev3_ui_button */
	unsigned red[EV3_UI_LEDS];         /* by enum ev3_ui_led */
	unsigned green[EV3_UI_LEDS];
};

extern const struct ev3_ui_pins ev3_ui_pins;

/* The board device (listed in ev3_board_devices). */
extern const struct hs_device ev3_ui_device;

/* Contact bounce after every button change: a few extra toggles spread over
 * about bounce_us (0: clean contacts, the default; at most
 * EV3_UI_MAX_BOUNCE_US, else E_PAR).  E_OBJ without a board. */
#define EV3_UI_MAX_BOUNCE_US 100000U
ER ev3_ui_set_bounce(uint32_t bounce_us);

/* Presses or releases a button now.  E_ID for a bad button, E_OBJ without a board. */
ER ev3_ui_button_set(enum ev3_ui_button button, bool pressed);
/* The same at absolute virtual time t_ns (>= now; E_PAR otherwise). */
ER ev3_ui_button_at(uint64_t t_ns, enum ev3_ui_button button, bool pressed);
/* A click: pressed at t_ns, released hold_ns later (hold_ns > 0). */
ER ev3_ui_click_at(uint64_t t_ns, enum ev3_ui_button button, uint64_t hold_ns);
/* Whether the user holds the button down now (before bounce: the intent). */
bool ev3_ui_button_held(enum ev3_ui_button button);
/* Level changes of the button's contact so far (bounces included). */
uint32_t ev3_ui_contact_changes(enum ev3_ui_button button);

/* What the LED shows now, read from its two pins. */
enum ev3_ui_color ev3_ui_led_color(enum ev3_ui_led led);
/* Colour changes of the LED so far (blinking counts every change). */
uint32_t ev3_ui_led_changes(enum ev3_ui_led led);

#endif /* HOST_SIM_DEVICES_EV3_UI_H */

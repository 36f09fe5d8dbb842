/*
 * ev3_power.h — the EV3's battery and power pins.  Host only.
 *
 * The battery is an EMF (ev3_set_battery_mv in ev3_brick.h, 9000 mV by
 * default) behind an internal resistance: the terminal voltage sags by
 * R × I, I being the brick's own draw (EV3_POWER_BRICK_MA) plus the motor
 * currents.  The ADC's battery channels show it through the front end
 * LEGO's FINAL boards have (and EV3RT always assumes):
 *   BatteryCurrent (ch 3)  I through a 0.11 Ω shunt, amplified 22×
 *   Cell123456     (ch 4)  (V_terminal − 0.11 Ω × I − 0.05 V diode) / 2
 *   MotorCurrent   (ch 15) the motors' current through 0.055 Ω, amplified 19×
 * so that V(Cell)/0.5 + V(BatteryCurrent)/22 + 0.05 gives the terminal
 * voltage back (LEGO's c_ui conversion).  Each channel saturates at 5 V.
 * The motors themselves are driven from the EMF: the sag is an ADC-side
 * effect only (the motor model's current depends on its supply, so a
 * shared sag would be an algebraic loop).
 *
 * Power pins (d_power's, EP2/retail board): P_EN GP6_5 and 5VPENON GP6_11
 * (outputs, high = supply on), SW_RECHARGE GP8_8 (the model drives it low
 * with a rechargeable pack, pulls it up with AA cells), test pin GP6_2.
 */
#ifndef HOST_SIM_DEVICES_EV3_POWER_H
#define HOST_SIM_DEVICES_EV3_POWER_H

#include <stdbool.h>
#include <stdint.h>
#include "kernel.h"
#include "host_sim/board.h"
#include "host_sim/gpio.h"

#define EV3_POWER_P_EN_PIN        HS_GPIO(6, 5)
#define EV3_POWER_5V_PIN          HS_GPIO(6, 11)
#define EV3_POWER_RECHARGE_PIN    HS_GPIO(8, 8)
#define EV3_POWER_TEST_PIN        HS_GPIO(6, 2)

#define EV3_POWER_BRICK_MA        100U   /* the brick's own draw */
#define EV3_POWER_DEFAULT_MOHM    500U   /* six AA alkaline cells, about 80 mΩ each */
#define EV3_POWER_MAX_MOHM        10000U

/* The board device (listed in ev3_board_devices). */
extern const struct hs_device ev3_power_device;

/* Internal resistance in mΩ (0..EV3_POWER_MAX_MOHM): E_OK, E_PAR, E_OBJ without a board. */
ER ev3_power_set_resistance_mohm(uint32_t mohm);
/* A rechargeable pack (SW_RECHARGE low) or AA cells: E_OK, E_OBJ without a board. */
ER ev3_power_set_rechargeable(bool rechargeable);

/* Total current drawn from the battery now (brick + motors), amperes. */
double ev3_power_battery_current_a(void);
/* Terminal voltage now, mV: EMF − R × I. */
uint32_t ev3_power_terminal_mv(void);

/* State of the power pins as the SoC drives them. */
struct ev3_power_pins {
	bool main_on;               /* P_EN driven high */
	bool rail_5v_on;            /* 5VPENON driven high */
	bool test_high;             /* test pin driven high */
	uint32_t test_changes;      /* test-pin level changes since boot */
};
void ev3_power_pins_state(struct ev3_power_pins *out);

/* The battery's ADC channels (2, 3, 4, 15) in mV, given the motors' current; 0 for others. */
uint32_t ev3_power_adc_mv(unsigned ch, double motor_a);

#endif /* HOST_SIM_DEVICES_EV3_POWER_H */

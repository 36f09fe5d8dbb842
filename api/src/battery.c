/*
 * battery.c — ev3_battery_current_mA / ev3_battery_voltage_mV over
 * d_analog's shared ANALOG area (ev3api_battery.h).
 */
#include <stddef.h>
#include "ev3api_battery.h"
#include "api_internal.h"
#include "analog_hack.h"
#include "t_syslog.h"

/* The FINAL board's battery front end (LEGO's c_ui; EV3RT uses it on every board). */
#define SHUNT_MOHM      110     /* battery current shunt, mΩ */
#define SHUNT_GAIN      22      /* its amplifier */
#define CELL_SCALE      2       /* the cell channel sees half the pack voltage */
#define DIODE_MV        50      /* the drop the cell channel does not see */

static const struct lms_analog *analog_shm;

void api_battery_boot(void)
{
	analog_shm = NULL;
}

/* d_analog's ANALOG area, mapped on first use; NULL (warning logged) if it cannot be. */
static const struct lms_analog *battery_channels(const char *caller)
{
	const struct lms_analog *map = NULL;
	ER ercd;

	if (analog_shm)
		return analog_shm;
	ercd = sns_ctx() ? E_CTX : analog_map(&map);
	if (ercd != E_OK) {
		syslog(LOG_WARNING, "%s: no battery channels (d_analog: %d)", caller, (int)ercd);
		return NULL;
	}
	analog_shm = map;
	return map;
}

/* A channel's raw count as millivolts at the converter. */
static int channel_mv(const volatile uint16_t *count)
{
	return (int)lms_analog_raw_to_mv(*count);
}

int ev3_battery_current_mA(void)
{
	const struct lms_analog *a = battery_channels(__func__);

	if (!a)
		return 0;
	/* I = V / gain / shunt */
	return channel_mv(&a->battery_current) * 1000 / (SHUNT_GAIN * SHUNT_MOHM);
}

int ev3_battery_voltage_mV(void)
{
	const struct lms_analog *a = battery_channels(__func__);

	if (!a || !*(const volatile uint16_t *)&a->cell123456)
		return 0;	/* no sample yet: d_analog reads the battery every 8 ms from its start */
	/* V = V(cell) / 0.5 + V(current) / gain + diode: the shunt's drop added back */
	return channel_mv(&a->cell123456) * CELL_SCALE + channel_mv(&a->battery_current) / SHUNT_GAIN +
	       DIODE_MV;
}

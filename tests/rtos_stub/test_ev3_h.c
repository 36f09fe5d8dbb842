/*
 * test_ev3_h.c — the names EV3RT's platform header gives apps through
 * kernel.h, with EV3RT's values (public sources: ev3rt-git/ev3rt-hrp2 and
 * ev3rt-git/ev3rt-hrp3, target/ev3_gcc/ev3.h), and STACK_SIZE overridden by
 * the app as on EV3RT (this file defines it before kernel.h, as an app's
 * app.h does before it includes ev3api.h).
 */
#define STACK_SIZE 8192
#include <stdbool.h>
#include "tap.h"
#include "kernel.h"

struct constant {
	const char *name;
	long long ours, ev3rt;
};

#define EV3RT(name, value) { #name, (long long)(name), (long long)(value) }

static const struct constant constants[] = {
	EV3RT(STACK_SIZE, 8192), EV3RT(CORE_CLK_MHZ, 300), EV3RT(OSCIN_MHZ, 24), EV3RT(ARM_PAGE_TABLE_RATIO, 20),
	EV3RT(PERIOD_UART_SENSOR_CYC, 10000U), EV3RT(INTNO_UART_PORT1, 53), EV3RT(INTNO_UART_PORT2, 25),
	EV3RT(INTNO_UART_PORT3, 4), EV3RT(INTNO_UART_PORT4, 3), EV3RT(INTNO_I2C_TIMER, 23),
	EV3RT(SUART1_INT, 3), EV3RT(SUART2_INT, 4),
	EV3RT(INTPRI_GPIO, TMIN_INTPRI), EV3RT(INTPRI_I2C_TIMER, TMIN_INTPRI), EV3RT(INTPRI_UART_PORT1, TMIN_INTPRI),
	EV3RT(INTPRI_UART_PORT2, TMIN_INTPRI), EV3RT(INTPRI_UART_PORT3, TMIN_INTPRI),
	EV3RT(INTPRI_UART_PORT4, TMIN_INTPRI), EV3RT(INTPRI_EDMA3, TMIN_INTPRI + 1),
	EV3RT(INTPRI_USBMSC, TMIN_INTPRI + 2), EV3RT(INTPRI_TIMER, TMIN_INTPRI + 3),
	EV3RT(INTPRI_BLUETOOTH, TMIN_INTPRI + 4), EV3RT(INTPRI_LCD_SPI, TMIN_INTPRI + 4),
	EV3RT(KERNEL_HEAP_SIZE, 1024 * 1024), EV3RT(APP_HEAP_SIZE, 1024 * 1024), EV3RT(BT_SND_BUF_SIZE, 2048),
	EV3RT(BT_HIGH_PRI_TIME_SLICE, 1), EV3RT(BT_LOW_PRI_TIME_SLICE, 19), EV3RT(BT_USE_EDMA_MODE, 1),
	EV3RT(TMAX_APP_TSK_NUM, 32), EV3RT(TMAX_APP_SEM_NUM, 16), EV3RT(TMAX_APP_FLG_NUM, 16),
	EV3RT(TMAX_APP_DTQ_NUM, 16), EV3RT(TMAX_APP_PDQ_NUM, 16), EV3RT(TMAX_APP_MTX_NUM, 16),
	EV3RT(TMAX_APP_CYC_NUM, 16), EV3RT(TMAX_APP_TEXT_SIZE, 1024 * 1024), EV3RT(TMAX_APP_DATA_SIZE, 1024 * 1024),
	EV3RT(TMAX_APP_BINARY_SIZE, 1024 * 1024), EV3RT(LCD_FRAME_RATE, 25), EV3RT(FORCE_SHUTDOWN_TIMEOUT, 500),
	EV3RT(TMAX_EV3_CYC_NUM, 16), EV3RT(TCNT_SYSLOG_BUFFER, 1024), EV3RT(TPRI_INIT_TASK, TMIN_TPRI),
	EV3RT(TPRI_PLATFORM_TERM, TMIN_TPRI), EV3RT(TPRI_BLUETOOTH_LOW, TMAX_TPRI),
};

/* The platform's task priorities, each above the app's (ev3lx's platform in EV3RT's order). */
static const struct { const char *name; int pri; } platform_pris[] = {
	{ "TPRI_USBMSC", TPRI_USBMSC }, { "TPRI_BLUETOOTH_QOS", TPRI_BLUETOOTH_QOS },
	{ "TPRI_BLUETOOTH_HIGH", TPRI_BLUETOOTH_HIGH }, { "TPRI_APP_TERM_TASK", TPRI_APP_TERM_TASK },
	{ "TPRI_EV3_LCD_TASK", TPRI_EV3_LCD_TASK }, { "TPRI_EV3_MONITOR", TPRI_EV3_MONITOR },
	{ "TPRI_PLATFORM_BUSY", TPRI_PLATFORM_BUSY }, { "TPRI_APP_INIT_TASK", TPRI_APP_INIT_TASK },
};

int main(void)
{
	size_t n = sizeof(constants) / sizeof(constants[0]), m = sizeof(platform_pris) / sizeof(platform_pris[0]);

	tap_plan((int)(n + m) + 4);
	for (size_t i = 0; i < n; i++)
		ok(constants[i].ours == constants[i].ev3rt, "%s is %lld, as on EV3RT (ours: %lld)", constants[i].name,
		   constants[i].ev3rt, constants[i].ours);
	for (size_t i = 0; i < m; i++)
		ok(platform_pris[i].pri >= TMIN_TPRI && platform_pris[i].pri < TMIN_APP_TPRI,
		   "%s (%d) is a platform priority, above TMIN_APP_TPRI", platform_pris[i].name, platform_pris[i].pri);
	is_int(TPRI_EV3_CYC, TMIN_APP_TPRI, "TPRI_EV3_CYC: EV3_CRE_CYC's handler tasks run at TMIN_APP_TPRI");
	is_int(SIO_PORT_DEFAULT, 1, "SIO_PORT_DEFAULT is SIO_PORT_UART, the port EV3_SERIAL_DEFAULT uses");
	ok(sizeof(SYSTIM) == sizeof(ulong_t) && (TMO)-1 < 0, "the HRP2 profile keeps HRP2's SYSTIM and signed TMO");
	ok(sizeof(float32_t) == 4 && sizeof(double64_t) == 8 && FLOAT32_MAX > 3e38F && DOUBLE64_MIN < 3e-308,
	   "t_stddef.h gives TOPPERS's float32_t and double64_t with their limits");
	return tap_done();
}

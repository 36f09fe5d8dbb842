/*
 * test_uart_hack.c — argument checks of d_uart's extended service calls
 * (uart_hack.h): ports, modes, lengths, pointers and context are refused
 * with the documented TOPPERS codes before anything reaches the driver, and
 * driver refusals come back as TOPPERS codes too.
 */
#include "uart_test.h"

static ER irq_ercd = E_OK;

/* Runs in the hardware's (non-task) context. */
static void from_irq(void *arg)
{
	(void)arg;
	irq_ercd = uart_svc_set_mode(0, 0);
}

static void body(void)
{
	struct lms_uart_types t = { 0 };
	const struct lms_uart_shm *map = NULL;
	uint8_t data[40] = { 1, 2, 3 };
	unsigned fn;

	for (fn = UART_FN_SET_MODE; fn <= UART_FN_WRITE; fn++) {
		is_int(cal_svc(fn, -1, 0, (intptr_t)&t, 0, 0), E_ID, "fn %u: port -1 is E_ID", fn);
		is_int(cal_svc(fn, 4, 0, (intptr_t)&t, 0, 0), E_ID, "fn %u: port 4 is E_ID", fn);
	}
	is_int(uart_svc_set_mode(0, 8), E_PAR, "set_mode: mode 8 is E_PAR");
	is_int(cal_svc(UART_FN_SET_MODE, 0, -1, 0, 0, 0), E_PAR, "set_mode: mode -1 is E_PAR");
	is_int(uart_svc_mode_info(0, 8, &t), E_PAR, "mode_info: mode 8 is E_PAR");
	is_int(uart_svc_mode_info(0, 0, NULL), E_MACV, "mode_info: NULL is E_MACV");
	is_int(uart_svc_mode_info(0, 0, &t), E_OBJ, "mode_info: idle port is E_OBJ");
	is_int(uart_svc_write(0, data, 0), E_PAR, "write: 0 bytes is E_PAR");
	is_int(uart_svc_write(0, data, 33), E_PAR, "write: 33 bytes is E_PAR");
	is_int(uart_svc_write(0, NULL, 3), E_MACV, "write: NULL is E_MACV");
	is_int(uart_svc_write(0, (const void *)(intptr_t)-2, 3), E_MACV, "write: wrapping range is E_MACV");
	is_int(uart_svc_write(0, data, 3), E_OBJ, "write: idle port is E_OBJ");
	is_int(uart_svc_map(NULL), E_MACV, "map: NULL is E_MACV");
	is_int(uart_svc_map(&map), E_OK, "map");
	ok(map && map->ext.magic == LMS_UART_EXT_MAGIC, "gives the shared memory");
	is_int(cal_svc(UART_FN_MAP + 1, 0, 0, 0, 0, 0), E_RSFN, "unused function code is E_RSFN");

	is_int(uart_svc_set_mode(0, 3), E_OK, "set_mode port 1 (no sensor)");
	is_int(map->ext.port[0].state, LMS_UART_STATE_SYNC, "searching");
	is_int(map->ext.port[0].mode, 3, "mode 3 wanted");
	is_int(uart_svc_set_mode(1, 0), E_OK, "set_mode port 2 too");
	is_int(map->ext.port[0].mode, 3, "port 1 keeps its mode");
	is_int(uart_svc_mode_info(0, 0, &t), E_OBJ, "mode_info before a sensor described itself: E_OBJ");
	is_int(uart_svc_write(0, data, 3), E_OK, "write: queued until DATA");
	is_int(uart_svc_write(0, data, 3), E_QOVR, "write: the previous one still pending is E_QOVR");
	is_int(uart_svc_clear_changed(0), E_OK, "clear_changed");
	is_int(uart_svc_stop(0), E_OK, "stop port 1");
	ok(map->ext.port[0].state == LMS_UART_STATE_IDLE && map->ext.port[1].state != LMS_UART_STATE_IDLE,
	   "port 1 idle, port 2 still running");
	is_int(uart_svc_stop(0), E_OK, "stopping an idle port is harmless");

	hs_sim_at(rtos_host_now() + UT_MS, from_irq, NULL);
	dly_tsk(2);
	is_int(irq_ercd, E_CTX, "non-task context is E_CTX");
	is_int(map->ext.port[0].state, LMS_UART_STATE_IDLE, "and changes nothing");
}

int main(void)
{
	tap_plan(10 + 28 + 1);
	ok(ut_run(body, 8, NULL), "scenario ran to its end");
	return tap_done();
}

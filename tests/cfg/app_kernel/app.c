/*
 * app.c — the configurator test app's code: every object of app.cfg is used
 * once, the way an EV3RT app would.
 */
#include "kernel_cfg.h"
#include "app.h"

struct app_result app_result;
static SYSTIM app_static_time;

void app_init(intptr_t exinf)
{
	(void)exinf;
	app_result.inits++;
}

void main_task(intptr_t exinf)
{
	(void)exinf;
	app_result.main_runs++;
	app_result.get_tim_static = get_tim(&app_static_time);
	app_result.get_tim_foreign = get_tim(app_foreign_static);
	sta_alm(ALM1, 15);
	act_tsk(WORKER_TASK);
	for (intptr_t i = 1; i <= 3; i++)
		snd_dtq(DTQ1, i * 10);
}

void worker_task(intptr_t exinf)
{
	intptr_t data;

	(void)exinf;
	while (app_result.nreceived < 3 && rcv_dtq(DTQ1, &data) == E_OK)
		app_result.received[app_result.nreceived++] = data;
}

void cyclic_handler(intptr_t exinf)
{
	(void)exinf;
	app_result.cyclic_runs++;
	app_result.cyclic_in_task = !sns_ctx();
}

void alarm_handler(intptr_t exinf)
{
	(void)exinf;
	app_result.alarm_runs++;
}

void ev3_cyclic(intptr_t exinf)
{
	(void)exinf;
	app_result.ev3_cyclic_runs++;
	app_result.ev3_cyclic_ctx = sns_ctx();
	app_result.ev3_cyclic_dly = dly_tsk(1);
}

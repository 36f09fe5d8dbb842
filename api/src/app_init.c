/*
 * app_init.c — an app's C++ global constructors, run as EV3RT runs them: in
 * a task of the app's domain once the platform is up, before the app's
 * tasks (ev3rt-git/ev3rt-hrp2-sdk, common/ev3api/src/ev3api.c:
 * _app_init_task calls the app's __init_array after initialising the API),
 * so a global object may configure a port or read a sensor.  The app's
 * build moves the .init_array of the app's objects and SDK libraries to
 * the section ev3rt_app_init_array (mk/ev3rt_app.mk), whose bounds the
 * linker gives; the program's own start-up never runs them.
 */
#include <stdbool.h>
#include <stddef.h>
#include "ev3api_routines.h"
#include "rtos_cfg.h"
#include "ev3api_brick.h"
#include "api_internal.h"

typedef void (*app_ctor)(void);

/* The app's constructors (none: both NULL). */
extern const app_ctor __start_ev3rt_app_init_array[] __attribute__((weak));
extern const app_ctor __stop_ev3rt_app_init_array[] __attribute__((weak));

/* Suspends every task of the app's priorities (TMIN_APP_TPRI and lower)
 * that is not dormant, marking each in held[]. */
static void hold_app_tasks(bool held[TNUM_TSKID + 1])
{
	for (ID id = 1; id <= TNUM_TSKID; id++) {
		PRI pri;

		held[id] = id != EV3_APP_INIT_TSKID && get_pri(id, &pri) == E_OK && pri >= TMIN_APP_TPRI &&
			   sus_tsk(id) == E_OK;
	}
}

/* Resumes the tasks hold_app_tasks suspended. */
static void release_app_tasks(const bool held[TNUM_TSKID + 1])
{
	for (ID id = 1; id <= TNUM_TSKID; id++)
		if (held[id])
			(void)rsm_tsk(id);
}

/* In order, as the C library's start-up would have; at every boot, as
 * EV3RT loads its app afresh each time.  The app's tasks are held
 * meanwhile: EV3RT's calls busy-wait for a sensor's data (its
 * ev3api_sensor.c, uart_sensor_fetch_data), so its init task keeps them off
 * the CPU while a constructor waits, where ev3lx's calls sleep; a global
 * pointer set by `new GyroSensor(...)` is thus never seen unset. */
void api_app_init_task(intptr_t exinf)
{
	const app_ctor *first = __start_ev3rt_app_init_array, *end = __stop_ev3rt_app_init_array;
	bool held[TNUM_TSKID + 1];

	(void)exinf;
	if (first == NULL || end == NULL || first == end)
		return;
	hold_app_tasks(held);
	for (const app_ctor *ctor = first; ctor < end; ctor++)
		(*ctor)();
	release_app_tasks(held);
}

/* Registers nothing: EV3RT never runs a global object's destructor (the
 * app does not exit; ev3api.c: "C++ destructors are not supported"), and
 * here the program's exit would run it after the simulation, calling the
 * API of a brick that is gone. */
int ev3rt_app_cxa_atexit(void (*destructor)(void *), void *object, void *dso_handle)
{
	(void)destructor;
	(void)object;
	(void)dso_handle;
	return 0;
}

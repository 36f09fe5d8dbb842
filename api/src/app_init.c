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
#include <stddef.h>
#include "ev3api_brick.h"
#include "api_internal.h"

typedef void (*app_ctor)(void);

/* The app's constructors (none: both NULL). */
extern const app_ctor __start_ev3rt_app_init_array[] __attribute__((weak));
extern const app_ctor __stop_ev3rt_app_init_array[] __attribute__((weak));

/* In order, as the C library's start-up would have; at every boot, as
 * EV3RT loads its app afresh each time. */
void api_app_init_task(intptr_t exinf)
{
	(void)exinf;
	if (__start_ev3rt_app_init_array == NULL || __stop_ev3rt_app_init_array == NULL)
		return;
	for (const app_ctor *ctor = __start_ev3rt_app_init_array; ctor < __stop_ev3rt_app_init_array; ctor++)
		(*ctor)();
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

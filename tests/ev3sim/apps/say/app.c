/*
 * app.c — say: logs what app.h says, once.
 */
#include "ev3api.h"
#include "app.h"

void main_task(intptr_t exinf)
{
	syslog(LOG_NOTICE, "say: %s", SAY_WHAT);
}

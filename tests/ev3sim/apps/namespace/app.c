/*
 * app.c — namespace: global functions and variables named as ev3lx's own
 * (the host kernel's tick handler and clock, linux_compat's jiffies and
 * kmalloc, the API's button task) and a main(), all the app's.
 */
#include "app.h"

int now_ns = 7;
unsigned long jiffies = 11;
int cpu;

void tick_handler(void)
{
	cpu++;
}

void *kmalloc(unsigned long size, int flags)
{
	return (void *)(size + (unsigned long)flags);
}

void api_button_task(intptr_t exinf)
{
	cpu += (int)exinf;
}

int main(void)
{
	tick_handler();
	api_button_task(2);
	return now_ns + (int)jiffies + cpu + (kmalloc(1, 1) == (void *)2);
}

void main_task(intptr_t exinf)
{
	syslog(LOG_NOTICE, "namespace: main() says %d", main());
	tslp_tsk(500);
	syslog(LOG_NOTICE, "namespace: ran 0.5 s with the platform's own tick handler");
}

/*
 * app.c — spp_loopback: the master connects (one attempt at a time, as
 * EV3RT's test-spp-master does), then sends REQUESTS "SENSOR" lines and one
 * "MOTOR" line while another task reads the answers from the same stream.
 * The slave answers each request with its running count and sets motor A's
 * power.  The master checks that every answer came back, in order.
 */
#include <string.h>
#include "ev3api.h"
#include "app.h"
#include "spp_link.h"

static const uint8_t slave_addr[6] = { 0x00, 0x16, 0x53, 0x00, 0x00, 0x01 };

static FILE *master;
static int answers, out_of_order;

/* The slave: one answer per request line, in the order they came. */
void slave_task(intptr_t unused)
{
	FILE *bt = ev3_serial_open_file(EV3_SERIAL_BT);
	int served = 0, power;
	char line[32];

	ev3_motor_config(EV3_PORT_A, LARGE_MOTOR);
	while (bt != NULL) {
		if (fgets(line, sizeof(line), bt) == NULL) {
			dly_tsk(10);
			continue;
		}
		if (strcmp(line, "SENSOR\n") == 0)
			fprintf(bt, "SENSOR %d\n", ++served);
		else if (sscanf(line, "MOTOR %d", &power) == 1)
			ev3_motor_set_power(EV3_PORT_A, power);
		else
			syslog(LOG_ERROR, "spp_loopback: the slave got '%s'", line);
	}
}

/* The master's reader: waits in fgets while the main task writes the same stream. */
void answer_task(intptr_t unused)
{
	char line[32];
	int value;

	for (;;) {
		if (fgets(line, sizeof(line), master) == NULL) {
			dly_tsk(10);
			continue;
		}
		if (sscanf(line, "SENSOR %d", &value) != 1)
			syslog(LOG_ERROR, "spp_loopback: the master got '%s'", line);
		else if (value != ++answers)
			out_of_order++;
	}
}

void main_task(intptr_t unused)
{
	SYSTIM start, connected;
	int attempts = 0;

	get_tim(&start);
	while (!spp_link_is_connected()) {
		spp_link_connect(slave_addr, "1234");
		attempts++;
	}
	get_tim(&connected);
	syslog(LOG_NOTICE, "spp_loopback: connected after %d attempt(s), %lu ms", attempts,
	       (unsigned long)(connected - start));

	master = spp_link_open_file();
	act_tsk(ANSWER_TASK);
	for (int i = 0; i < REQUESTS; i++) {
		fprintf(master, "SENSOR\n");
		dly_tsk(REQUEST_MS);
	}
	fprintf(master, "MOTOR %d\n", MOTOR_POWER);
	dly_tsk(500);
	syslog(LOG_NOTICE, "spp_loopback: %d requests, %d answers, %d out of order", REQUESTS, answers,
	       out_of_order);
	syslog(LOG_NOTICE, "spp_loopback: motor A at power %d, turned %s", ev3_motor_get_power(EV3_PORT_A),
	       ev3_motor_get_counts(EV3_PORT_A) > 90 ? "over 90 degrees" : "90 degrees or less");
}

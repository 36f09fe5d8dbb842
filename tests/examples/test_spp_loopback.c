/*
 * test_spp_loopback.c — examples/spp_loopback: Bluetooth SPP as EV3RT's
 * SDK libraries use it (platform_interface_layer.h's
 * spp_master_test_connect, serial_ref_por on SIO_PORT_SPP_MASTER_TEST, the
 * stream from fdopen on SIO_PORT_SPP_MASTER_TEST_FILENO), the brick's
 * master connected to its own slave (--bt and --bt-master on one socket):
 * the connection takes its paging time, every request is answered in
 * order while one task reads and another writes the same stream, and the
 * slave drives the motor the master asked for.
 */
#define _GNU_SOURCE     /* mkdtemp */
#include <stdlib.h>
#include <unistd.h>
#include "example_test.h"

int main(void)
{
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;
	char dir[] = "/tmp/ev3lx-spp-XXXXXX", sock[64];
	const char *line;
	int attempts = 0;
	unsigned long ms = 0;

	if (mkdtemp(dir) == NULL)
		tap_bail_out("mkdtemp: cannot make a scratch directory");
	snprintf(sock, sizeof(sock), "%s/spp.sock", dir);
	ev3sim_run_defaults(&o, EV3SIM_ROBOT_BARE);
	o.app_name = "spp_loopback";
	o.seconds = 3;
	o.out[0] = EV3SIM_OUT_LARGE;
	o.bt_path = sock;
	o.bt_master_path = sock;
	if (!ok(ex_run(&o, &r), "spp_loopback runs"))
		return tap_done();
	line = ex_logged("spp_loopback: connected after ");
	if (line != NULL && sscanf(line, "spp_loopback: connected after %d attempt(s), %lu ms", &attempts, &ms) != 2)
		attempts = 0;
	ok(attempts == 1 && ms >= 640 && ms < 660,
	   "the master connects at its first attempt, once the slave answered the page (640 ms; %lu)", ms);
	ok(ex_logged("spp_loopback: 50 requests, 50 answers, 0 out of order") != NULL,
	   "every request is answered, in order, while one task reads and another writes the stream");
	ok(ex_logged("spp_loopback: motor A at power 40, turned over 90 degrees") != NULL,
	   "the slave drives motor A at the power the master sent");
	is_int(r.warnings + r.errors + r.bugs, 0, "no warnings, errors or bugs");
	unlink(sock);
	rmdir(dir);
	return tap_done();
}

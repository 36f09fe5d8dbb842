/*
 * spp_link.c — the SPP master over EV3RT's platform interface layer: the
 * connection through spp_master_test_connect, the link's state through
 * TOPPERS's serial interface, its stream through the port's file number.
 */
#include "ev3api.h"
#include "platform_interface_layer.h"
#include "syssvc/serial.h"
#include "spp_link.h"

void spp_link_connect(const uint8_t addr[6], const char *pin)
{
	ER ercd = spp_master_test_connect(addr, pin);

	if (ercd != E_OK)
		syslog(LOG_WARNING, "spp_link: connect: %d", ercd);
}

bool_t spp_link_is_connected(void)
{
	T_SERIAL_RPOR rpor;

	return serial_ref_por(SIO_PORT_SPP_MASTER_TEST, &rpor) == E_OK;
}

FILE *spp_link_open_file(void)
{
	FILE *fp = fdopen(SIO_PORT_SPP_MASTER_TEST_FILENO, "a+");

	/* unbuffered: each fprintf is on the air when it returns */
	if (fp != NULL)
		setbuf(fp, NULL);
	return fp;
}

/*
 * t_stdlib.c — TOPPERS's library functions on the host: error names and
 * the log line of a failed service call (t_perror, EV3RT's svc_perror).  On the AM1808 the kernel's library and EV3RT's
 * platform define them.
 */
#include "kernel_impl.h"
#include "t_stdlib.h"

struct error_name {
	ER mercd;
	const char *name;
};

static const struct error_name error_names[] = {
	{ E_OK, "E_OK" },         { E_SYS, "E_SYS" },       { E_NOSPT, "E_NOSPT" },
	{ E_RSFN, "E_RSFN" },     { E_RSATR, "E_RSATR" },   { E_PAR, "E_PAR" },
	{ E_ID, "E_ID" },         { E_CTX, "E_CTX" },       { E_MACV, "E_MACV" },
	{ E_OACV, "E_OACV" },     { E_ILUSE, "E_ILUSE" },   { E_NOMEM, "E_NOMEM" },
	{ E_NOID, "E_NOID" },     { E_NORES, "E_NORES" },   { E_OBJ, "E_OBJ" },
	{ E_NOEXS, "E_NOEXS" },   { E_QOVR, "E_QOVR" },     { E_RLWAI, "E_RLWAI" },
	{ E_TMOUT, "E_TMOUT" },   { E_DLT, "E_DLT" },       { E_CLS, "E_CLS" },
	{ E_WBLK, "E_WBLK" },     { E_BOVR, "E_BOVR" },
	{ -53, "E_RASTER" },      { -65, "E_COMM" },      /* HRP3's (t_stddef.h, EV3LX_KERNEL_HRP3) */
};

/* The name of ercd's main error code, or "unknown error". */
const char *itron_strerror(ER ercd)
{
	ER mercd = MERCD(ercd);

	for (size_t i = 0; i < sizeof(error_names) / sizeof(error_names[0]); i++)
		if (error_names[i].mercd == mercd)
			return error_names[i].name;
	return "unknown error";
}

/* Logs at prio that expr, at file:line, returned ercd. */
void t_perror(uint_t prio, const char *file, int_t line, const char *expr, ER ercd)
{
	/* the sub code: what lies above the main code's byte (SERCD, without shifting a negative) */
	int sub = (int)((ercd - (ercd & 0xff)) / 256);

	syslog(prio, "%s (%d) reported by `%s' in line %d of `%s'.", itron_strerror(ercd), sub, expr, (int)line, file);
}

/* EV3RT's default serial port (ev3.h): ev3lx's is the UART of sensor port 1,
 * SIO_PORT_UART (target_serial.h). */
int SIO_PORT_DEFAULT = 1;

/* Logs a failed service call (ercd < 0) at LOG_ERROR, as EV3RT's platform does. */
void svc_perror(const char *file, int_t line, const char *expr, ER ercd)
{
	if (ercd < 0)
		t_perror(LOG_ERROR, file, line, expr, ercd);
}

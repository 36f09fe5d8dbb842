/*
 * serial_log.c — the serial log channel's port model and its polled
 * write service call (serial_log.h).
 *
 * The transmitter holds at most two bytes: one in the shift register (on the
 * wire) and one in the holding register.  line_free_at is when the last byte
 * accepted leaves the wire; the holding register is empty once no more than
 * one byte time of it remains.
 */
#include "rtos_host.h"
#include "ev3sim/serial_log.h"

static struct {
	uint32_t baud;
	uint64_t byte_ns;
	uint64_t line_free_at;
	FILE *out;
	struct serial_log_stats stats;
} port = { SERIAL_LOG_DEFAULT_BAUD, 10ULL * 1000000000ULL / SERIAL_LOG_DEFAULT_BAUD, 0, NULL, { 0, 0, 0 } };

ER serial_log_setup(uint32_t baud, FILE *out)
{
	if (baud == 0)
		return E_PAR;
	port.baud = baud;
	/* start + 8 data + stop bits, rounded up: a byte never leaves early */
	port.byte_ns = (10ULL * 1000000000ULL + baud - 1) / baud;
	port.line_free_at = 0;
	port.out = out;
	port.stats = (struct serial_log_stats){ 0, 0, 0 };
	return E_OK;
}

const struct serial_log_stats *serial_log_get_stats(void)
{
	return &port.stats;
}

/* Spins until the holding register is empty (polling the line status): a
 * spin preempted meanwhile finds the register empty when it resumes. */
static void wait_holding_register(void)
{
	uint64_t now = rtos_host_now();

	if (port.line_free_at > now + port.byte_ns)
		port.stats.spin_ns += rtos_host_spin_until(port.line_free_at - port.byte_ns);
}

/* The polled write of buf[0..len) by the calling task (checked by the caller). */
ER_UINT serial_log_send(const char *buf, uint_t len)
{
	for (uint_t i = 0; i < len; i++) {
		uint64_t now;

		wait_holding_register();
		now = rtos_host_now();
		port.line_free_at = (port.line_free_at > now ? port.line_free_at : now) + port.byte_ns;
		rtos_host_consume(SERIAL_LOG_ACCESS_NS);
		if (port.out)
			fputc(buf[i], port.out);
		port.stats.bytes++;
	}
	port.stats.writes++;
	return (ER_UINT)len;
}

/* Extended service call: the polled write of buf[0..len). */
static ER_UINT svc_write(intptr_t p_buf, intptr_t p_len, intptr_t p3, intptr_t p4, intptr_t p5,
			 ID cdmid)
{
	const char *buf = (const char *)p_buf;
	uint_t len = (uint_t)p_len;

	(void)p3; (void)p4; (void)p5; (void)cdmid;
	if (sns_ctx())
		return E_CTX;
	if (p_len <= 0 || len > SERIAL_LOG_MAX_WRITE)
		return E_PAR;
	if (buf == NULL || prb_mem(buf, len, TSK_SELF, TPM_READ) != E_OK)
		return E_MACV;
	return serial_log_send(buf, len);
}

static const struct rtos_svc_cfg serial_log_svcs[] = {
	{ SERIAL_LOG_FN_WRITE, svc_write, 1024 },
};

const struct rtos_cfg serial_log_cfg = {
	.name = "serial_log",
	.svcs = RTOS_TABLE(serial_log_svcs),
	.svc_first = SERIAL_LOG_FN_WRITE, .svc_count = 1,
};

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

/* Records bytes buf[from..to) as sent (the far end's copy, the counts) with
 * spin_ns of spinning and the line busy until free_at: what the kernel may
 * let others see (a task preempting the writer, the end of the run). */
static void record_sent(const char *buf, uint_t from, uint_t to, uint64_t free_at, uint64_t spin_ns)
{
	port.line_free_at = free_at;
	port.stats.spin_ns += spin_ns;
	port.stats.bytes += to - from;
	if (port.out && to > from)
		fwrite(buf + from, 1, to - from, port.out);
}

/*
 * The polled write of buf[0..len) by the calling task (checked by the caller).
 * Per byte the driver spins until the holding register is empty, then makes
 * one register access.  A spin or access that ends before
 * rtos_host_quiet_until() cannot be preempted and only moves the clock, so
 * it is timed here, running ahead of the kernel's clock; the kernel catches
 * up in one call: the next spin that reaches the quiet bound (spinning from
 * the kernel's clock, it spins through the time ahead first: that time is
 * counted already), or one spin to where the bytes left the clock.  An
 * access that reaches the bound is the kernel's rtos_host_consume, as each
 * was before: the times, counts and spin statistics are those of one
 * rtos_host_spin_until and one rtos_host_consume per byte.
 */
ER_UINT serial_log_send(const char *buf, uint_t len)
{
	const uint64_t byte_ns = port.byte_ns;
	uint64_t kernel_clock = rtos_host_now();
	uint64_t clock = kernel_clock;          /* where the bytes so far left the CPU */
	uint64_t quiet = rtos_host_quiet_until();
	uint64_t free_at = port.line_free_at;
	uint64_t spin_ns = 0;                   /* spun by bytes [recorded..i) */
	uint_t recorded = 0;

	for (uint_t i = 0; i < len; i++) {
		/* the holding register is empty once no more than one byte time is left on the line */
		if (free_at > clock + byte_ns) {
			uint64_t empty_at = free_at - byte_ns;

			if (empty_at < quiet) {
				spin_ns += empty_at - clock;
				clock = empty_at;
			} else {
				uint64_t spun;

				record_sent(buf, recorded, i, free_at, spin_ns);
				recorded = i;
				spin_ns = 0;
				spun = rtos_host_spin_until(empty_at);
				port.stats.spin_ns += spun - (clock - kernel_clock);
				clock = kernel_clock = rtos_host_now();
				quiet = rtos_host_quiet_until();
				free_at = port.line_free_at;
			}
		}
		free_at = (free_at > clock ? free_at : clock) + byte_ns;
		if (clock + SERIAL_LOG_ACCESS_NS < quiet) {
			clock += SERIAL_LOG_ACCESS_NS;
		} else {
			record_sent(buf, recorded, i, free_at, spin_ns);
			recorded = i;
			spin_ns = 0;
			if (clock > kernel_clock)
				rtos_host_spin_until(clock);
			rtos_host_consume(SERIAL_LOG_ACCESS_NS);
			clock = kernel_clock = rtos_host_now();
			quiet = rtos_host_quiet_until();
			free_at = port.line_free_at;
		}
	}
	record_sent(buf, recorded, len, free_at, spin_ns);
	if (clock > kernel_clock)
		rtos_host_spin_until(clock);
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

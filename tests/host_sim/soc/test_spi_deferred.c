/*
 * test_spi_deferred.c — SPI0's deferred frame ends are unobservable: the
 * same sequence of polled frames (d_analog's pattern, reads in the middle of
 * a frame, flags cleared before SPIBUF is read, an interrupt enabled before
 * and during a frame, a word waiting in the TX buffer, an overrun, a reset,
 * the idle check, reads by events at the frame's end time, the format,
 * delay and format selection changed between frames, SPIBUF stalls that
 * an event interrupts, that a device event makes across the run's end and
 * that a model-side read makes outside any access) gives the same
 * register values at the same virtual times, the same interrupt line (VCD)
 * and the same statistics with deferral on as with every frame end an event;
 * and with SPI0's register log on (its 32-bit accesses then take the hooks
 * instead of SPIBUF's and SPIDAT0's direct accesses) as with it off.
 */
#define _XOPEN_SOURCE 700
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "devtest.h"
#include "host_sim/intc.h"
#include "host_sim/regs.h"
#include "host_sim/trace.h"
#include "host_sim/devices/spi.h"
#include "devtest_compare.h"
#include "text_files_test.h"

#define SPI       HS_SPI0_BASE
#define SPIGCR0   (SPI + 0x00)
#define SPIGCR1   (SPI + 0x04)
#define SPIINT0   (SPI + 0x08)
#define SPIFLG    (SPI + 0x10)
#define SPIDAT0   (SPI + 0x38)
#define SPIBUF    (SPI + 0x40)
#define SPIEMU    (SPI + 0x44)
#define RXINTENA  (1U << 8)
#define RXINTFLG  (1U << 8)
#define TXFULL    (1U << 29)
#define RXEMPTY   (1U << 31)
#define US        1000ULL

struct run {
	struct devtest_notes notes;
	struct ev3_spi_stats stats;
	char vcd[65536];
	uint32_t deferred;
	unsigned log_lines;         /* of the register log, if on */
};

static struct run *cur;

/* Records an observation in the current run. */
static void note(const char *what, uint32_t value)
{
	devtest_note(&cur->notes, what, value, hs_intc_pending(EV3_SPI0_INTNO) ? 1U : 0U);
}

/* Configures SPI0 as d_analog does: 16-bit 2 MHz master, interrupts off. */
static void spi_setup(void)
{
	wr32(SPIGCR0, 1);
	wr32(SPIGCR1, 3);
	wr32(SPI + 0x14, 0x0E08);
	wr32(SPI + 0x50, 0x00010010U | (74U << 8));
	wr32(SPI + 0x48, 0x0A0A0A0A);
	wr32(SPIINT0, 0);
	wr32(SPI + 0x4C, 8);
	wr32(SPIGCR1, 0x01000003);
}

/* d_analog's transfer: wait for TXFULL to clear, write, poll until RXEMPTY clears. */
static uint32_t polled_frame(uint16_t word)
{
	uint32_t buf;

	while ((buf = rd32(SPIBUF)) & TXFULL)
		;
	note("poll tx", buf);
	wr32(SPIDAT0, word);
	while ((buf = rd32(SPIBUF)) & RXEMPTY)
		;
	note("poll rx", buf);
	return buf;
}

static void event_reads_flags(void *arg)
{
	note(arg, rd32(SPIFLG));
}

/* A device event polling a frame of its own (the stall inside an event). */
static void event_polls_frame(void *arg)
{
	uint32_t buf;

	wr32(SPIDAT0, 0x1A40);
	while ((buf = rd32(SPIBUF)) & RXEMPTY)
		;
	note(arg, buf);
}

/* The frame time of the format spi_setup sets: one frame written and polled. */
static uint64_t frame_length(void)
{
	uint64_t t0 = hs_now();

	wr32(SPIDAT0, 0x1840);
	while (rd32(SPIBUF) & RXEMPTY)
		;
	return hs_now() - t0;
}

/* The sequence, observed; deferral on or off, SPI0's register log on or off. */
static void run_sequence(bool defer, bool logged, struct run *r, const char *vcd_path)
{
	uint64_t frame_ns, end;
	uint32_t buf;
	struct devtest_reglog log = { NULL, NULL, 0 };

	cur = r;
	r->notes.count = 0;
	hs_spi_defer_private_ends(defer);
	devtest_boot(11, vcd_path);
	if (logged)
		devtest_reglog_begin(&log, "SPI0");
	spi_setup();
	for (unsigned i = 0; i < 6; i++)
		polled_frame((uint16_t)(0x1840U | (i << 7)));

	/* reads in the middle of a frame, then the stalling SPIBUF read */
	wr32(SPIDAT0, 0x1840);
	hs_sim_run_for(2 * US);
	note("mid flg", rd32(SPIFLG));
	note("mid emu", rd32(SPIEMU));
	note("mid buf", rd32(SPIBUF));
	note("after buf", rd32(SPIBUF));

	/* the frame ends unobserved; its flag is cleared before SPIBUF is read */
	wr32(SPIDAT0, 0x18C0);
	hs_sim_run_for(20 * US);
	wr32(SPIFLG, RXINTFLG);
	note("flg after w1c", rd32(SPIFLG));
	note("buf after w1c", rd32(SPIBUF));

	/* an interrupt-enabled frame, enabled before it starts */
	wr32(SPIINT0, RXINTENA);
	wr32(SPIDAT0, 0x1940);
	hs_sim_run_for(2 * US);
	note("irq frame mid", rd32(SPIFLG));
	hs_sim_run_for(20 * US);
	note("irq frame end", rd32(SPIFLG));
	note("irq frame buf", rd32(SPIBUF));
	wr32(SPIINT0, 0);

	/* the interrupt enabled in the middle of a frame: the line rises at its end */
	wr32(SPIDAT0, 0x19C0);
	hs_sim_run_for(3 * US);
	wr32(SPIINT0, RXINTENA);
	note("enabled mid frame", rd32(SPIINT0));
	hs_sim_run_for(20 * US);
	note("line after end", rd32(SPIFLG));
	note("its buf", rd32(SPIBUF));
	wr32(SPIINT0, 0);

	/* enabled after an unobserved end: the line rises at the write */
	wr32(SPIDAT0, 0x1A40);
	hs_sim_run_for(20 * US);
	wr32(SPIINT0, RXINTENA);
	note("enabled after end", rd32(SPIINT0));
	note("late buf", rd32(SPIBUF));
	wr32(SPIINT0, 0);

	/* a word waiting in the TX buffer starts at the first one's end */
	wr32(SPIDAT0, 0x1AC0);
	wr32(SPIDAT0, 0x1B40);
	note("txfull buf", rd32(SPIBUF));
	note("second buf", rd32(SPIBUF));
	note("drained", rd32(SPIBUF));

	/* an overrun: two frames end with SPIBUF unread */
	wr32(SPIDAT0, 0x1BC0);
	hs_sim_run_for(20 * US);
	wr32(SPIDAT0, 0x1C40);
	hs_sim_run_for(20 * US);
	note("ovr flg", rd32(SPIFLG));
	note("ovr buf", rd32(SPIBUF));
	wr32(SPIFLG, 0x15F);

	/* the idle check stops at the frame's end */
	wr32(SPIDAT0, 0x1CC0);
	note("idle", rtos_host_run_until_idle(1000 * US));
	note("idle buf", rd32(SPIBUF));

	/* events at the frame's end time, one scheduled before the frame and one after */
	frame_ns = frame_length();
	end = hs_now() + frame_ns;
	hs_sim_at(end, event_reads_flags, "event before frame");
	wr32(SPIDAT0, 0x1D40);
	hs_sim_at(end, event_reads_flags, "event after frame");
	hs_sim_run_for(20 * US);
	note("buf after events", rd32(SPIBUF));

	/* the run ends exactly at the frame's end */
	wr32(SPIDAT0, 0x1DC0);
	hs_sim_run_until(end + frame_ns + 2 * US);
	note("flg at end", rd32(SPIFLG));
	rd32(SPIBUF);

	/* the format, the delay and the format selected change between polled
	 * frames: each next frame is timed and cut by them */
	wr32(SPI + 0x50, 0x00010010U | (20U << 8));    /* SPIFMT0: a faster clock */
	polled_frame(0x1E40);
	wr32(SPI + 0x48, 0x02020202);                   /* SPIDELAY: shorter chip-select delays */
	polled_frame(0x1EC0);
	wr32(SPI + 0x54, 0x00010008U | (10U << 8));    /* SPIFMT1: 8-bit words */
	wr32(SPI + 0x3C, (1U << 24) | 0x1F40U);         /* SPIDAT1: selects SPIFMT1 and sends */
	while ((buf = rd32(SPIBUF)) & RXEMPTY)
		;
	note("8-bit frame", buf);
	polled_frame(0x1FC0);
	wr32(SPI + 0x3C, 0x1840);                       /* back to SPIFMT0 */
	while (rd32(SPIBUF) & RXEMPTY)
		;
	polled_frame(0x1840);
	wr32(SPIGCR1, 0x01000003);                      /* written again, unchanged */
	polled_frame(0x18C0);

	/* SPIBUF stalls that do more than move the clock: an event falls due
	 * during the stall; a device event's stall crosses the run's end; a
	 * model-side read (hs_cpu_read: no register access in progress) stalls */
	hs_sim_at(hs_now() + 3 * US, event_reads_flags, "event during stall");
	wr32(SPIDAT0, 0x1940);
	note("buf after event", rd32(SPIBUF));
	hs_sim_at(hs_now() + 10 * US, event_polls_frame, "event's frame");
	hs_sim_run_for(12 * US);
	note("after run end", rd32(SPIFLG));
	hs_sim_run_for(20 * US);
	wr32(SPIDAT0, 0x19C0);
	note("model-side buf", hs_cpu_read(SPIBUF, 4));
	note("model-side after", rd32(SPIFLG));

	/* a reset after an unobserved end, and the statistics */
	wr32(SPIDAT0, 0x1E40);
	hs_sim_run_for(20 * US);
	wr32(SPIGCR0, 0);
	note("after reset", rd32(SPIBUF));
	spi_setup();
	wr32(SPIDAT0, 0x1EC0);
	hs_sim_run_for(20 * US);
	r->stats = *ev3_spi_get_stats();
	r->deferred = r->stats.deferred_ends;
	r->stats.deferred_ends = 0;
	note("stats transfers", r->stats.transfers);
	if (logged)
		r->log_lines = devtest_reglog_end(&log);
	if (hs_sim_shutdown() != E_OK)
		tap_bail_out("shutdown failed");
	tf_read_text(vcd_path, r->vcd, sizeof(r->vcd));
}

int main(void)
{
	static struct run eager, deferred, logged;
	char dir[] = "/tmp/test_spi_deferred.XXXXXX", eager_vcd[64], deferred_vcd[64], logged_vcd[64];

	tap_plan(12);
	tf_make_scratch_dir(dir);
	snprintf(eager_vcd, sizeof(eager_vcd), "%s/eager.vcd", dir);
	snprintf(deferred_vcd, sizeof(deferred_vcd), "%s/deferred.vcd", dir);
	snprintf(logged_vcd, sizeof(logged_vcd), "%s/logged.vcd", dir);
	run_sequence(false, false, &eager, eager_vcd);
	run_sequence(true, false, &deferred, deferred_vcd);
	run_sequence(true, true, &logged, logged_vcd);
	tf_remove_tree(dir);

	is_int(eager.deferred, 0, "with deferral off every frame end is an event");
	ok(deferred.deferred >= 10, "with deferral on the polled frames' ends are deferred (%u)", deferred.deferred);
	is_int(deferred.notes.count, eager.notes.count, "the same number of observations (%u)", eager.notes.count);
	is_int(devtest_same_notes(&eager.notes, &deferred.notes, "eager", "deferred"), eager.notes.count,
	       "every observation has the same value, time and interrupt line");
	ok(memcmp(&eager.stats, &deferred.stats, sizeof(eager.stats)) == 0,
	   "the same statistics (%u transfers, %u stalls, %u overruns)", eager.stats.transfers,
	   eager.stats.stalls, eager.stats.rx_overruns);
	ok(eager.stats.rx_overruns >= 1, "the sequence has an overrun");
	ok(strstr(eager.vcd, "spi0") != NULL || strstr(eager.vcd, "SPI0") != NULL || eager.vcd[0] != '\0',
	   "the VCD was written");
	is_str(deferred.vcd, eager.vcd, "the VCD (interrupt lines and every other signal) is identical");
	ok(eager.notes.count > 30, "the sequence was observed (%u notes)", eager.notes.count);
	ok(logged.notes.count == deferred.notes.count &&
	   devtest_same_notes(&deferred.notes, &logged.notes, "unlogged", "logged") == deferred.notes.count,
	   "with the register log on (the hooks instead of the direct accesses), the same observations");
	ok(memcmp(&logged.stats, &deferred.stats, sizeof(logged.stats)) == 0 && logged.deferred == deferred.deferred &&
	   strcmp(logged.vcd, deferred.vcd) == 0, "and the same statistics, deferrals and VCD");
	ok(logged.log_lines > 2U * eager.notes.count, "the register log was on (%u lines)", logged.log_lines);
	return tap_done();
}

/*
 * test_edge_watch.c — a driver from outside ev3_drivers/ taken unchanged:
 * edge_watch.c (GPIO both-edge IRQ, hrtimer watchdog, misc device with
 * blocking read and poll, ioctls, module parameters) is included verbatim,
 * as a hack file does, and used through its file operations while host_sim
 * drives its pin: edges and watchdog timeouts wake a blocked read at the
 * virtual time they happen, and a pulse generator (a host_sim event source)
 * drives the pin while the task sleeps.
 */
#define KBUILD_MODNAME "edge_watch"
#include "driver_common.h"
#include "edge_watch.c"

#include "lx_test.h"
#include <linux_compat/devfs.h>
#include <linux_compat/clock.h>
#include "host_sim/board.h"
#include "host_sim/gpio.h"
#include "host_sim/clock.h"

/* A pulse generator outside the SoC: toggles the pin every half period, count edges. */
struct pulse_gen {
	unsigned int pin;
	uint64_t half_period_ns;
	unsigned int edges_left;
	int level;
	hs_event_t ev;
};

static void pulse_gen_edge(void *arg)
{
	struct pulse_gen *g = arg;

	g->level = !g->level;
	hs_gpio_set_input(g->pin, g->level);
	g->ev = --g->edges_left ? hs_event_after(g->half_period_ns, pulse_gen_edge, g) : (hs_event_t){ 0 };
}

static void body(void)
{
	struct edge_watch_counts counts;
	struct file *f = NULL, *nb = NULL;
	char line[48];
	uint64_t t0;
	ssize_t n;

	if (lx_dev_open("/dev/edge_watch", O_RDONLY, &f) != 0 ||
	    lx_dev_open("/dev/edge_watch", O_RDONLY | O_NONBLOCK, &nb) != 0) {
		ok(0, "open /dev/edge_watch");
		return;
	}
	ok(1, "module_init ran at boot: /dev/edge_watch opens (blocking and O_NONBLOCK)");
	is_int((int)lx_dev_read(nb, line, sizeof(line), NULL), -EAGAIN, "O_NONBLOCK read with no event: -EAGAIN");
	ok(!(lx_dev_poll(nb) & EPOLLIN), "poll: nothing to read");

	hs_gpio_set_input(gpio, 1);
	ok(lx_dev_poll(nb) & EPOLLIN, "a rising edge: poll reports EPOLLIN");
	memset(line, 0, sizeof(line));
	n = lx_dev_read(f, line, sizeof(line), NULL);
	ok(n > 0 && strcmp(line, "edges=1 timeouts=0\n") == 0, "read returns the edge: %s", line);

	t0 = lx_clock_now_ns();
	memset(line, 0, sizeof(line));
	n = lx_dev_read(f, line, sizeof(line), NULL);
	ok(n > 0 && strcmp(line, "edges=1 timeouts=1\n") == 0, "a blocking read wakes on the watchdog: %s", line);
	in_range((long long)(lx_clock_now_ns() - t0), 10000000LL - 200000LL, 10000000LL + 200000LL,
		 "after timeout_ms (10 ms) without an edge, within a tick");

	hs_gpio_set_input(gpio, 0);
	hs_gpio_set_input(gpio, 1);
	hs_gpio_set_input(gpio, 0);
	is_int((int)lx_dev_ioctl(f, EDGE_WATCH_GET, (unsigned long)&counts), 0, "EDGE_WATCH_GET");
	ok(counts.edges == 4 && counts.timeouts == 1, "both edges counted: %u edges, %u timeouts",
	   counts.edges, counts.timeouts);
	is_int((int)lx_dev_ioctl(f, EDGE_WATCH_RESET, 0), 0, "EDGE_WATCH_RESET");

	{
		/* 20 edges 500 us apart: no watchdog period (10 ms) passes without an edge. */
		static struct pulse_gen gen = { .half_period_ns = 500000, .edges_left = 20 };

		gen.pin = (unsigned int)gpio;
		gen.level = 0;
		gen.ev = hs_event_after(gen.half_period_ns, pulse_gen_edge, &gen);
		msleep(15);
		(void)lx_dev_ioctl(f, EDGE_WATCH_GET, (unsigned long)&counts);
		ok(counts.edges == 20 && counts.timeouts == 0,
		   "a pulse generator on the pin: 20 edges, no timeout (%u, %u)", counts.edges, counts.timeouts);
	}
	is_int((int)lx_dev_ioctl(f, 0x1234, 0), -ENOTTY, "an unknown ioctl: -ENOTTY");
	(void)lx_dev_close(f);
	(void)lx_dev_close(nb);
}

int main(void)
{
	tap_plan(14);
	is_int(hs_board_init(NULL), E_OK, "host_sim board (the AM1808 registers)");
	ok(lx_test_run(body), "test task ran to completion");
	return tap_done();
}

/*
 * app.c — dtq: a producer and a consumer coupled by a data queue.
 *
 * The producer, an EV3 cyclic handler every 10 ms, sends sequence numbers
 * 1..ITEMS into SAMPLE_DTQ without waiting (psnd_dtq: a full queue loses the
 * item, counted).  The consumer task takes them with a timeout (trcv_dtq),
 * checks that they come in order, and works in bursts: after every 5 items it
 * sleeps 35 ms, so the queue fills up to a few elements and drains again —
 * QUEUE_DEPTH is enough that nothing is lost.  When no item comes for 200 ms
 * the consumer logs the totals.
 */
#include "ev3api.h"
#include "app.h"

#define BURST        5
#define BURST_PAUSE  35
#define IDLE_MS      200

static volatile int produced, lost;

void producer_cyc(intptr_t exinf)
{
	if (produced == ITEMS)
		return;
	produced++;
	if (psnd_dtq(SAMPLE_DTQ, (intptr_t)produced) != E_OK)
		lost++;
}

void consumer_task(intptr_t exinf)
{
	intptr_t item;
	long sum = 0;
	int received = 0, out_of_order = 0, max_depth = 0;
	T_RDTQ ref;

	while (trcv_dtq(SAMPLE_DTQ, &item, IDLE_MS) == E_OK) {
		if (item != received + 1 + lost)
			out_of_order++;
		received++;
		sum += item;
		if (ref_dtq(SAMPLE_DTQ, &ref) == E_OK && (int)ref.sdtqcnt > max_depth)
			max_depth = (int)ref.sdtqcnt;
		if (received % BURST == 0)
			tslp_tsk(BURST_PAUSE);
	}
	syslog(LOG_NOTICE, "dtq: received %d of %d, sum %ld, out of order %d, lost %d, max depth %d",
	       received, produced, sum, out_of_order, lost, max_depth);
}

/*
 * test_header_wait_first.c — linux/wait.h is self-contained at use: with it
 * as the first and only Linux header, wait_event_interruptible (which
 * expands to -ERESTARTSYS) compiles and works.
 */
#include <linux/wait.h>
#include "lx_test.h"

static DECLARE_WAIT_QUEUE_HEAD(wq);
static int flag = 1;

static void body(void)
{
	is_int(wait_event_interruptible(wq, flag != 0), 0, "wait_event_interruptible on a true condition: 0");
	is_int(wait_event_interruptible_timeout(wq, flag != 0, 1), 1,
	       "wait_event_interruptible_timeout on a true condition: the jiffies left (at least 1)");
}

int main(void)
{
	tap_plan(3);
	ok(lx_test_run(body), "test task ran to completion");
	return tap_done();
}

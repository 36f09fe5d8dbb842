/*
 * test_irq_thread.c — threaded IRQs (kernel/irq/manage.c's rules): the
 * primary handler in interrupt context wakes the thread function with
 * IRQ_WAKE_THREAD, the thread runs in its own task (process context, it may
 * sleep) before lower-priority tasks; IRQF_ONESHOT keeps the line masked
 * until the thread returns and an interrupt latched meanwhile is delivered
 * after; without ONESHOT the line stays open; a NULL primary handler needs
 * ONESHOT; irq_wake_thread; IRQ_WAKE_THREAD without a thread warns;
 * free_irq and disable_irq wait for a running thread; the threads run out
 * (-ENOMEM); shared handlers disagreeing on ONESHOT are -EBUSY.
 */
#include "lx_log_test.h"
#include <linux/delay.h>
#include <linux/interrupt.h>
#include <linux_compat/context.h>
#include <mach/irqs.h>

#define LINE	IRQ_DA8XX_UARTINT0
#define LINE2	IRQ_DA8XX_UARTINT1
#define LINE3	IRQ_DA8XX_EVTOUT1

static char log_buf[128];
static int dev_a, dev_b, dev_c;
static bool hard_in_irq, thread_in_task, line_open_in_thread;
static unsigned int thread_sleep_ms;
static int thread_runs;

static void log_add(const char *s)
{
	strncat(log_buf, s, sizeof(log_buf) - strlen(log_buf) - 1);
}

static irqreturn_t hard(int irq, void *dev)
{
	log_add("h");
	hard_in_irq = in_interrupt() && !in_task();
	return IRQ_WAKE_THREAD;
}

static irqreturn_t thread_fn(int irq, void *dev)
{
	log_add("t");
	thread_in_task = in_task() && !in_atomic();
	line_open_in_thread = rtos_host_irq_enabled((INTNO)irq);
	if (thread_sleep_ms)
		msleep(thread_sleep_ms);
	thread_runs++;
	log_add("T");
	return IRQ_HANDLED;
}

static irqreturn_t plain(int irq, void *dev)
{
	log_add("p");
	return IRQ_WAKE_THREAD;
}

static void oneshot_tests(void)
{
	log_buf[0] = '\0';
	is_int(request_threaded_irq(LINE, hard, thread_fn, IRQF_ONESHOT, "t", &dev_a), 0,
	       "request_threaded_irq with IRQF_ONESHOT");
	ok(rtos_host_irq_enabled(LINE), "the line is enabled");
	rtos_host_irq_raise(LINE);
	is_str(log_buf, "htT", "the interrupt ran the handler, then the thread before this task went on");
	ok(hard_in_irq, "the handler ran in interrupt context");
	ok(thread_in_task, "the thread function ran in process context");
	ok(!line_open_in_thread, "IRQF_ONESHOT: the line was masked while the thread ran");
	ok(rtos_host_irq_enabled(LINE), "and is unmasked when it returned");

	log_buf[0] = '\0';
	thread_sleep_ms = 10;
	thread_runs = 0;
	rtos_host_irq_raise(LINE);
	is_str(log_buf, "ht", "a thread that sleeps: this task runs meanwhile");
	rtos_host_irq_raise(LINE);
	ok(!rtos_host_irq_enabled(LINE), "a second interrupt waits while the line is masked");
	msleep(30);
	is_str(log_buf, "htThtT", "and is delivered once the thread returned");
	is_int(thread_runs, 2, "two thread runs");

	log_buf[0] = '\0';
	thread_runs = 0;
	rtos_host_irq_raise(LINE);
	free_irq(LINE, &dev_a);
	is_str(log_buf, "htT", "free_irq waited for the sleeping thread to finish");
	ok(!rtos_host_irq_enabled(LINE), "the line is off after free_irq");
	thread_sleep_ms = 0;
}

static void open_line_tests(void)
{
	log_buf[0] = '\0';
	is_int(request_threaded_irq(LINE, hard, thread_fn, 0, "t", &dev_a), 0, "a threaded IRQ without ONESHOT");
	rtos_host_irq_raise(LINE);
	is_str(log_buf, "htT", "handler and thread");
	ok(line_open_in_thread, "the line stayed open while the thread ran");

	log_buf[0] = '\0';
	irq_wake_thread(LINE, &dev_a);
	is_str(log_buf, "tT", "irq_wake_thread runs the thread without an interrupt");

	log_buf[0] = '\0';
	thread_sleep_ms = 10;
	rtos_host_irq_raise(LINE);
	disable_irq(LINE);
	is_str(log_buf, "htT", "disable_irq waited for the running thread");
	enable_irq(LINE);
	thread_sleep_ms = 0;
	free_irq(LINE, &dev_a);

	log_buf[0] = '\0';
	is_int(request_threaded_irq(LINE, NULL, thread_fn, 0, "t", &dev_a), -EINVAL,
	       "no primary handler and no IRQF_ONESHOT: -EINVAL");
	is_int(request_threaded_irq(LINE, NULL, thread_fn, IRQF_ONESHOT, "t", &dev_a), 0,
	       "no primary handler with IRQF_ONESHOT");
	rtos_host_irq_raise(LINE);
	is_str(log_buf, "tT", "every interrupt wakes the thread");
	ok(!line_open_in_thread, "with the line masked meanwhile");
	free_irq(LINE, &dev_a);
}

static void limit_tests(void)
{
	is_int(request_threaded_irq(LINE, hard, thread_fn, IRQF_ONESHOT | IRQF_SHARED, "a", &dev_a), 0,
	       "a shared ONESHOT threaded handler");
	is_int(request_irq(LINE, plain, IRQF_SHARED, "b", &dev_b), -EBUSY,
	       "a shared handler without ONESHOT on that line: -EBUSY");
	is_int(request_threaded_irq(LINE2, hard, thread_fn, 0, "b", &dev_b), 0, "a second thread");
	dc_log_start();
	is_int(request_threaded_irq(LINE3, hard, thread_fn, 0, "c", &dev_c), -ENOMEM,
	       "all LX_NR_IRQ_THREADS threads taken: -ENOMEM");
	ok(dc_logged("raise LX_NR_IRQ_THREADS"), "with a message saying what to raise");
	free_irq(LINE, &dev_a);
	free_irq(LINE2, &dev_b);
	is_int(request_threaded_irq(LINE3, hard, thread_fn, 0, "c", &dev_c), 0, "free_irq gave the thread back");
	free_irq(LINE3, &dev_c);

	log_buf[0] = '\0';
	dc_log_start();
	is_int(request_irq(LINE, plain, 0, "plain", &dev_a), 0, "a handler without a thread");
	rtos_host_irq_raise(LINE);
	is_str(log_buf, "p", "returning IRQ_WAKE_THREAD");
	ok(dc_logged("IRQ 25 device plain returned IRQ_WAKE_THREAD but no thread function available"),
	   "warns as Linux does");
	free_irq(LINE, &dev_a);
}

static void body(void)
{
	oneshot_tests();
	open_line_tests();
	limit_tests();
}

int main(void)
{
	tap_plan(32);
	ok(lx_test_run(body), "test task ran to completion");
	return tap_done();
}

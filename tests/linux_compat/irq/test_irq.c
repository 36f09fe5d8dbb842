/*
 * test_irq.c — Linux IRQs on the RTOS lines of linux_irq_cfg: request_irq
 * enables the line and free_irq of the last handler disables it; shared
 * lines call every handler in request order (IRQ_NONE / IRQ_HANDLED
 * accounted), a shared request with a different trigger is -EBUSY;
 * handlers run in interrupt context; disable/enable nest; argument and context errors are refused or reported.
 */
#include "lx_test.h"
#include <linux/interrupt.h>
#include <linux/irq.h>
#include <linux_compat/context.h>
#include <linux_compat/irq.h>

static char log_buf[256];
static int dev_a, dev_b, dev_c;
static irqreturn_t answer_a = IRQ_HANDLED, answer_b = IRQ_HANDLED;
static bool saw_interrupt_context, saw_current_irq;

static void log_add(const char *s)
{
	strncat(log_buf, s, sizeof(log_buf) - strlen(log_buf) - 1);
}

static irqreturn_t handler_a(int irq, void *dev)
{
	log_add(dev == &dev_a ? "a" : "a?");
	saw_interrupt_context = lx_in_interrupt() && lx_in_atomic();
	saw_current_irq = lx_current_irq() == irq;
	return answer_a;
}

static irqreturn_t handler_b(int irq, void *dev)
{
	log_add(dev == &dev_b ? "b" : "b?");
	return answer_b;
}

static irqreturn_t handler_c(int irq, void *dev)
{
	log_add("c");
	return IRQ_NONE;
}

static irqreturn_t handler_frees_itself(int irq, void *dev)
{
	log_add("f");
	(void)free_irq((unsigned int)irq, dev);
	return IRQ_HANDLED;
}

static irqreturn_t handler_disables_itself(int irq, void *dev)
{
	log_add("d");
	disable_irq((unsigned int)irq);
	return IRQ_HANDLED;
}

static irqreturn_t handler_nosync(int irq, void *dev)
{
	log_add("n");
	disable_irq_nosync((unsigned int)irq);
	return IRQ_HANDLED;
}

static void raise_and_log(unsigned int line, const char *expect, const char *what)
{
	log_buf[0] = '\0';
	rtos_host_irq_raise(line);
	is_str(log_buf, expect, "%s", what);
}

static void test_errors(void)
{
	is_int(request_irq(IRQ_DA8XX_UARTINT0, NULL, 0, "x", &dev_a), -EINVAL, "no handler: -EINVAL");
	is_int(request_irq(30, handler_a, 0, "x", &dev_a), -EINVAL, "a line without an RTOS ISR: -EINVAL");
	is_int(request_irq(IRQ_DA8XX_GPIO5, handler_a, 0, "x", &dev_a), -EINVAL,
	       "a GPIO bank line (demultiplexed into pin IRQs): -EINVAL");
	is_int(request_irq(NR_IRQS, handler_a, 0, "x", &dev_a), -EINVAL, "beyond NR_IRQS: -EINVAL");
	is_int(request_irq(IRQ_DA8XX_UARTINT1, handler_a, IRQF_SHARED, "x", NULL), -EINVAL,
	       "IRQF_SHARED without dev_id: -EINVAL");
	is_int(request_threaded_irq(IRQ_DA8XX_UARTINT1, NULL, handler_b, 0, "x", &dev_a), -EINVAL,
	       "a threaded handler without a primary handler needs IRQF_ONESHOT: -EINVAL");
	is_int(irq_set_irq_type(IRQ_DA8XX_UARTINT0, IRQ_TYPE_EDGE_FALLING), -EINVAL,
	       "an AINTC line cannot trigger on falling edges");
	is_int(irq_set_irq_type(IRQ_DA8XX_UARTINT0, IRQ_TYPE_LEVEL_HIGH), 0, "but level-high is its nature");
	is_int(set_irq_type(IRQ_DA8XX_UARTINT0, IRQ_TYPE_EDGE_RISING), 0, "2.6.33's set_irq_type works too");
	is_int(irq_get_trigger_type(IRQ_DA8XX_UARTINT0), IRQ_TYPE_EDGE_RISING, "and is recorded");
}

static void test_single(void)
{
	ok(!rtos_host_irq_enabled(IRQ_DA8XX_UARTINT0), "the line starts disabled");
	is_int(rtos_host_irq_priority(IRQ_DA8XX_UARTINT0), LX_IRQ_PRIORITY, "at the Linux lines' priority");
	is_int(request_irq(IRQ_DA8XX_UARTINT0, handler_a, 0, "uart0", &dev_a), 0, "request_irq");
	ok(rtos_host_irq_enabled(IRQ_DA8XX_UARTINT0), "request_irq enabled the RTOS line");
	raise_and_log(IRQ_DA8XX_UARTINT0, "a", "the handler runs on an interrupt, with its dev_id");
	ok(saw_interrupt_context, "in interrupt (atomic) context");
	ok(saw_current_irq, "lx_current_irq() names its irq");
	is_int(lx_irq_count(IRQ_DA8XX_UARTINT0), 1, "one dispatch counted");
	is_int(request_irq(IRQ_DA8XX_UARTINT0, handler_b, IRQF_SHARED, "b", &dev_b), -EBUSY,
	       "a second handler on a non-shared line: -EBUSY");

	disable_irq(IRQ_DA8XX_UARTINT0);
	disable_irq(IRQ_DA8XX_UARTINT0);
	ok(!rtos_host_irq_enabled(IRQ_DA8XX_UARTINT0), "disable_irq disables the line");
	raise_and_log(IRQ_DA8XX_UARTINT0, "", "no handler call while disabled");
	enable_irq(IRQ_DA8XX_UARTINT0);
	ok(!rtos_host_irq_enabled(IRQ_DA8XX_UARTINT0), "disables nest: one enable is not enough");
	log_buf[0] = '\0';
	enable_irq(IRQ_DA8XX_UARTINT0);
	is_str(log_buf, "a", "the second enable delivers the edge latched meanwhile");

	rtos_host_expect_bugs(true);
	enable_irq(IRQ_DA8XX_UARTINT0);
	rtos_host_expect_bugs(false);
	ok(strstr(rtos_host_last_bug(), "Unbalanced enable") != NULL, "an unbalanced enable_irq warns");

	is_str((const char *)free_irq(IRQ_DA8XX_UARTINT0, &dev_a), "uart0", "free_irq returns the name");
	ok(!rtos_host_irq_enabled(IRQ_DA8XX_UARTINT0), "freeing the last handler disabled the line");
	rtos_host_expect_bugs(true);
	ok(free_irq(IRQ_DA8XX_UARTINT0, &dev_a) == NULL, "freeing it again returns NULL");
	rtos_host_expect_bugs(false);
	ok(strstr(rtos_host_last_bug(), "already-free") != NULL, "and warns");
}

static void test_shared(void)
{
	unsigned int line = IRQ_DA8XX_UARTINT1;

	is_int(request_irq(line, handler_a, IRQF_SHARED, "a", &dev_a), 0, "shared handler a");
	is_int(request_irq(line, handler_b, IRQF_SHARED, "b", &dev_b), 0, "shared handler b");
	is_int(request_irq(line, handler_b, IRQF_SHARED, "b2", &dev_b), -EINVAL,
	       "the same dev_id twice on a line: -EINVAL");
	is_int(request_irq(line, handler_b, 0, "c", &dev_c), -EBUSY, "a non-shared request on a shared line: -EBUSY");
	raise_and_log(line, "ab", "both handlers run, in request order");

	answer_a = IRQ_NONE;
	raise_and_log(line, "ab", "both run although a answers IRQ_NONE");
	is_int(lx_irq_unhandled_count(line), 0, "b handled it: not an unhandled interrupt");
	answer_b = IRQ_NONE;
	raise_and_log(line, "ab", "both run again");
	is_int(lx_irq_unhandled_count(line), 1, "nobody handled it: counted as unhandled");
	answer_a = answer_b = IRQ_HANDLED;

	is_int(request_irq(line, handler_c, IRQF_SHARED, "c", &dev_c), 0, "a third handler joins");
	raise_and_log(line, "abc", "three handlers, in order");
	is_str((const char *)free_irq(line, &dev_b), "b", "free the middle one by its dev_id");
	raise_and_log(line, "ac", "the others remain, in order");
	ok(rtos_host_irq_enabled(line), "the line stays enabled while handlers remain");
	(void)free_irq(line, &dev_a);
	(void)free_irq(line, &dev_c);
	ok(!rtos_host_irq_enabled(line), "freeing the last one disables it");
	raise_and_log(line, "", "no handler runs any more");
}

/* Linux's __setup_irq: a shared request whose trigger differs from the line's is a type mismatch. */
static void test_shared_trigger_mismatch(void)
{
	unsigned int line = IRQ_DA8XX_EVTOUT1;

	is_int(request_irq(line, handler_a, IRQF_SHARED | IRQF_TRIGGER_HIGH, "a", &dev_a), 0,
	       "shared, level-high: the line takes that trigger");
	is_int(request_irq(line, handler_b, IRQF_SHARED | IRQF_TRIGGER_RISING, "b", &dev_b), -EBUSY,
	       "shared with a different trigger (rising): -EBUSY");
	is_int(request_irq(line, handler_b, IRQF_SHARED | IRQF_TRIGGER_HIGH, "b", &dev_b), 0,
	       "shared with the same trigger joins");
	is_int(request_irq(line, handler_c, IRQF_SHARED, "c", &dev_c), 0,
	       "shared without a trigger takes the line's");
	ok(irq_get_trigger_type(line) == IRQ_TYPE_LEVEL_HIGH, "the line's trigger is unchanged");
	(void)free_irq(line, &dev_a);
	(void)free_irq(line, &dev_b);
	(void)free_irq(line, &dev_c);
}

static void test_flags_and_context(void)
{
	unsigned int line = IRQ_DA8XX_EVTOUT0;
	uint_t before;

	is_int(request_irq(line, handler_a, IRQF_NO_AUTOEN, "noauto", &dev_a), 0, "IRQF_NO_AUTOEN");
	ok(!rtos_host_irq_enabled(line), "leaves the line disabled");
	enable_irq(line);
	ok(rtos_host_irq_enabled(line), "until enable_irq");
	(void)free_irq(line, &dev_a);

	is_int(request_irq(line, handler_nosync, 0, "nosync", &dev_a), 0, "handler using disable_irq_nosync");
	before = rtos_host_bug_count();
	raise_and_log(line, "n", "runs");
	ok(!rtos_host_irq_enabled(line) && rtos_host_bug_count() == before,
	   "disable_irq_nosync from its own handler masks the line, silently");
	enable_irq(line);
	(void)free_irq(line, &dev_a);

	is_int(request_irq(line, handler_disables_itself, 0, "selfdisable", &dev_a), 0, "handler using disable_irq");
	rtos_host_expect_bugs(true);
	raise_and_log(line, "d", "runs");
	rtos_host_expect_bugs(false);
	ok(strstr(rtos_host_last_bug(), "disable_irq") != NULL,
	   "disable_irq from the IRQ's own handler is reported (deadlock in Linux)");
	enable_irq(line);
	(void)free_irq(line, &dev_a);

	is_int(request_irq(line, handler_frees_itself, 0, "selffree", &dev_a), 0, "handler calling free_irq");
	rtos_host_expect_bugs(true);
	raise_and_log(line, "f", "runs");
	rtos_host_expect_bugs(false);
	ok(strstr(rtos_host_last_bug(), "free_irq") != NULL,
	   "free_irq from interrupt context is reported: %s", rtos_host_last_bug());
}

static void body(void)
{
	test_errors();
	test_single();
	test_shared();
	test_shared_trigger_mismatch();
	test_flags_and_context();
}

int main(void)
{
	tap_plan(62);
	ok(lx_test_run(body), "test task ran to completion");
	return tap_done();
}

/*
 * ui_svc.c — d_ui's interface on the RTOS: the module's extended
 * service calls (ui_hack.h) and its configuration fragment.  The calls reach
 * the driver only through its file operations (write, read, poll, mmap), so
 * its own checks guard them.
 *
 * A wait for a click with a timeout is what poll(2) + read(2) do in Linux:
 * the driver's .poll puts the caller on its wait queue (through our
 * poll_table), a non-blocking read takes a click when there is one, and in
 * between the task sleeps until the driver's wake_up, the deadline or
 * rel_wai - so a task waiting for clicks can always be stopped.
 * The driver is in ui_hack.c.
 */
#include "hack_svc.h"
#include "ui_hack.h"
#include "ui_module.h"
#include <linux_compat/clock.h>

/* Common checks: task context, the driver up. */
static ER ui_hack_check(void)
{
	if (sns_ctx())
		return E_CTX;
	return ui_file ? E_OK : E_OBJ;
}

/* UI_FN_LED: one pattern byte written to the device. */
ER_UINT svc_ui_led(intptr_t pattern, intptr_t p2, intptr_t p3, intptr_t p4,
			  intptr_t p5, ID cdmid)
{
	u8 byte = (u8)pattern;
	ER ercd = ui_hack_check();

	if (ercd != E_OK)
		return ercd;
	if (pattern < LMS_UI_LED_OFF || pattern > LMS_UI_LED_ORANGE_PULSE)
		return E_PAR;
	return lx_errno_to_er(lx_dev_write(ui_file, (const char __user *)&byte, 1, NULL));
}

/* UI_FN_MAP: the address of the shared page. */
ER_UINT svc_ui_map(intptr_t out, intptr_t p2, intptr_t p3, intptr_t p4,
			  intptr_t p5, ID cdmid)
{
	ER ercd = ui_hack_check();

	if (ercd != E_OK)
		return ercd;
	if (copy_to_user((void __user *)out, &ui_map, sizeof(ui_map)))
		return E_MACV;
	return E_OK;
}

/* The caller's place on the driver's wait queue while it waits for a click. */
struct ui_poller {
	poll_table table;
	wait_queue_head_t *queue;	/* the queue the driver's .poll named, once it has */
	struct lx_waiter waiter;
};

/* poll_wait's callback: queues the calling task on the driver's wait queue. */
static void ui_poll_queue(struct file *file, wait_queue_head_t *queue, poll_table *table)
{
	struct ui_poller *p = container_of(table, struct ui_poller, table);

	if (p->queue)
		return;
	p->queue = queue;
	lx_wait_prepare(queue, &p->waiter, false);
}

/* UI_FN_WAIT_CLICK: read() of one click, waiting at most tmout ms (poll(2) + read(2)). */
ER_UINT svc_ui_wait_click(intptr_t out, intptr_t tmout, intptr_t p3, intptr_t p4,
				 intptr_t p5, ID cdmid)
{
	struct ui_poller p = { .queue = NULL };
	uint64_t deadline = U64_MAX;
	ssize_t ret;
	ER ercd = ui_hack_check();

	if (ercd != E_OK)
		return ercd;
	if (tmout < TMO_FEVR)
		return E_PAR;
	if (prb_mem((void *)out, sizeof(struct lms_ui_click), TSK_SELF, TPM_WRITE) != E_OK)
		return E_MACV;
	if (tmout > 0)
		deadline = lx_clock_now_ns() + (uint64_t)tmout * NSEC_PER_MSEC;
	init_poll_funcptr(&p.table, ui_poll_queue);
	for (;;) {
		struct file *file = READ_ONCE(ui_file);	/* NULL once d_ui is unloading */

		ret = lx_dev_read(file, (char __user *)out, sizeof(struct lms_ui_click), NULL);
		if (ret != -EAGAIN || tmout == TMO_POL)
			break;
		if (!p.queue) {
			/* On the queue first, then look again: no wake_up falls in between. */
			if (file->f_op->poll(file, &p.table) & EPOLLIN)
				continue;
			if (WARN_ON(!p.queue))
				break;
		}
		ret = lx_wait_block(p.queue, &p.waiter, deadline, true);
		if (ret)
			break;
	}
	if (p.queue)
		lx_wait_finish(p.queue, &p.waiter);
	return ret == sizeof(struct lms_ui_click) ? E_OK : lx_errno_to_er(ret < 0 ? ret : -EIO);
}

static const struct rtos_svc_cfg ui_svcs[] = {
	{ UI_FN_LED,        svc_ui_led,        256 },
	{ UI_FN_MAP,        svc_ui_map,        128 },
	{ UI_FN_WAIT_CLICK, svc_ui_wait_click, 1024 },
};

const struct rtos_cfg ui_hack_cfg = {
	.name = "ui_hack",
	.svcs = RTOS_TABLE(ui_svcs),
	.svc_first = UI_FN_FIRST, .svc_count = UI_FN_COUNT,
};

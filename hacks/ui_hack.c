/*
 * ui_hack.c — d_ui on the RTOS (the paper's Fig. 5 pattern): the Linux
 * driver source included byte-for-byte, then its interface as extended
 * service calls (ui_hack.h).  The calls reach the driver only through its
 * file operations (write, read, poll, mmap), so its own checks guard them.
 *
 * A wait for a click with a timeout is what poll(2) + read(2) do in Linux:
 * the driver's .poll puts the caller on its wait queue (through our
 * poll_table), a non-blocking read takes a click when there is one, and in
 * between the task sleeps until the driver's wake_up, the deadline or
 * rel_wai - so a task waiting for clicks can always be stopped.
 */
#define KBUILD_MODNAME "d_ui"
/* The driver's module_init/exit become plain pointers, called by ours below. */
#define LX_HACK_DRIVER_INIT ui_driver_init
#define LX_HACK_DRIVER_EXIT ui_driver_exit

#include "d_ui.c"

#include "driver_common.h"
#include <linux_compat/clock.h>

#include "ui_hack.h"

static struct file *ui_file;		/* /dev/lms_ui, non-blocking */
static const struct lms_ui *ui_map;

/* Loads d_ui, then opens its device and maps the shared page for the service calls. */
static int __init ui_hack_init(void)
{
	void *map;
	int ret;

	ret = ui_driver_init();
	if (ret)
		return ret;
	ret = lx_dev_open("/dev/" LMS_UI_DEVICE_NAME, O_RDWR | O_NONBLOCK, &ui_file);
	if (!ret)
		ret = lx_dev_mmap(ui_file, LMS_UI_MAP_SIZE, &map);
	if (ret) {
		pr_err("ui_hack: cannot open d_ui's device (%d)\n", ret);
		lx_dev_close(ui_file);
		ui_file = NULL;
		ui_driver_exit();
		return ret;
	}
	ui_map = map;
	return 0;
}
module_init(ui_hack_init);

/*
 * Withdraws the device (the service calls then answer E_OBJ), wakes the
 * tasks waiting for a click so that they see it gone, then closes the file
 * and unloads d_ui.  (In Linux an open file would keep the module loaded.)
 */
static void __exit ui_hack_exit(void)
{
	struct file *file = ui_file;

	WRITE_ONCE(ui_file, NULL);
	ui_map = NULL;
	wake_up_all(&ui.readers);
	lx_dev_close(file);
	ui_driver_exit();
}
module_exit(ui_hack_exit);

/* Common checks: task context, the driver up. */
static ER ui_hack_check(void)
{
	if (sns_ctx())
		return E_CTX;
	return ui_file ? E_OK : E_OBJ;
}

/* UI_FN_LED: one pattern byte written to the device. */
static ER_UINT svc_ui_led(intptr_t pattern, intptr_t p2, intptr_t p3, intptr_t p4,
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
static ER_UINT svc_ui_map(intptr_t out, intptr_t p2, intptr_t p3, intptr_t p4,
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
static ER_UINT svc_ui_wait_click(intptr_t out, intptr_t tmout, intptr_t p3, intptr_t p4,
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

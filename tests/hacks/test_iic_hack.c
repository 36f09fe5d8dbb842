/*
 * test_iic_hack.c — argument checks of d_iic's extended service calls
 * (iic_hack.h): ports, modes, lengths, pointers and context are refused
 * with the documented TOPPERS codes before anything reaches the driver,
 * driver refusals come back as TOPPERS codes, and a port's start and stop
 * leave the other ports alone.
 */
#include "iic_test.h"

static ER irq_ercd = E_OK;

/* Runs in the hardware's (non-task) context. */
static void from_irq(void *arg)
{
	(void)arg;
	irq_ercd = (ER)iic_svc_state(0);
}

static void body(void)
{
	struct lms_iic_str s;
	struct lms_iic_dat d;
	const struct lms_iic *map = NULL;
	unsigned fn;

	memset(&s, 0, sizeof(s));
	memset(&d, 0, sizeof(d));
	for (fn = IIC_FN_START; fn <= IIC_FN_STATE; fn++) {
		if (fn == IIC_FN_SET || fn == IIC_FN_SETUP || fn == IIC_FN_MAP)
			continue;	/* the port is in the structure, or there is none */
		is_int(cal_svc(fn, -1, (intptr_t)&s, 0, 0, 0), E_ID, "fn %u: port -1 is E_ID", fn);
		is_int(cal_svc(fn, 4, (intptr_t)&s, 0, 0, 0), E_ID, "fn %u: port 4 is E_ID", fn);
	}
	s.port = 4;
	is_int(iic_svc_set(&s), E_ID, "set: port 4 in the IICSTR is E_ID");
	d.port = -1;
	is_int(iic_svc_setup(&d), E_ID, "setup: port -1 in the IICDAT is E_ID");
	is_int(cal_svc(IIC_FN_START, 0, -1, 0, 0, 0), E_PAR, "start: mode -1 is E_PAR");
	is_int(cal_svc(IIC_FN_START, 0, 128, 0, 0, 0), E_PAR, "start: mode 128 is E_PAR");
	is_int(iic_svc_set(NULL), E_MACV, "set: NULL is E_MACV");
	is_int(iic_svc_setup(NULL), E_MACV, "setup: NULL is E_MACV");
	is_int(iic_svc_type_info(0, NULL), E_MACV, "type_info: NULL is E_MACV");
	is_int(iic_svc_map(NULL), E_MACV, "map: NULL is E_MACV");
	is_int(iic_svc_type_info(0, &s), E_OBJ, "type_info: idle port is E_OBJ");
	d.port = 0;
	d.wr_lng = 2;
	d.rd_lng = 1;
	is_int(iic_svc_setup(&d), E_OBJ, "setup: idle port is E_OBJ");
	s.port = 0;
	s.poll_lng = 2;
	s.read_lng = 40;
	is_int(iic_svc_set(&s), E_PAR, "set: read length 40 is E_PAR (the driver's -EINVAL)");
	is_int(iic_svc_map(&map), E_OK, "map");
	ok(map != NULL && map == it_shm, "gives the shared memory");
	is_int(cal_svc(IIC_FN_STATE + 1, 0, 0, 0, 0, 0), E_RSFN, "unused function code is E_RSFN");

	is_int(iic_svc_start(0, 1), E_OK, "start port 1 (no sensor)");
	is_int(iic_svc_start(1, 0), E_OK, "start port 2");
	dly_tsk(4);
	ok(iic_svc_state(0) >= LMS_IIC_STATE_ENABLE && iic_svc_state(1) >= LMS_IIC_STATE_ENABLE, "both probing");
	is_int(iic_svc_stop(0), E_OK, "stop port 1");
	dly_tsk(4);
	ok(iic_svc_state(0) == LMS_IIC_STATE_IDLE && iic_svc_state(1) != LMS_IIC_STATE_IDLE,
	   "port 1 idle, port 2 still running");
	is_int(iic_svc_stop(0), E_OK, "stopping an idle port is harmless");

	hs_sim_at(rtos_host_now() + IT_MS, from_irq, NULL);
	dly_tsk(2);
	is_int(irq_ercd, E_CTX, "non-task context is E_CTX");
}

int main(void)
{
	tap_plan(30);
	ok(it_run(body, 3), "scenario ran to its end");
	return tap_done();
}

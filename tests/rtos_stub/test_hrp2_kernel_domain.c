/*
 * test_hrp2_kernel_domain.c — the kernel domain's view of rtos_stub's
 * interface, as HRP2 gives it to code compiled with TOPPERS_SVC_CALL (its
 * kernel, system services and drivers; public source: ev3rt-git/ev3rt-hrp2,
 * include/svc_call.h, target/ev3_gcc/target_svc.h, syssvc/syslog.h): every
 * service call is the kernel's function _kernel_<call> under the plain name,
 * syslog_msk_log is the service's entry as the kernel domain, and cal_svc
 * stays the trap (a code <= 0 is E_RSFN).  A library object that called a
 * plain act_tsk would link against nothing in an HRP2 image.
 */
#define TOPPERS_SVC_CALL 1
#include <string.h>
#include "tap.h"
#include "kernel.h"
#include "syssvc/syslog.h"

#define EXPANDED(name) EXPANDED_(name)
#define EXPANDED_(name) #name

struct renamed {
	const char *call, *expansion;
};

#define CALL(name) { #name, EXPANDED(name) }

static const struct renamed calls[] = {
	CALL(act_tsk),
	CALL(iact_tsk),
	CALL(can_act),
	CALL(ext_tsk),
	CALL(chg_pri),
	CALL(get_pri),
	CALL(get_tid),
	CALL(iget_tid),
	CALL(slp_tsk),
	CALL(tslp_tsk),
	CALL(wup_tsk),
	CALL(iwup_tsk),
	CALL(can_wup),
	CALL(rel_wai),
	CALL(irel_wai),
	CALL(dly_tsk),
	CALL(sus_tsk),
	CALL(rsm_tsk),
	CALL(ter_tsk),
	CALL(sig_sem),
	CALL(isig_sem),
	CALL(wai_sem),
	CALL(pol_sem),
	CALL(twai_sem),
	CALL(set_flg),
	CALL(iset_flg),
	CALL(clr_flg),
	CALL(wai_flg),
	CALL(pol_flg),
	CALL(twai_flg),
	CALL(snd_dtq),
	CALL(psnd_dtq),
	CALL(ipsnd_dtq),
	CALL(tsnd_dtq),
	CALL(fsnd_dtq),
	CALL(ifsnd_dtq),
	CALL(rcv_dtq),
	CALL(prcv_dtq),
	CALL(trcv_dtq),
	CALL(ini_dtq),
	CALL(ref_dtq),
	CALL(snd_pdq),
	CALL(psnd_pdq),
	CALL(ipsnd_pdq),
	CALL(tsnd_pdq),
	CALL(rcv_pdq),
	CALL(prcv_pdq),
	CALL(trcv_pdq),
	CALL(ini_pdq),
	CALL(ref_pdq),
	CALL(loc_mtx),
	CALL(ploc_mtx),
	CALL(tloc_mtx),
	CALL(unl_mtx),
	CALL(ini_mtx),
	CALL(ref_mtx),
	CALL(get_tim),
	CALL(get_utm),
	CALL(sta_cyc),
	CALL(stp_cyc),
	CALL(sta_alm),
	CALL(ista_alm),
	CALL(stp_alm),
	CALL(istp_alm),
	CALL(rot_rdq),
	CALL(irot_rdq),
	CALL(loc_cpu),
	CALL(iloc_cpu),
	CALL(unl_cpu),
	CALL(iunl_cpu),
	CALL(dis_dsp),
	CALL(ena_dsp),
	CALL(sns_ctx),
	CALL(sns_loc),
	CALL(sns_dsp),
	CALL(sns_dpn),
	CALL(ext_ker),
	CALL(dis_int),
	CALL(ena_int),
	CALL(prb_mem),
};

int main(void)
{
	size_t n = sizeof(calls) / sizeof(calls[0]);
	size_t plain = 0;
	char want[64];

	tap_plan(4);
	for (size_t i = 0; i < n; i++) {
		(void)snprintf(want, sizeof(want), "_kernel_%s", calls[i].call);
		if (strcmp(calls[i].expansion, want) != 0) {
			tap_diag("%s is %s, not %s", calls[i].call, calls[i].expansion, want);
			plain++;
		}
	}
	is_int((int)plain, 0, "each of the %zu service calls is the kernel's _kernel_ function", n);
	ok(strcmp(EXPANDED(syslog_msk_log(1, 2)), "_syslog_msk_log(1, 2, (-1))") == 0,
	   "syslog_msk_log is the log service's entry for the kernel domain (%s)",
	   EXPANDED(syslog_msk_log(1, 2)));
	is_int(cal_svc(0, 0, 0, 0, 0, 0), E_RSFN, "cal_svc(0) is E_RSFN, as HRP2's trap wrapper");
	is_int(cal_svc(-5, 0, 0, 0, 0, 0), E_RSFN, "cal_svc of a kernel function code is E_RSFN");
	return tap_done();
}

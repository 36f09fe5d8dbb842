/*
 * test_hrp2_constants.c — rtos_stub's kernel interface against TOPPERS/HRP2's
 * own: every constant both define has HRP2's value (public source:
 * ev3rt-git/ev3rt-hrp2, include/kernel.h, include/t_stddef.h,
 * include/t_syslog.h), so code written against rtos_stub is code written
 * against the kernel on the brick — an access mode swapped (prb_mem's
 * TPM_READ checking writes) compiles everywhere and is wrong only there.
 * Also the signatures HRP2 gives that differ from the obvious: ext_tsk
 * returns an ER.
 */
#include "tap.h"
#include "kernel.h"

struct constant {
	const char *name;
	long long ours, hrp2;
};

#define HRP2(name, value) { #name, (long long)(name), (long long)(value) }

static const struct constant constants[] = {
	HRP2(E_BOVR, -58),
	HRP2(E_CLS, -52),
	HRP2(E_CTX, -25),
	HRP2(E_DLT, -51),
	HRP2(E_ID, -18),
	HRP2(E_ILUSE, -28),
	HRP2(E_MACV, -26),
	HRP2(E_NOEXS, -42),
	HRP2(E_NOID, -34),
	HRP2(E_NOMEM, -33),
	HRP2(E_NORES, -35),
	HRP2(E_NOSPT, -9),
	HRP2(E_OACV, -27),
	HRP2(E_OBJ, -41),
	HRP2(E_OK, 0),
	HRP2(E_PAR, -17),
	HRP2(E_QOVR, -43),
	HRP2(E_RLWAI, -49),
	HRP2(E_RSATR, -11),
	HRP2(E_RSFN, -10),
	HRP2(E_SYS, -5),
	HRP2(E_TMOUT, -50),
	HRP2(E_WBLK, -57),
	HRP2(LOG_ALERT, 1U),
	HRP2(LOG_CRIT, 2U),
	HRP2(LOG_DEBUG, 7U),
	HRP2(LOG_EMERG, 0U),
	HRP2(LOG_ERROR, 3U),
	HRP2(LOG_INFO, 6U),
	HRP2(LOG_NOTICE, 5U),
	HRP2(LOG_WARNING, 4U),
	HRP2(TA_ACT, 0x02U),
	HRP2(TA_CEILING, 0x03U),
	HRP2(TA_CLR, 0x04U),
	HRP2(TA_EDGE, 0x02U),
	HRP2(TA_ENAINT, 0x01U),
	HRP2(TA_NULL, 0U),
	HRP2(TA_STA, 0x02U),
	HRP2(TA_TPRI, 0x01U),
	HRP2(TA_WMUL, 0x02U),
	HRP2(TDOM_KERNEL, -1),
	HRP2(TDOM_NONE, -2),
	HRP2(TDOM_SELF, 0),
	HRP2(TIPM_ENAALL, 0),
	HRP2(TMAX_ACTCNT, 1U),
	HRP2(TMAX_DPRI, 16),
	HRP2(TMAX_ISRPRI, 16),
	HRP2(TMAX_TPRI, 16),
	HRP2(TMAX_WUPCNT, 1U),
	HRP2(TMIN_DPRI, 1),
	HRP2(TMIN_ISRPRI, 1),
	HRP2(TMIN_TPRI, 1),
	HRP2(TMO_FEVR, -1),
	HRP2(TMO_NBLK, -2),
	HRP2(TMO_POL, 0),
	HRP2(TPM_EXEC, 0x04U),
	HRP2(TPM_READ, 0x02U),
	HRP2(TPM_WRITE, 0x01U),
	HRP2(TPRI_INI, 0),
	HRP2(TPRI_SELF, 0),
	HRP2(TSK_NONE, 0),
	HRP2(TSK_SELF, 0),
	HRP2(TTS_DMT, 0x10U),
	HRP2(TTS_RDY, 0x02U),
	HRP2(TTS_RUN, 0x01U),
	HRP2(TTS_SUS, 0x08U),
	HRP2(TTS_WAI, 0x04U),
	HRP2(TTS_WAS, 0x0cU),
	HRP2(TWF_ANDW, 0x02U),
	HRP2(TWF_ORW, 0x01U),
};

int main(void)
{
	ER (*const ext_tsk_is_er)(void) = ext_tsk;

	tap_plan((int)(sizeof(constants) / sizeof(constants[0])) + 1);
	for (size_t i = 0; i < sizeof(constants) / sizeof(constants[0]); i++)
		ok(constants[i].ours == constants[i].hrp2, "%s is %lld, as in HRP2 (ours: %lld)",
		   constants[i].name, constants[i].hrp2, constants[i].ours);
	ok(ext_tsk_is_er != NULL, "ext_tsk returns ER, as HRP2 declares it");
	return tap_done();
}

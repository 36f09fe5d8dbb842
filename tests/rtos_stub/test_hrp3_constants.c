/*
 * test_hrp3_constants.c — the kernel interface an app built in the HRP3
 * profile sees (EV3LX_KERNEL_HRP3, as the build defines it) against
 * TOPPERS/HRP3's own (public source: ev3rt-git/ev3rt-hrp3, include/kernel.h,
 * include/t_stddef.h): every constant both define has HRP3's value, the
 * time types have HRP3's sizes and signedness, the i-names are HRP3's
 * macros, and EV3RT 1.x's ev3.h (target/ev3_gcc/ev3.h) gives its names.
 */
#define EV3LX_KERNEL_HRP3 1
#include "tap.h"
#include "kernel.h"
#include "t_stdlib.h"

struct constant {
	const char *name;
	long long ours, hrp3;
};

#define HRP3(name, value) { #name, (long long)(name), (long long)(value) }

static const struct constant constants[] = {
	HRP3(E_OK, 0), HRP3(E_SYS, -5), HRP3(E_NOSPT, -9), HRP3(E_RSFN, -10), HRP3(E_RSATR, -11),
	HRP3(E_PAR, -17), HRP3(E_ID, -18), HRP3(E_CTX, -25), HRP3(E_MACV, -26), HRP3(E_OACV, -27),
	HRP3(E_ILUSE, -28), HRP3(E_NOMEM, -33), HRP3(E_NOID, -34), HRP3(E_NORES, -35), HRP3(E_OBJ, -41),
	HRP3(E_NOEXS, -42), HRP3(E_QOVR, -43), HRP3(E_RLWAI, -49), HRP3(E_TMOUT, -50), HRP3(E_DLT, -51),
	HRP3(E_CLS, -52), HRP3(E_RASTER, -53), HRP3(E_WBLK, -57), HRP3(E_BOVR, -58), HRP3(E_COMM, -65),
	HRP3(TMO_POL, 0U), HRP3(TMO_FEVR, 0xffffffffU), HRP3(TMO_NBLK, 0xfffffffeU),
	HRP3(TMAX_RELTIM, 4000000000U),
	HRP3(TNFY_HANDLER, 0x00U), HRP3(TNFY_SETVAR, 0x01U), HRP3(TNFY_INCVAR, 0x02U), HRP3(TNFY_ACTTSK, 0x03U),
	HRP3(TNFY_WUPTSK, 0x04U), HRP3(TNFY_SIGSEM, 0x05U), HRP3(TNFY_SETFLG, 0x06U), HRP3(TNFY_SNDDTQ, 0x07U),
	HRP3(TENFY_SETVAR, 0x10U), HRP3(TENFY_INCVAR, 0x20U), HRP3(TENFY_ACTTSK, 0x30U), HRP3(TENFY_WUPTSK, 0x40U),
	HRP3(TENFY_SIGSEM, 0x50U), HRP3(TENFY_SETFLG, 0x60U), HRP3(TENFY_SNDDTQ, 0x70U),
	HRP3(TA_STA, 0x02U), HRP3(TA_ACT, 0x02U) /* HRP2's value: ev3lx's kernel is one */,
	HRP3(TCYC_STP, 0x01U), HRP3(TCYC_STA, 0x02U), HRP3(TALM_STP, 0x01U), HRP3(TALM_STA, 0x02U),
	HRP3(TKERNEL_MAKER, 0x0118U), HRP3(TKERNEL_PRID, 0x0006U), HRP3(TKERNEL_SPVER, 0xf633U),
	HRP3(TWF_ORW, 0x01U), HRP3(TWF_ANDW, 0x02U), HRP3(TMIN_TPRI, 1), HRP3(TMAX_TPRI, 16),
	HRP3(TMAX_ACTCNT, 1U), HRP3(TMAX_WUPCNT, 1U),
	/* EV3RT 1.x's ev3.h */
	HRP3(INTNO_I2C_TIMER, 24), HRP3(INTNO_UART_PORT1, 53), HRP3(INTNO_UART_PORT2, 25),
	HRP3(INTNO_UART_PORT3, 4), HRP3(INTNO_UART_PORT4, 3), HRP3(PERIOD_UART_SENSOR_CYC, 10000U),
	HRP3(TMAX_APP_CYC_NUM, 16), HRP3(APP_HEAP_SIZE, 1024 * 1024), HRP3(LCD_FRAME_RATE, 25),
};

int main(void)
{
	tap_plan((int)(sizeof(constants) / sizeof(constants[0])) + 9);
	for (size_t i = 0; i < sizeof(constants) / sizeof(constants[0]); i++)
		ok(constants[i].ours == constants[i].hrp3, "%s is %lld, as in HRP3 (ours: %lld)",
		   constants[i].name, constants[i].hrp3, constants[i].ours);
	is_int((int)sizeof(SYSTIM), 8, "SYSTIM is HRP3's uint64_t");
	ok(sizeof(TMO) == 4 && (TMO)-1 > 0, "TMO is HRP3's uint32_t");
	ok(sizeof(RELTIM) == 4 && (RELTIM)-1 > 0, "RELTIM is uint32_t");
	ok(sizeof(HRTCNT) == 4 && sizeof(PRCTIM) == 4, "HRTCNT and PRCTIM are uint32_t");
	ok(sizeof(T_NFYINFO) >= sizeof(MODE) + 2 * sizeof(intptr_t) && sizeof(T_CCYC) > sizeof(T_NFYINFO),
	   "T_NFYINFO and T_CCYC exist with HRP3's members");
	is_str(itron_strerror(E_RASTER), "E_RASTER", "itron_strerror names HRP3's E_RASTER");
	is_str(itron_strerror(E_COMM), "E_COMM", "and E_COMM");
#define STRING_OF(text) #text
#define NAME_OF(call) STRING_OF(call)
	is_str(NAME_OF(iact_tsk(1)), "act_tsk(1)", "HRP3's i-names are its calls: iact_tsk(x) is act_tsk(x)");
#ifdef STACK_SIZE
	ok(0, "STACK_SIZE is defined (%d), where EV3RT 1.x's ev3.h leaves it to the app", STACK_SIZE);
#else
	ok(1, "STACK_SIZE is the app's to define, as EV3RT 1.x's ev3.h leaves it");
#endif
	return tap_done();
}

/*
 * ev3.h — EV3RT's platform header for the EV3 target, which every app sees
 * through kernel.h (target_kernel.h) and some include by name: every name
 * it gives apps, in both EV3RT lines (public sources: ev3rt-git/ev3rt-hrp2
 * and ev3rt-git/ev3rt-hrp3, target/ev3_gcc/ev3.h).  As there, STACK_SIZE is
 * the one an app may define first (and in EV3RT 1.x's, the app's to
 * define); the rest are the platform's.  Where a
 * value describes EV3RT's own platform (its tasks' priorities) it is ev3lx's
 * platform's, in EV3RT's order; the hardware's (clocks, interrupt numbers)
 * are the AM1808's, as EV3RT gives them.
 */
#ifndef TOPPERS_EV3_H
#define TOPPERS_EV3_H

#include "t_stddef.h"

/* The AM1808's clocks (MHz) and the page-table ratio of EV3RT's MMU set-up. */
#define CORE_CLK_MHZ          (300)
#define OSCIN_MHZ             (24)
#define ARM_PAGE_TABLE_RATIO  (20)

/* The UART sensors' polling period, in us. */
#define PERIOD_UART_SENSOR_CYC (10000U)

/* The AM1808's interrupt numbers EV3RT's ev3.h names (AM1808 TRM, the
 * AINTC's system events; EV3RT's arch/arm_gcc/am1808/am1808.h), and the
 * PRU soft UARTs' lines of sensor ports 3 and 4. */
#define T64P1_TINT12  23
#define T64P1_TINT34  24
#define UART0_INT     25
#define UART1_INT     53
#define SUART1_INT    3
#define SUART2_INT    4
#define INTNO_UART_PORT1 (UART1_INT)
#define INTNO_UART_PORT2 (UART0_INT)
#define INTNO_UART_PORT3 (SUART2_INT)
#define INTNO_UART_PORT4 (SUART1_INT)
#ifdef EV3LX_KERNEL_HRP3
#define INTNO_I2C_TIMER  (T64P1_TINT34)   /* EV3RT 1.x */
#else
#define INTNO_I2C_TIMER  (T64P1_TINT12)   /* EV3RT 0.x */
#endif

/* Interrupt priorities of EV3RT's drivers. */
#define INTPRI_GPIO       (TMIN_INTPRI)
#define INTPRI_I2C_TIMER  (TMIN_INTPRI)
#define INTPRI_UART_PORT1 (TMIN_INTPRI)
#define INTPRI_UART_PORT2 (TMIN_INTPRI)
#define INTPRI_UART_PORT3 (TMIN_INTPRI)
#define INTPRI_UART_PORT4 (TMIN_INTPRI)
#define INTPRI_EDMA3      (TMIN_INTPRI + 1)
#define INTPRI_USBMSC     (TMIN_INTPRI + 2)
#define INTPRI_TIMER      (TMIN_INTPRI + 3)
#define INTPRI_BLUETOOTH  (TMIN_INTPRI + 4)
#define INTPRI_LCD_SPI    (TMIN_INTPRI + 4)

/* The highest priority an application task may use: the levels above belong
 * to the platform (linux_compat's workers at 4, the API's button and LCD
 * tasks at 5).  EV3RT's platform keeps TMIN_TPRI..TMIN_TPRI + 7 for its own
 * tasks; ev3lx needs five. */
#define TMIN_APP_TPRI 6

/* The platform's task priorities, in EV3RT's order above TMIN_APP_TPRI;
 * EV3_CRE_CYC's handler tasks run at TMIN_APP_TPRI (docs/ev3rt-apps.md). */
#define TPRI_INIT_TASK       (TMIN_TPRI)
#define TPRI_PLATFORM_TERM   (TMIN_TPRI)
#define TPRI_USBMSC          (TMIN_TPRI + 1)
#define TPRI_BLUETOOTH_QOS   (TMIN_TPRI + 1)
#define TPRI_BLUETOOTH_HIGH  (TMIN_TPRI + 2)
#define TPRI_APP_TERM_TASK   (TMIN_TPRI + 3)
#define TPRI_EV3_LCD_TASK    (TMIN_APP_TPRI - 1)
#define TPRI_EV3_MONITOR     (TMIN_APP_TPRI - 1)
#define TPRI_PLATFORM_BUSY   (TMIN_APP_TPRI - 1)
#define TPRI_APP_INIT_TASK   (TMIN_APP_TPRI - 1)
#define TPRI_EV3_CYC         (TMIN_APP_TPRI)
#define TPRI_BLUETOOTH_LOW   (TMAX_TPRI)

/* A task's stack size where the app does not give one: EV3RT 0.x's default.
 * EV3RT 1.x's ev3.h leaves it out (its apps define it, some without asking
 * whether it is defined: EV3RT 1.x's test-cyc sample), so the HRP3 profile
 * does too. */
#if !defined(STACK_SIZE) && !defined(EV3LX_KERNEL_HRP3)
#define STACK_SIZE 4096
#endif

/* Memory: the heaps of the kernel domain and of the apps' domain (ev3lx's
 * apps' heap, from which ev3_memfile_load allocates, is this size). */
#define KERNEL_HEAP_SIZE (1024 * 1024)
#define APP_HEAP_SIZE    (1024 * 1024)

/* Bluetooth: the send buffer, time slices (ms), EDMA mode. */
#define BT_SND_BUF_SIZE        (2048)
#define BT_HIGH_PRI_TIME_SLICE (1)
#define BT_LOW_PRI_TIME_SLICE  (19)
#define BT_USE_EDMA_MODE       (true)   /* C99 bool (stdbool.h), as on EV3RT */

/* What a loadable application module may hold (EV3RT's app loader). */
#define TMAX_APP_TSK_NUM     (32)
#define TMAX_APP_SEM_NUM     (16)
#define TMAX_APP_FLG_NUM     (16)
#define TMAX_APP_DTQ_NUM     (16)
#define TMAX_APP_PDQ_NUM     (16)
#define TMAX_APP_MTX_NUM     (16)
#define TMAX_APP_CYC_NUM     (16)
#define TMAX_APP_TEXT_SIZE   (1024 * 1024)
#define TMAX_APP_DATA_SIZE   (1024 * 1024)
#define TMAX_APP_BINARY_SIZE (1024 * 1024)

/* The LCD's refresh rate (Hz). */
#define LCD_FRAME_RATE (25)

/* BACK+LEFT+RIGHT held this long (ms) ends the app; at most TMAX_EV3_CYC_NUM
 * EV3_CRE_CYC in an app; the syslog buffer's entries. */
#define FORCE_SHUTDOWN_TIMEOUT (500)
#define TMAX_EV3_CYC_NUM       (16)
#define TCNT_SYSLOG_BUFFER     (1024)

#ifndef TOPPERS_MACRO_ONLY
#ifdef __cplusplus
extern "C" {
#endif

/* The serial port syslog and EV3_SERIAL_DEFAULT use (target_serial.h's
 * SIO_PORT_*): ev3lx's is the UART of sensor port 1, SIO_PORT_UART. */
extern int SIO_PORT_DEFAULT;

/* Logs a service call's error (ercd < 0) with its expression, file and line,
 * through t_perror at LOG_ERROR; nothing for E_OK or a positive result. */
void svc_perror(const char *file, int_t line, const char *expr, ER ercd);

/* The PRU soft UART driver's interrupt routine, EV3RT's: ev3lx's UART
 * sensors are LEGO's d_uart, so an app calling it fails to link, naming it. */
void pru_suart_isr(intptr_t portline) __asm__("ev3lx_not_yet_supported__platform__pru_suart_isr");

#ifdef __cplusplus
}
#endif

/* Calls expr and logs it if it fails (EV3RT's ev3.h). */
#define SVC_PERROR(expr) svc_perror(__FILE__, __LINE__, #expr, (expr))
#endif /* TOPPERS_MACRO_ONLY */

#endif /* TOPPERS_EV3_H */

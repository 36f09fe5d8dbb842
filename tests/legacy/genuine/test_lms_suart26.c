/*
 * test_lms_suart26.c — lms_suart26, a module as Linux 2.6.33's DaVinci
 * kernel built TI's PRU soft-UART drivers (a platform driver of the board's
 * ti_omapl_pru_suart device, request_firmware, clocks by name, a struct
 * uart_port whose ops it calls itself, plain pointers into the PRU's data
 * RAM, INTC, McASP and PSC), built with linux_compat alone and run at the
 * configuration's -O2 on the simulated EV3 with a colour sensor on input
 * port 4: it receives the sensor's 2400-baud handshake through the PRU's
 * double FIFO (full halves and time-outs), answers ACK through the soft
 * UART's transmitter, follows the sensor to 57600 baud and receives its
 * DATA messages, and gives back its firmware, clocks and IRQ at exit.
 */
#include <errno.h>
#include <string.h>
#include "legacy_test.h"
#include "sil.h"
#include "host_sim/devices/pru_suart.h"
#include "host_sim/devices/uart_sensor.h"

#include "lms_suart26_hack.h"

#define PORT4          3U
#define COLOR_TYPE     29U
/* LUMP (LEGO's d_uart: CMD_TYPE, SYS_ACK, SYS_NACK, DATA of mode 0 with one byte) */
#define LUMP_TYPE      0x40U
#define LUMP_ACK       0x04U
#define LUMP_NACK      0x02U
#define LUMP_DATA_M0_1 0xC0U
/* SYSCFG0 (AM1808 TRM, SYSCFG chapter): KICK0R/KICK1R unlock, PINMUXn 4 bits a pin */
#define SYSCFG0   0x01C14000U
#define KICK0R    0x38U
#define KICK1R    0x3CU
#define PINMUX(n) (0x120U + 4U * (n))

static unsigned char rx[4096];
static int nrx;

/* Takes what the module received into rx. */
static void drain(void)
{
	nrx += lms_suart26_read(rx + nrx, (int)sizeof(rx) - nrx);
}

/* True if rx holds the bytes of want (n of them) in a row. */
static bool received(const unsigned char *want, int n)
{
	for (int i = 0; i + n <= nrx; i++)
		if (!memcmp(rx + i, want, (size_t)n))
			return true;
	return false;
}

static struct uart_sensor *sensor(void)
{
	return ev3_input_uart_sensor(PORT4);
}

/* Waits (1 ms steps, at most ms) until the sensor is in state st, draining what arrives. */
static bool wait_state(enum uart_sensor_state st, unsigned ms)
{
	for (unsigned i = 0; i < ms && uart_sensor_get_state(sensor()) != st; i++) {
		dly_tsk(1);
		drain();
	}
	return uart_sensor_get_state(sensor()) == st;
}

static void body(void)
{
	static const unsigned char type_msg[] = { LUMP_TYPE, COLOR_TYPE, 0xFFU ^ LUMP_TYPE ^ COLOR_TYPE };
	const unsigned char ack = LUMP_ACK, nack = LUMP_NACK;
	int irqs, halves, timeouts, data_msgs = 0;
	unsigned frames0, sent;

	is_int(lms_suart26_board(1), 0, "the board registers its ti_omapl_pru_suart device and PRU_SUART.bin");
	is_int(lms_suart26_missing_firmware(), -ENOENT, "request_firmware of an unregistered name: -ENOENT");
	is_int(lms_suart26_load(), 0, "lms_suart26's init: probe, PRU up, port started at 2400 baud");
	is_int((int)lms_suart26_timeout(), 1000 * 10 * 16 / 2400 + 1000 / 50,
	       "uart_update_timeout: 16 characters of 10 bits at 2400 baud, plus 20 ms, in jiffies");

	ok(wait_state(UART_SENSOR_WAIT_ACK, 3000), "the sensor sent its handshake and waits for the host's ACK");
	for (int i = 0; i < 15; i++) {          /* the PRU's 10 ms receive time-out hands over the last part */
		dly_tsk(1);
		drain();
	}
	ok(received(type_msg, 3), "its TYPE message (0x40 0x1d 0xa2) came through the PRU's receive FIFO");
	lms_suart26_counts(&irqs, &halves, &timeouts);
	ok(halves > 0 && timeouts > 0, "by full halves (%d) and by time-outs for partial ones (%d), %d interrupts",
	   halves, timeouts, irqs);

	is_int(lms_suart26_write(&ack, 1), 1, "ACK queued for the soft UART's transmitter");
	for (int i = 0; i < 50 && !lms_suart26_tx_idle(); i++)
		dly_tsk(1);
	ok(lms_suart26_tx_idle(), "the transmitter went idle: the ACK is out");
	lms_suart26_set_baud(57600);
	ok(wait_state(UART_SENSOR_DATA, 100), "the sensor took the ACK and streams DATA at 57600 baud");
	is_int((int)uart_sensor_get_stats(sensor())->rx_garbled, 0, "no byte reached the sensor at a wrong speed");

	frames0 = uart_sensor_get_stats(sensor())->data_frames;
	nrx = 0;
	for (int i = 0; i < 10; i++) {
		lms_suart26_write(&nack, 1);
		for (int k = 0; k < 50; k++) {
			dly_tsk(1);
			drain();
		}
	}
	for (int i = 0; i < nrx; i++)
		if (rx[i] == LUMP_DATA_M0_1)
			data_msgs++;
	sent = uart_sensor_get_stats(sensor())->data_frames - frames0;
	ok(sent >= 5 && data_msgs + 2 >= (int)sent,
	   "kept alive by NACKs, its DATA messages arrive: %u sent in 0.5 s, %d headers received",
	   sent, data_msgs);

	lms_suart26_unload();
	is_int(lms_suart26_board(0), 0, "exit released the firmware: the board can take it back");
	is_int(lms_suart26_board(1), 0, "and register it again");
	is_int(lms_suart26_load(), 0, "a second init probes again (IRQ, clocks and regions were given back)");
	lms_suart26_unload();
	lms_suart26_board(0);
}

/* Sets PINMUXn[shift + 3 : shift] to mode, as a 2.6 board file's pin set-up does before the modules load. */
static void board_mux(unsigned n, unsigned shift, unsigned mode)
{
	uint32_t *kick0 = rtos_host_map_io(SYSCFG0 + KICK0R, 4), *kick1 = rtos_host_map_io(SYSCFG0 + KICK1R, 4);
	uint32_t *mux = rtos_host_map_io(SYSCFG0 + PINMUX(n), 4);

	sil_wrw_mem(kick0, 0x83E70B13U);
	sil_wrw_mem(kick1, 0x95A4F1E0U);
	sil_wrw_mem(mux, (sil_rew_mem(mux) & ~(0xFU << shift)) | mode << shift);
	sil_wrw_mem(kick0, 0);
	sil_wrw_mem(kick1, 0);
}

/* The board file's part: port 4's TX buffer pin GP7[10] muxed as a GPIO; the sensor plugged in. */
static void power_on(void)
{
	board_mux(16, 28, 8);
	ev3_attach_uart_sensor(PORT4, COLOR_TYPE, NULL);
}

int main(void)
{
	static const struct lt_test test = {
		.name = "lms_suart26", .power_on = power_on, .body = body, .after_boot = 16, .plain_pointers = true,
		.run_ms = 10000,
	};

	tap_plan(16);
	if (lt_run(&test))
		ok(lt_done, "the test body ran to its end");
	return tap_done();
}

/*
 * test_i2c_algo_bit.c — i2c-algo-bit's errors and timing over test lines
 * (a slave on the NXT bus answers in tests/linux_compat/porting/nxt_us):
 * SCL held low by a slave beyond the timeout, SDA held low under a 1 (lost
 * arbitration, after the core's retries), nobody answering, the clock's
 * half period from udelay, and the required callbacks.
 */
#define KBUILD_MODNAME "algobit"
#include "lx_log_test.h"
#include <linux/i2c-algo-bit.h>
#include <linux_compat/clock.h>
#include "host_sim/board.h"

static int sda_out = 1, scl_out = 1;
static bool sda_stuck_low, scl_stuck_low, slave_acks;
static unsigned int scl_rises;

static void t_setsda(void *data, int state)
{
	sda_out = state;
}

static void t_setscl(void *data, int state)
{
	if (state && !scl_out)
		scl_rises++;
	scl_out = state;
}

/* A slave that ACKs on every ninth clock when slave_acks, else only the lines' wired AND. */
static int t_getsda(void *data)
{
	if (sda_stuck_low)
		return 0;
	if (slave_acks && scl_out && scl_rises % 9 == 0)
		return 0;
	return sda_out;
}

static int t_getscl(void *data)
{
	return scl_stuck_low ? 0 : scl_out;
}

static struct i2c_algo_bit_data bit = {
	.setsda = t_setsda, .setscl = t_setscl, .getsda = t_getsda, .getscl = t_getscl,
	.udelay = 10, .timeout = 2,
};
static struct i2c_adapter adap = { .name = "test bit", .algo_data = &bit };

static void body(void)
{
	u8 buf[2] = { 0x10, 0x20 };
	struct i2c_msg msg = { .addr = 0x22, .len = 2, .buf = buf };
	struct i2c_adapter incomplete = { .name = "incomplete" };
	struct i2c_algo_bit_data no_getsda = { .setsda = t_setsda, .setscl = t_setscl };
	u64 t0;

	incomplete.algo_data = &no_getsda;
	is_int(i2c_bit_add_bus(&incomplete), -EINVAL, "without getsda: -EINVAL");
	is_int(i2c_bit_add_bus(&adap), 0, "i2c_bit_add_bus");
	ok(adap.algo == &i2c_bit_algo && adap.retries == 3, "the bit algorithm, 3 retries");
	ok(i2c_check_functionality(&adap, I2C_FUNC_I2C | I2C_FUNC_SMBUS_EMUL), "I2C and emulated SMBus");

	scl_rises = 0;
	slave_acks = true;
	t0 = lx_clock_now_ns();
	is_int(i2c_transfer(&adap, &msg, 1), 1, "address and two bytes, each ACKed");
	is_int((int)scl_rises, 27 + 1, "27 clocks and the STOP's");
	in_range((long long)(lx_clock_now_ns() - t0), 27 * 20000LL, 27 * 20000LL + 60000LL,
		 "each clock 2 x udelay (10 us) long");

	slave_acks = false;
	is_int(i2c_transfer(&adap, &msg, 1), -ENXIO, "nobody ACKs the address: -ENXIO");
	scl_stuck_low = true;
	t0 = lx_clock_now_ns();
	is_int(i2c_transfer(&adap, &msg, 1), -ETIMEDOUT, "SCL held low by a slave: -ETIMEDOUT");
	in_range((long long)(lx_clock_now_ns() - t0), 16000000LL, 16500000LL,
		 "the address tried retries + 1 times, each try and its STOP waiting the 2-jiffy timeout");
	scl_stuck_low = false;
	sda_stuck_low = true;
	is_int(i2c_transfer(&adap, &msg, 1), -EAGAIN, "SDA low under a 1: arbitration lost, -EAGAIN");
	sda_stuck_low = false;
	i2c_del_adapter(&adap);
}

int main(void)
{
	tap_plan(13);
	is_int(hs_board_init(NULL), E_OK, "host_sim board");
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}

/*
 * test_i2c.c — the DaVinci I2C adapter (da8xx_register_i2c) on host_sim's
 * I2C0 with a register-file slave at 0x50: SMBus and I2C-block reads and
 * writes through the controller's interrupts, a write-then-read as one
 * transaction with a repeated START, the SCL period the bus frequency
 * asks for, a NACKed address, a lost arbitration, the functionality Linux
 * gives it, and unregistering.
 */
#define KBUILD_MODNAME "davinci_i2c_test"
#include "lx_log_test.h"
#include <linux/i2c.h>
#include <linux/err.h>
#include <linux/platform_data/i2c-davinci.h>
#include <mach/da8xx.h>
#include <linux_compat/clock.h>
#include "host_sim/board.h"
#include "host_sim/devices/i2c.h"

static struct hs_i2c_regfile eeprom;

static void body(void)
{
	struct davinci_i2c_platform_data pdata = { .bus_freq = 100 };
	struct hs_i2c_stats st;
	struct i2c_adapter *adap;
	struct i2c_client *client, *nobody;
	u8 block[16], expect[16];
	u64 t0;
	int i;

	for (i = 0; i < 256; i++)
		eeprom.regs[i] = (u8)(i * 7);
	is_int(hs_i2c_attach(0, 0x50, &hs_i2c_regfile_ops, &eeprom), E_OK, "a register-file slave at 0x50 on I2C0");
	is_int(da8xx_register_i2c(0, &pdata), 0, "da8xx_register_i2c(0), 100 kHz");
	is_int(da8xx_register_i2c(0, &pdata), -EBUSY, "twice: -EBUSY");
	adap = i2c_get_adapter(1);
	ok(adap && !strcmp(adap->name, "DaVinci I2C adapter"), "bus i2c-1, as Linux numbers I2C0");
	if (!adap)
		return;
	i2c_put_adapter(adap);
	ok(i2c_check_functionality(adap, I2C_FUNC_I2C | I2C_FUNC_SMBUS_BYTE_DATA | I2C_FUNC_SMBUS_I2C_BLOCK) &&
	   !i2c_check_functionality(adap, I2C_FUNC_SMBUS_QUICK), "I2C and emulated SMBus but QUICK, as Linux's");
	client = i2c_new_dummy_device(adap, 0x50);
	ok(!IS_ERR(client), "a client at 0x50");
	if (IS_ERR(client))
		return;

	is_int(i2c_smbus_write_byte_data(client, 0x10, 0xab), 0, "write_byte_data");
	is_int(eeprom.regs[0x10], 0xab, "  the slave's register 0x10 written");
	t0 = lx_clock_now_ns();
	is_int(i2c_smbus_read_byte_data(client, 0x10), 0xab, "read_byte_data");
	st = hs_i2c_get_stats(0);
	ok(st.repeated_starts == 1 && st.starts == 2 && st.stops == 2,
	   "  the pointer write and the read as one transaction: a repeated START (%u starts, %u repeated, %u stops)",
	   st.starts, st.repeated_starts, st.stops);
	is_int((int)st.scl_period_ns, 10000, "  SCL period 10 us at 100 kHz");
	/* START + address, pointer, repeated START + address, data, STOP: 39 periods of 10 us */
	in_range((long long)(lx_clock_now_ns() - t0), 390000LL, 600000LL, "  about 39 SCL periods long");

	is_int(i2c_smbus_read_i2c_block_data(client, 0x20, 16, block), 16, "read_i2c_block_data of 16 bytes");
	for (i = 0; i < 16; i++)
		expect[i] = (u8)((0x20 + i) * 7);
	ok(!memcmp(block, expect, 16), "  registers 0x20..0x2f");
	is_int(i2c_smbus_write_i2c_block_data(client, 0x80, 4, (const u8 *)"\x01\x02\x03\x04"), 0,
	       "write_i2c_block_data of 4 bytes");
	ok(!memcmp(eeprom.regs + 0x80, "\x01\x02\x03\x04", 4), "  stored from 0x80");
	is_int(i2c_master_recv(client, (char *)block, 3), 3, "i2c_master_recv: 3 bytes from the pointer");
	ok(block[0] == eeprom.regs[0x84] && block[2] == eeprom.regs[0x86], "  where the last write left it");

	nobody = i2c_new_dummy_device(adap, 0x51);
	is_int(i2c_smbus_read_byte_data(nobody, 0), -EREMOTEIO, "nobody at 0x51: NACK, -EREMOTEIO (i2c-davinci's code)");
	st = hs_i2c_get_stats(0);
	is_int((int)st.address_nacks, 1, "  the controller saw the address NACKed");
	is_int(i2c_smbus_read_byte_data(client, 0x10), 0xab, "the bus free again afterwards");
	i2c_unregister_device(nobody);

	hs_i2c_lose_arbitration(0, 1);
	is_int(i2c_smbus_read_byte_data(client, 0x10), -EAGAIN, "arbitration lost: -EAGAIN");
	is_int(i2c_smbus_read_byte_data(client, 0x10), 0xab, "the next transfer goes through");
	is_int(i2c_smbus_xfer(adap, 0x50, 0, I2C_SMBUS_WRITE, 0, I2C_SMBUS_QUICK, NULL), -EOPNOTSUPP,
	       "a zero-length message (SMBus quick): -EOPNOTSUPP");

	i2c_unregister_device(client);
	da8xx_unregister_i2c(0);
	ok(!i2c_get_adapter(1), "da8xx_unregister_i2c removes i2c-1");

	pdata.bus_freq = 400;
	is_int(da8xx_register_i2c(0, &pdata), 0, "again at 400 kHz");
	client = i2c_new_dummy_device(i2c_get_adapter(1), 0x50);
	i2c_put_adapter(client->adapter);
	is_int(i2c_smbus_read_byte_data(client, 0x80), 0x01, "read_byte_data");
	is_int((int)hs_i2c_get_stats(0).scl_period_ns, 2500, "  SCL period 2.5 us");
	i2c_unregister_device(client);
	da8xx_unregister_i2c(0);
}

int main(void)
{
	static const struct hs_device *const devices[] = { &hs_i2c0_device, NULL };
	static const struct hs_board_cfg board = { .devices = devices };

	tap_plan(30);
	is_int(hs_board_init(&board), E_OK, "host_sim board with I2C0");
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}

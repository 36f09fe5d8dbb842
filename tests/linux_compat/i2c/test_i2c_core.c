/*
 * test_i2c_core.c — the I2C core (linux/i2c.h) over a test algorithm that
 * records each transaction and answers from a register file: adapter
 * numbering and the board's static clients, client drivers matched by
 * compatible and by id_table (the one-argument probe, match data),
 * address checks, devres on unbind, each SMBus call as the I2C messages
 * Linux emulates it with, errors passed through, retries after a lost
 * arbitration, and i2c_transfer's context rule from an hrtimer callback.
 */
#define KBUILD_MODNAME "i2ctest"
#include "lx_log_test.h"
#include <linux/i2c.h>
#include <linux/i2c-algo-bit.h>
#include <linux/err.h>
#include <linux/delay.h>
#include <linux/hrtimer.h>
#include <linux/slab.h>
#include <linux/string.h>
#include "host_sim/board.h"

/* ---- the test algorithm ---- */

static u8 regs[256];            /* the slave at 0x50's register file */
static u8 pointer;
static struct i2c_msg seen[4];  /* the last transaction's messages */
static u8 seen_data[4][40];
static int seen_num, xfer_calls, fail_with, fail_times, short_by;

static int test_xfer(struct i2c_adapter *adap, struct i2c_msg *msgs, int num)
{
	int i, j;

	xfer_calls++;
	if (fail_times > 0) {
		fail_times--;
		return fail_with;
	}
	seen_num = num;
	for (i = 0; i < num && i < 4; i++) {
		struct i2c_msg *m = &msgs[i];

		seen[i] = *m;
		if (m->addr != 0x50)
			return -ENXIO;
		if (m->flags & I2C_M_RD) {
			int len = m->len;

			if (m->flags & I2C_M_RECV_LEN) {
				m->buf[0] = 3;        /* a 3-byte SMBus block */
				for (j = 1; j <= 3; j++)
					m->buf[j] = regs[pointer++];
				m->len = 4;
				len = 0;
			}
			for (j = 0; j < len; j++)
				m->buf[j] = regs[pointer++];
		} else {
			for (j = 0; j < m->len; j++) {
				if (j == 0)
					pointer = m->buf[0];
				else
					regs[pointer++] = m->buf[j];
			}
		}
		memcpy(seen_data[i], m->buf, min_t(size_t, m->len, sizeof(seen_data[i])));
	}
	return num - short_by;
}

static int atomic_calls;

static int test_xfer_atomic(struct i2c_adapter *adap, struct i2c_msg *msgs, int num)
{
	atomic_calls++;
	return test_xfer(adap, msgs, num);
}

static u32 test_func(struct i2c_adapter *adap)
{
	return I2C_FUNC_I2C | I2C_FUNC_SMBUS_EMUL_ALL;
}

static const struct i2c_algorithm test_algo = { .master_xfer = test_xfer, .functionality = test_func };
static const struct i2c_algorithm test_algo_atomic = {
	.master_xfer = test_xfer, .master_xfer_atomic = test_xfer_atomic, .functionality = test_func,
};
static const struct i2c_algorithm no_xfer_algo = { .functionality = test_func };

/* ---- a client driver ---- */

static int probes, removes, released;
static const void *probe_match;
static struct i2c_client *probed, *board_client;
static int probe_result;

static void count_release(void *data)
{
	released++;
}

static int test_probe(struct i2c_client *client)
{
	probes++;
	probed = client;
	probe_match = i2c_get_match_data(client);
	if (!devm_kzalloc(&client->dev, 16, GFP_KERNEL))
		return -ENOMEM;
	if (devm_add_action_or_reset(&client->dev, count_release, NULL))
		return -ENOMEM;
	return probe_result;
}

static void test_remove(struct i2c_client *client)
{
	removes++;
}

static const int of_data = 7;
static const struct of_device_id test_of_match[] = {
	{ .compatible = "acme,eeprom", .data = &of_data },
	{ }
};
static const struct i2c_device_id test_ids[] = {
	{ "eeprom", 3 },
	{ }
};
static struct i2c_driver test_driver = {
	.driver = { .name = "i2ctest", .of_match_table = test_of_match },
	.probe = test_probe,
	.remove = test_remove,
	.id_table = test_ids,
};

static struct i2c_adapter adap_a = { .name = "test a", .algo = &test_algo };
static struct i2c_adapter adap_b = { .name = "test b", .algo = &test_algo_atomic, .nr = 2 };
static struct i2c_adapter adap_c = { .name = "no master_xfer", .algo = &no_xfer_algo };

static const char *const eeprom_compat[] = { "acme,eeprom", NULL };
static struct device_node eeprom_node = { .name = "eeprom", .compatible = eeprom_compat };

/* ---- the context rule ---- */

static struct hrtimer timer;
static int timer_result;
static struct i2c_adapter *timer_adap;

static enum hrtimer_restart transfer_in_timer(struct hrtimer *t)
{
	u8 b = 0;
	struct i2c_msg msg = { .addr = 0x50, .flags = I2C_M_RD, .len = 1, .buf = &b };

	timer_result = i2c_transfer(timer_adap, &msg, 1);
	return HRTIMER_NORESTART;
}

/* Runs an I2C transfer on adap from an hrtimer callback: its result. */
static int transfer_from_timer(struct i2c_adapter *adap)
{
	timer_adap = adap;
	timer_result = 1000;
	hrtimer_setup(&timer, transfer_in_timer, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	hrtimer_start(&timer, ms_to_ktime(1), HRTIMER_MODE_REL);
	msleep(5);
	return timer_result;
}

static void test_adapters_and_clients(void)
{
	static const struct i2c_board_info board[] = {
		{ I2C_BOARD_INFO("eeprom", 0x50) },
		{ I2C_BOARD_INFO("other", 0x51) },
	};
	struct i2c_adapter nameless = { .algo = &test_algo };
	struct i2c_adapter algoless = { .name = "x" };
	struct i2c_client *c, *dup;

	is_int(i2c_add_adapter(&nameless), -EINVAL, "an adapter without a name: -EINVAL");
	is_int(i2c_add_adapter(&algoless), -EINVAL, "without an algorithm: -EINVAL");
	is_int(i2c_register_board_info(2, board, 2), 0, "the board's clients of bus 2");
	is_int(i2c_add_adapter(&adap_a), 0, "i2c_add_adapter");
	ok(adap_a.nr == 3 && !strcmp(dev_name(&adap_a.dev), "i2c-3"),
	   "numbered after the board's buses: i2c-3 (%d)", adap_a.nr);
	is_int(i2c_add_driver(&test_driver), 0, "i2c_add_driver");
	is_int(i2c_add_numbered_adapter(&adap_b), 0, "i2c_add_numbered_adapter(2)");
	ok(probes == 1 && probed && !strcmp(dev_name(&probed->dev), "2-0050") && probed->adapter == &adap_b,
	   "the board's eeprom created as 2-0050 and bound by id_table (the other one left unbound)");
	ok(probe_match == (const void *)3UL && i2c_client_get_device_id(probed) == &test_ids[0],
	   "match data from the id_table entry");
	board_client = probed;
	is_int(i2c_add_numbered_adapter(&(struct i2c_adapter){ .name = "dup", .algo = &test_algo, .nr = 2 }),
	       -EBUSY, "bus 2 again: -EBUSY");

	c = i2c_new_client_device(&adap_a, &(struct i2c_board_info){ I2C_BOARD_INFO("x", 0x50),
								      .of_node = &eeprom_node });
	ok(!IS_ERR(c) && probed == c && probe_match == &of_data, "a client matched by compatible: the node's data");
	dup = i2c_new_client_device(&adap_a, &(struct i2c_board_info){ I2C_BOARD_INFO("eeprom", 0x50) });
	is_int((int)PTR_ERR(dup), -EBUSY, "the same address twice: -EBUSY");
	is_int((int)PTR_ERR(i2c_new_client_device(&adap_a, &(struct i2c_board_info){ I2C_BOARD_INFO("eeprom", 0x80) })),
	       -EINVAL, "a 7-bit address above 0x7f: -EINVAL");
	dup = i2c_new_client_device(&adap_a, &(struct i2c_board_info){ I2C_BOARD_INFO("eeprom", 0x150),
									.flags = I2C_CLIENT_TEN });
	ok(!IS_ERR(dup) && !strcmp(dev_name(&dup->dev), "3-a150"), "a 10-bit client is 3-a150");
	i2c_unregister_device(dup);
	released = 0;
	removes = 0;
	i2c_unregister_device(c);
	ok(removes == 1 && released == 1, "unregistering a client runs remove, then its devres (%d, %d)",
	   removes, released);

	probe_result = -EIO;
	released = 0;
	c = i2c_new_client_device(&adap_a, &(struct i2c_board_info){ I2C_BOARD_INFO("eeprom", 0x52) });
	ok(!IS_ERR(c) && !c->dev.driver && released == 1, "a failing probe leaves the client unbound, devres released");
	probe_result = 0;
	i2c_unregister_device(c);
}

static void test_smbus(void)
{
	struct i2c_client *client = board_client;
	u8 block[8] = { 0 };

	memcpy(regs + 0x10, "\x11\x22\x33\x44\x55\x66", 6);
	is_int(i2c_smbus_read_byte_data(client, 0x10), 0x11, "read_byte_data");
	ok(seen_num == 2 && seen[0].len == 1 && !(seen[0].flags & I2C_M_RD) && seen_data[0][0] == 0x10 &&
	   seen[1].len == 1 && (seen[1].flags & I2C_M_RD), "  as a write of the command, then a 1-byte read");
	is_int(i2c_smbus_write_byte_data(client, 0x20, 0xab), 0, "write_byte_data");
	ok(seen_num == 1 && seen[0].len == 2 && seen_data[0][1] == 0xab && regs[0x20] == 0xab, "  as one 2-byte write");
	is_int(i2c_smbus_read_word_data(client, 0x10), 0x2211, "read_word_data: the low byte first");
	is_int(i2c_smbus_read_word_swapped(client, 0x10), 0x1122, "read_word_swapped");
	is_int(i2c_smbus_write_word_data(client, 0x30, 0xbeef), 0, "write_word_data");
	ok(regs[0x30] == 0xef && regs[0x31] == 0xbe && seen[0].len == 3, "  low byte first, one 3-byte write");
	is_int(i2c_smbus_read_i2c_block_data(client, 0x12, 4, block), 4, "read_i2c_block_data: 4 bytes");
	ok(!memcmp(block, "\x33\x44\x55\x66", 4) && seen[1].len == 4, "  the registers from 0x12");
	is_int(i2c_smbus_write_i2c_block_data(client, 0x40, 3, (const u8 *)"abc"), 0, "write_i2c_block_data");
	ok(!memcmp(regs + 0x40, "abc", 3) && seen[0].len == 4, "  one write: command and 3 bytes");
	is_int(i2c_smbus_read_block_data(client, 0x10, block), 3, "read_block_data: the count the slave sends");
	ok((seen[1].flags & I2C_M_RECV_LEN) && !memcmp(block, "\x11\x22\x33", 3), "  with I2C_M_RECV_LEN");
	pointer = 0x13;
	is_int(i2c_smbus_read_byte(client), 0x44, "read_byte: one read, no command");
	ok(seen_num == 1 && (seen[0].flags & I2C_M_RD), "  one message");
	is_int(i2c_smbus_write_byte(client, 0x10), 0, "write_byte");
	regs[0x52] = 0x34;
	regs[0x53] = 0x12;
	is_int(i2c_smbus_process_call(client, 0x50, 0x0102), 0x1234, "process_call: the word read after the write");
	ok(regs[0x50] == 0x02 && regs[0x51] == 0x01 && seen_num == 2, "  the word written low byte first, then read");
	is_int(i2c_master_send(client, "\x60\x01\x02", 3), 3, "i2c_master_send: the count");
	is_int(i2c_master_recv(client, (char *)block, 2), 2, "i2c_master_recv: the count");
	is_int(i2c_smbus_read_i2c_block_data_or_emulated(client, 0x10, 5, block), 5, "read_i2c_block_data_or_emulated");

	fail_with = -ENXIO;
	fail_times = 1;
	is_int(i2c_smbus_read_byte_data(client, 0), -ENXIO, "a NACKed address: -ENXIO passed through");
	fail_with = -EREMOTEIO;
	fail_times = 1;
	is_int(i2c_smbus_write_byte_data(client, 0, 0), -EREMOTEIO, "a NACKed byte: -EREMOTEIO");
	fail_with = -ETIMEDOUT;
	fail_times = 1;
	is_int(i2c_smbus_read_word_data(client, 0), -ETIMEDOUT, "a timeout: -ETIMEDOUT");
	client->adapter->retries = 2;
	fail_with = -EAGAIN;
	fail_times = 2;
	xfer_calls = 0;
	is_int(i2c_smbus_read_byte_data(client, 0x10), 0x11, "two lost arbitrations, then through");
	is_int(xfer_calls, 3, "  three attempts (retries 2)");
	fail_times = 10;
	xfer_calls = 0;
	is_int(i2c_smbus_read_byte_data(client, 0x10), -EAGAIN, "lost every time: -EAGAIN");
	is_int(xfer_calls, 3, "  after retries + 1 attempts");
	fail_times = 0;
	short_by = 1;
	is_int(i2c_smbus_read_byte_data(client, 0x10), -EIO, "fewer messages done than asked: -EIO");
	short_by = 0;
	{
		int result = 0, bugs = (int)DC_EXPECT_BUG(result = i2c_transfer(&adap_a, NULL, 0));

		ok(result == -EINVAL && bugs == 1, "no messages: -EINVAL, warned as Linux's WARN_ON");
	}
}

static void test_context_and_teardown(void)
{
	int result = 0, bugs;

	is_int(i2c_add_adapter(&adap_c), 0, "an adapter without master_xfer");
	is_int(i2c_transfer(&adap_c, &(struct i2c_msg){ .addr = 0x50, .len = 0, .buf = regs }, 1), -EOPNOTSUPP,
	       "i2c_transfer: -EOPNOTSUPP");
	i2c_del_adapter(&adap_c);

	bugs = (int)DC_EXPECT_BUG(result = transfer_from_timer(&adap_a));
	is_int(result, -EAGAIN, "from an hrtimer callback without an atomic handler: -EAGAIN");
	is_int(bugs, 1, "and the sleep in atomic context reported");
	ok(strstr(dc_bug, "i2c_transfer()") != NULL, "naming i2c_transfer() (%s)", dc_bug);
	atomic_calls = 0;
	bugs = (int)DC_EXPECT_BUG(result = transfer_from_timer(&adap_b));
	is_int(result, 1, "with master_xfer_atomic: done through it");
	is_int(bugs, 1, "reported all the same");
	is_int(atomic_calls, 1, "master_xfer_atomic ran once");

	removes = 0;
	i2c_del_adapter(&adap_b);
	ok(removes == 1 && !i2c_get_adapter(2), "i2c_del_adapter unbinds its clients and frees bus 2");
	is_int(i2c_add_numbered_adapter(&adap_b), 0, "the adapter added again");
	ok(probed && probed->adapter == &adap_b && probed->dev.driver, "with the board's client bound again");
	removes = 0;
	i2c_del_driver(&test_driver);
	ok(removes == 1 && probed->dev.driver == NULL, "i2c_del_driver unbinds it");
	i2c_del_adapter(&adap_b);
	i2c_del_adapter(&adap_a);
}

/* ---- detection: a driver that finds its chip by probing addresses ---- */

static int detect_calls, detected_probes, detected_removes;
static unsigned short detect_addrs[4];

static int det_detect(struct i2c_client *client, struct i2c_board_info *info)
{
	detect_addrs[detect_calls++ & 3] = client->addr;
	if (client->addr != 0x50)
		return -ENODEV;
	strscpy(info->type, "det-chip", sizeof(info->type));
	return 0;
}

static int det_probe(struct i2c_client *client)
{
	detected_probes++;
	return 0;
}

static void det_remove(struct i2c_client *client)
{
	detected_removes++;
}

static const unsigned short det_addresses[] = { 0x4f, 0x50, I2C_CLIENT_END };
static const struct i2c_device_id det_ids[] = { { "det-chip", 0 }, { } };
static struct i2c_driver det_driver = {
	.class = I2C_CLASS_HWMON, .driver = { .name = "det" }, .probe = det_probe, .remove = det_remove,
	.id_table = det_ids, .detect = det_detect, .address_list = det_addresses,
};
static struct i2c_adapter adap_hwmon = { .name = "hwmon bus", .algo = &test_algo, .class = I2C_CLASS_HWMON };
static struct i2c_adapter adap_plain = { .name = "no class", .algo = &test_algo };

static void test_detection(void)
{
	is_int(i2c_add_driver(&det_driver), 0, "a driver with detect and an address list");
	is_int(i2c_add_adapter(&adap_plain), 0, "an adapter of no class");
	is_int(detect_calls, 0, "is not scanned");
	is_int(i2c_add_adapter(&adap_hwmon), 0, "an adapter of the driver's class");
	ok(detect_calls == 1 && detect_addrs[0] == 0x50,
	   "is scanned: detect is offered only the address that answers the probe (0x%02x)", detect_addrs[0]);
	ok(detected_probes == 1 && list_is_singular(&det_driver.clients), "the detected chip's client is created and bound");
	i2c_del_driver(&det_driver);
	ok(detected_removes == 1 && list_empty(&det_driver.clients), "removing the driver removes the detected client");
	is_int(i2c_add_driver(&det_driver), 0, "the driver registered again");
	ok(detected_probes == 2, "detects the chip on the adapter already there");
	i2c_del_adapter(&adap_hwmon);
	ok(detected_removes == 2 && list_empty(&det_driver.clients), "removing the adapter removes the detected client");
	i2c_del_driver(&det_driver);
	i2c_del_adapter(&adap_plain);
}

static void body(void)
{
	test_adapters_and_clients();
	test_smbus();
	test_context_and_teardown();
	test_detection();
}

int main(void)
{
	tap_plan(71);
	is_int(hs_board_init(NULL), E_OK, "host_sim board");
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}

/*
 * test_nxt_us.c — an upstream-style I2C client driver taken unchanged:
 * nxt_us.c (module_i2c_driver, of_match_table and id_table, probe_new,
 * devm_kzalloc, SMBus byte and I2C-block reads, a misc device torn down
 * through devm_add_action_or_reset) is included verbatim, as a hack file
 * does; the hack's init gives the board's part first — the sensor's board
 * info for input port 1's bus and the bit-banged bus itself
 * (mach/legoev3-i2c.h) — then runs the driver's init.  host_sim's NXT
 * ultrasonic sensor answers on the port's pins; the distance, a single
 * shot, a sensor of another make, an empty port and unbinding are checked
 * through the driver's file operations and the sensor's registers.
 */
#define KBUILD_MODNAME "nxt_us"
#define LX_HACK_DRIVER_INIT us_driver_init
#define LX_HACK_DRIVER_EXIT us_driver_exit
#include "nxt_us.c"

#include "driver_common.h"

#include "lx_log_test.h"
#include <linux/err.h>
#include <linux/of.h>
#include <mach/legoev3-i2c.h>
#include <linux_compat/devfs.h>
#include "host_sim/board.h"
#include "host_sim/gpio.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/ev3_ports.h"
#include "host_sim/devices/nxt_iic.h"

static const char *const us_compat[] = { "lego,nxt-ultrasonic", NULL };
static struct device_node us_node = { .name = "ultrasonic", .full_name = "/in1/ultrasonic@1",
				      .compatible = us_compat };
static const struct i2c_board_info board_us = {
	I2C_BOARD_INFO("nxt-us", NXT_IIC_US_ADDRESS), .of_node = &us_node,
};

/* The board file's part (the sensor on port 1, the port's bus), then the driver. */
static int __init hack_init(void)
{
	int ret = i2c_register_board_info(LEGOEV3_IN_PORT_I2C_BUS(0), &board_us, 1);

	if (!ret)
		ret = legoev3_in_port_i2c_add(0);
	return ret ? ret : us_driver_init();
}
module_init(hack_init);

static void __exit hack_exit(void)
{
	us_driver_exit();
	legoev3_in_port_i2c_del(0);
}
module_exit(hack_exit);

/* Reads /dev/<name> as text: the number, or -1. */
static int read_cm(const char *name)
{
	struct file *f;
	char text[8] = { 0 };
	ssize_t n;

	if (lx_dev_open(name, O_RDONLY, &f))
		return -1;
	n = lx_dev_read(f, text, sizeof(text) - 1, NULL);
	lx_dev_close(f);
	return n > 0 ? (int)simple_strtol(text, NULL, 10) : (int)n;
}

/* The client behind /dev/<name> (through the driver's own state), or NULL. */
static struct i2c_client *bound_client(const char *name)
{
	struct i2c_client *client;
	struct file *f;

	if (lx_dev_open(name, O_RDONLY, &f))
		return NULL;
	client = file_to_us(f)->client;
	lx_dev_close(f);
	return client;
}

static void body(void)
{
	struct i2c_adapter *adap = legoev3_in_port_i2c_adapter(0);
	struct nxt_us_echoes echoes;
	struct nxt_iic_stats stats;
	struct i2c_client *client, *other;
	struct file *f;
	int i, zeros = 0;

	ok(adap && adap->nr == 3, "input port 1 is bus i2c-3");
	ok(lx_dev_exists("nxt_us3"), "/dev/nxt_us3 registered");
	client = bound_client("nxt_us3");
	ok(client && client->dev.driver == &nxt_us_driver.driver && !strcmp(dev_name(&client->dev), "3-0001"),
	   "by the board's sensor, 3-0001, bound at module init (by compatible)");
	is_int(read_cm("nxt_us3"), 42, "read: the distance the scene sets, 42 cm");
	ev3_set_nxt_iic_scene(0, &(struct nxt_iic_scene){ .distance_cm = 173 });
	is_int(read_cm("nxt_us3"), 173, "then 173 cm");

	if (lx_dev_open("nxt_us3", O_RDONLY, &f) == 0) {
		is_int((int)lx_dev_ioctl_kernel(f, NXT_US_SINGLE_SHOT, &echoes), 0,
		       "NXT_US_SINGLE_SHOT");
		for (i = 1; i < 8; i++)
			zeros += echoes.cm[i] == 0;
		ok(echoes.cm[0] == 173 && zeros == 7, "one echo at 173 cm, the other seven 0 (%u, %d)",
		   echoes.cm[0], zeros);
		is_int(ev3_nxt_iic_register(0, 0x41), 1, "the sensor's command register says single shot");
		is_int((int)lx_dev_ioctl_kernel(f, NXT_US_CONTINUOUS, NULL), 0, "NXT_US_CONTINUOUS");
		is_int(ev3_nxt_iic_register(0, 0x41), 2, "and continuous again");
		lx_dev_close(f);
	} else {
		ok(0, "open /dev/nxt_us3");
	}
	is_int(ev3_nxt_iic_stats(0, &stats), E_OK, "the slave's counters");
	ok(stats.contention == 0 && stats.aborted_bytes == 0 && stats.write_nacks == 0 &&
	   stats.repeated_starts > 0 && stats.starts == stats.stops + stats.repeated_starts,
	   "the bus as the slave saw it: repeated STARTs, every START stopped, no contention "
	   "(%u starts, %u repeated, %u stops)", stats.starts, stats.repeated_starts, stats.stops);

	/* a HiTechnic sensor where the board said ultrasonic: identified, refused */
	is_int(legoev3_in_port_i2c_add(1), 0, "input port 2's bus");
	dc_log_start();
	other = i2c_new_client_device(legoev3_in_port_i2c_adapter(1),
				      &(struct i2c_board_info){ I2C_BOARD_INFO("nxt-ultrasonic", 0x01) });
	ok(!IS_ERR(other) && !other->dev.driver, "an empty port: the client exists, unbound");
	ok(dc_logged("error -11: no NXT ultrasonic sensor"),
	   "pin 6's pull-down holds SDA low: the address's first 1 reads back 0, -EAGAIN (lost arbitration)");
	i2c_unregister_device(other);
	is_int(ev3_attach_nxt_iic(1, NXT_IIC_HT_ACCEL, NULL), E_OK, "a HiTechnic accelerometer on port 2");
	dc_log_start();
	other = i2c_new_client_device(legoev3_in_port_i2c_adapter(1),
				      &(struct i2c_board_info){ I2C_BOARD_INFO("nxt-ultrasonic", 0x02) });
	ok(!IS_ERR(other) && !other->dev.driver && dc_logged("error -6: no NXT ultrasonic sensor"),
	   "at an address nobody answers: NACK, -ENXIO");
	i2c_unregister_device(other);
	dc_log_start();
	other = i2c_new_client_device(legoev3_in_port_i2c_adapter(1),
				      &(struct i2c_board_info){ I2C_BOARD_INFO("nxt-ultrasonic", 0x01) });
	ok(!IS_ERR(other) && !other->dev.driver && dc_logged("is 'HITECHNC', not 'LEGO'"),
	   "matched by id_table, identified and refused: -ENODEV");
	ok(!lx_dev_exists("nxt_us4"), "no /dev/nxt_us4");
	legoev3_in_port_i2c_del(1);

	i2c_unregister_device(client);
	ok(!lx_dev_exists("nxt_us3"), "unbinding removed /dev/nxt_us3");
	is_int(ev3_nxt_iic_register(0, 0x41), 0, "and the remove switched the sensor off");
}

int main(void)
{
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	unsigned int i;

	tap_plan(24);
	is_int(hs_board_init(&board), E_OK, "host_sim EV3 board");
	for (i = 2; i < 4; i++)
		hs_gpio_mux_as_gpio(ev3_input_pins[i].pin6);   /* as the boot loader leaves them */
	ok(ev3_attach_nxt_iic(0, NXT_IIC_US, &(struct nxt_iic_scene){ .distance_cm = 42 }) == E_OK,
	   "NXT ultrasonic sensor on input port 1");
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}

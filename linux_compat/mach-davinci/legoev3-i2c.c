/*
 * legoev3-i2c.c — the EV3 input ports' bit-banged I2C buses
 * (mach/legoev3-i2c.h states the contract): i2c-algo-bit's callbacks on
 * the ports' GPIOs, SDA open-drain by switching the pin's direction.
 */
#include <mach/legoev3-i2c.h>
#include <mach/da8xx.h>
#include <linux/gpio.h>
#include <linux/i2c-algo-bit.h>
#include <linux/io.h>
#include <linux/kernel.h>
#include <linux/string.h>
#include <linux_compat/irq.h>

/* SYSCFG0 KICK0R/KICK1R unlock values (AM1808 TRM, SYSCFG chapter). */
#define KICK0_KEY	0x83e70b13U
#define KICK1_KEY	0x95a4f1e0U

struct in_port_lines {
	unsigned int buffer;    /* TX buffer enable, low = on */
	unsigned int scl;
	unsigned int sda;
	int mux_reg;            /* PINMUX register of the SCL pad, -1: none */
	unsigned int mux_shift;
	u32 mux_gpio;
	const char *name;
};

static const struct in_port_lines port_lines[LEGOEV3_NUM_IN_PORTS] = {
	{ GPIO_TO_PIN(8, 11), GPIO_TO_PIN(1, 0), GPIO_TO_PIN(0, 15), 4, 28, 8, "in1" },
	{ GPIO_TO_PIN(8, 14), GPIO_TO_PIN(8, 3), GPIO_TO_PIN(0, 13), 3, 20, 4, "in2" },
	{ GPIO_TO_PIN(7, 9), GPIO_TO_PIN(1, 12), GPIO_TO_PIN(1, 14), -1, 0, 0, "in3" },
	{ GPIO_TO_PIN(7, 10), GPIO_TO_PIN(1, 11), GPIO_TO_PIN(1, 15), -1, 0, 0, "in4" },
};

struct in_port_bus {
	struct i2c_adapter adap;
	struct i2c_algo_bit_data bit;
	bool added;
};

static struct in_port_bus buses[LEGOEV3_NUM_IN_PORTS];

static void port_setsda(void *data, int state)
{
	const struct in_port_lines *lines = data;

	if (state)
		gpio_direction_input(lines->sda);
	else
		gpio_direction_output(lines->sda, 0);
}

static void port_setscl(void *data, int state)
{
	const struct in_port_lines *lines = data;

	gpio_set_value(lines->scl, state);
}

static int port_getsda(void *data)
{
	const struct in_port_lines *lines = data;

	return gpio_get_value(lines->sda) != 0;
}

/* Muxes the SCL pad as GPIO, as the board file does for a UART TX pad. */
static void mux_scl_as_gpio(const struct in_port_lines *lines)
{
	void __iomem *reg;

	if (lines->mux_reg < 0)
		return;
	reg = DA8XX_SYSCFG0_VIRT(DA8XX_PINMUX_REG(lines->mux_reg));
	writel(KICK0_KEY, DA8XX_SYSCFG0_VIRT(DA8XX_KICK0_REG));
	writel(KICK1_KEY, DA8XX_SYSCFG0_VIRT(DA8XX_KICK1_REG));
	writel((readl(reg) & ~(0xfU << lines->mux_shift)) | lines->mux_gpio << lines->mux_shift, reg);
	writel(0, DA8XX_SYSCFG0_VIRT(DA8XX_KICK0_REG));
	writel(0, DA8XX_SYSCFG0_VIRT(DA8XX_KICK1_REG));
}

/* Requests one of the port's lines, logging its owner if taken. */
static int request_line(unsigned int gpio, const char *label)
{
	int ret = gpio_request(gpio, label);

	if (ret)
		pr_err("legoev3-i2c: %s: GPIO %u is taken (by %s): %d\n", label, gpio,
		       gpio_label(gpio) ? gpio_label(gpio) : "?", ret);
	return ret;
}

int legoev3_in_port_i2c_add(unsigned int index)
{
	const struct in_port_lines *lines;
	struct in_port_bus *bus;
	int ret;

	if (index >= LEGOEV3_NUM_IN_PORTS)
		return -EINVAL;
	lines = &port_lines[index];
	bus = &buses[index];
	if (bus->added)
		return -EBUSY;
	ret = request_line(lines->buffer, "legoev3-i2c buffer");
	if (ret)
		return ret;
	ret = request_line(lines->scl, "legoev3-i2c scl");
	if (ret)
		goto free_buffer;
	ret = request_line(lines->sda, "legoev3-i2c sda");
	if (ret)
		goto free_scl;
	mux_scl_as_gpio(lines);
	gpio_direction_output(lines->scl, 1);
	gpio_direction_input(lines->sda);
	gpio_direction_output(lines->buffer, 0);

	memset(bus, 0, sizeof(*bus));
	bus->bit = (struct i2c_algo_bit_data){
		.data = (void *)lines,
		.setsda = port_setsda,
		.setscl = port_setscl,
		.getsda = port_getsda,
		.udelay = 50,
		.timeout = HZ / 10,
		.can_do_atomic = true,
	};
	bus->adap.algo_data = &bus->bit;
	bus->adap.nr = LEGOEV3_IN_PORT_I2C_BUS(index);
	snprintf(bus->adap.name, sizeof(bus->adap.name), "legoev3 input port %s", lines->name);
	ret = i2c_bit_add_numbered_bus(&bus->adap);
	if (ret)
		goto release;
	bus->added = true;
	return 0;

release:
	gpio_direction_output(lines->buffer, 1);
	gpio_free(lines->sda);
free_scl:
	gpio_free(lines->scl);
free_buffer:
	gpio_free(lines->buffer);
	return ret;
}

void legoev3_in_port_i2c_del(unsigned int index)
{
	const struct in_port_lines *lines;
	struct in_port_bus *bus;

	if (index >= LEGOEV3_NUM_IN_PORTS || !buses[index].added)
		return;
	lines = &port_lines[index];
	bus = &buses[index];
	i2c_del_adapter(&bus->adap);
	bus->added = false;
	gpio_direction_output(lines->buffer, 1);
	gpio_direction_input(lines->sda);
	gpio_free(lines->sda);
	gpio_free(lines->scl);
	gpio_free(lines->buffer);
}

struct i2c_adapter *legoev3_in_port_i2c_adapter(unsigned int index)
{
	return index < LEGOEV3_NUM_IN_PORTS && buses[index].added ? &buses[index].adap : NULL;
}

/* Forgets the buses of a previous boot (their adapters died with it). */
void lx_legoev3_i2c_boot(void)
{
	memset(buses, 0, sizeof(buses));
}

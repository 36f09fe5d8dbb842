/*
 * i2c.c — the DaVinci I2C controllers as I2C adapters (da8xx_register_i2c,
 * mach/da8xx.h), interrupt-driven as Linux 6.1's i2c-davinci: each message
 * one controller transfer (ICSAR, ICCNT, ICMDR with STT and, for the last
 * message, STP), bytes moved on ICXRDY / ICRRDY, the message done at SCD
 * (after a STOP) or ARDY (bus held for the next message's repeated START).
 * Registers: AM1808 TRM, I2C chapter.
 */
#include <linux/completion.h>
#include <linux/delay.h>
#include <linux/i2c.h>
#include <linux/interrupt.h>
#include <linux/io.h>
#include <linux/jiffies.h>
#include <linux/kernel.h>
#include <linux/platform_data/i2c-davinci.h>
#include <linux/sizes.h>
#include <linux/string.h>
#include <mach/da8xx.h>
#include <mach/irqs.h>
#include <linux_compat/irq.h>

#define ICOAR		0x00
#define ICIMR		0x04
#define ICSTR		0x08
#define ICCLKL		0x0c
#define ICCLKH		0x10
#define ICCNT		0x14
#define ICDRR		0x18
#define ICSAR		0x1c
#define ICDXR		0x20
#define ICMDR		0x24
#define ICIVR		0x28
#define ICPSC		0x30
#define ICPFUNC		0x48

#define STR_AL		BIT(0)
#define STR_NACK	BIT(1)
#define STR_ARDY	BIT(2)
#define STR_RRDY	BIT(3)
#define STR_XRDY	BIT(4)
#define STR_SCD		BIT(5)
#define STR_BB		BIT(12)
#define MDR_RM		BIT(7)
#define MDR_IRS		BIT(5)
#define MDR_TRX		BIT(9)
#define MDR_MST		BIT(10)
#define MDR_STP		BIT(11)
#define MDR_STT		BIT(13)
#define MDR_FREE	BIT(14)

enum { IVR_NONE, IVR_AL, IVR_NACK, IVR_ARDY, IVR_RDR, IVR_XRDY, IVR_SCD, IVR_AAS };

#define OWN_ADDRESS	0x08
#define PRESCALED_MAX_HZ 12000000U      /* TRM: the prescaled clock must be 7..12 MHz */
#define MAX_IRQ_ROUNDS	2000

struct davinci_i2c {
	struct i2c_adapter adap;
	void __iomem *base;
	unsigned int irq;
	unsigned long clock_hz;
	unsigned int bus_freq_khz;
	unsigned int bus_delay_us;
	bool has_pfunc;
	struct completion done;
	u8 *buf;
	size_t buf_len;
	bool stop;
	u32 cmd_err;
	bool added;
};

/* Per instance: base, IRQ, module clock (I2C0 the 24 MHz oscillator, PLL0's
 * AUXCLK; I2C1 taken as ASYNC3, 132 MHz as LEGO sets PLL1). */
static const struct {
	resource_size_t base;
	unsigned int irq;
	unsigned long clock_hz;
} instances[2] = {
	{ DA8XX_I2C0_BASE, IRQ_DA8XX_I2CINT0, 24000000UL },
	{ DA8XX_I2C1_BASE, IRQ_DA8XX_I2CINT1, 132000000UL },
};

static struct davinci_i2c i2c_devs[2];

static u32 rd(struct davinci_i2c *dev, unsigned int reg)
{
	return readl((u8 __iomem *)dev->base + reg);
}

static void wr(struct davinci_i2c *dev, unsigned int reg, u32 value)
{
	writel(value, (u8 __iomem *)dev->base + reg);
}

/* Resets the module and programs its clock and own address, interrupts on
 * for AL, NACK, ARDY and SCD (ICRRDY/ICXRDY per message). */
static void davinci_i2c_init(struct davinci_i2c *dev)
{
	u32 psc, d, clk, clkl, clkh, prescaled;

	wr(dev, ICMDR, 0);
	psc = DIV_ROUND_UP(dev->clock_hz, PRESCALED_MAX_HZ) - 1;
	d = psc == 0 ? 7 : psc == 1 ? 6 : 5;
	prescaled = dev->clock_hz / (psc + 1);
	/* SCL period = (ICCLKL + d) + (ICCLKH + d) prescaled cycles, no faster than bus_freq */
	clk = DIV_ROUND_UP(prescaled, dev->bus_freq_khz * 1000U);
	clkl = max_t(u32, clk / 2, d + 1) - d;
	clkh = max_t(u32, clk - clk / 2, d + 1) - d;
	wr(dev, ICPSC, psc);
	wr(dev, ICCLKL, clkl);
	wr(dev, ICCLKH, clkh);
	wr(dev, ICOAR, OWN_ADDRESS);
	if (dev->has_pfunc)
		wr(dev, ICPFUNC, 0);
	wr(dev, ICMDR, MDR_IRS | MDR_FREE);
	wr(dev, ICIMR, STR_AL | STR_NACK | STR_ARDY | STR_SCD);
}

/* Waits for the bus to be free, at most the adapter's timeout; a bus still
 * busy is freed by resetting the module: 0. */
static void wait_bus_not_busy(struct davinci_i2c *dev)
{
	unsigned long deadline = jiffies + (unsigned long)dev->adap.timeout;

	while (rd(dev, ICSTR) & STR_BB) {
		if (time_after(jiffies, deadline)) {
			dev_warn(&dev->adap.dev, "timeout waiting for bus ready\n");
			davinci_i2c_init(dev);
			return;
		}
		usleep_range(100, 200);
	}
}

/* One message as one controller transfer: its length, or -errno. */
static int xfer_msg(struct davinci_i2c *dev, struct i2c_msg *msg, bool stop)
{
	bool read = msg->flags & I2C_M_RD;
	u32 flag = MDR_IRS | MDR_MST | MDR_FREE;
	unsigned long left;

	if (msg->len == 0 || (msg->flags & I2C_M_TEN))
		return -EOPNOTSUPP;
	/* a data interrupt left enabled by a message cut short must not fire on this one's setup */
	wr(dev, ICIMR, rd(dev, ICIMR) & ~(STR_RRDY | STR_XRDY));
	wr(dev, ICSAR, msg->addr);
	wr(dev, ICCNT, msg->len);
	dev->buf = msg->buf;
	dev->buf_len = msg->len;
	dev->stop = stop;
	dev->cmd_err = 0;
	reinit_completion(&dev->done);
	if (!read)
		flag |= MDR_TRX;
	/* mode first, STT only once ICDXR holds the first byte */
	wr(dev, ICMDR, flag);
	if (!read) {
		wr(dev, ICDXR, *dev->buf++);
		dev->buf_len--;
	}
	flag |= MDR_STT;
	if (stop)
		flag |= MDR_STP;
	wr(dev, ICMDR, flag);
	/* the data interrupt only now: ICXRDY, set while the module idles, would
	 * otherwise take the first byte before the code above does */
	wr(dev, ICIMR, rd(dev, ICIMR) | (read ? STR_RRDY : STR_XRDY));

	left = wait_for_completion_timeout(&dev->done, (unsigned long)dev->adap.timeout);
	if (!left) {
		dev_err(&dev->adap.dev, "controller timed out\n");
		davinci_i2c_init(dev);
		return -ETIMEDOUT;
	}
	if (dev->cmd_err & STR_AL) {
		davinci_i2c_init(dev);
		return -EAGAIN;
	}
	if (dev->cmd_err & STR_NACK) {
		if (msg->flags & I2C_M_IGNORE_NAK)
			return msg->len;
		wr(dev, ICMDR, rd(dev, ICMDR) | MDR_STP);
		return -EREMOTEIO;
	}
	if (dev->buf_len) {
		dev_err(&dev->adap.dev, "abnormal termination buf_len=%zu\n", dev->buf_len);
		dev->buf_len = 0;
		return -EREMOTEIO;
	}
	return msg->len;
}

static int davinci_i2c_xfer(struct i2c_adapter *adap, struct i2c_msg msgs[], int num)
{
	struct davinci_i2c *dev = i2c_get_adapdata(adap);
	int i, ret;

	wait_bus_not_busy(dev);
	for (i = 0; i < num; i++) {
		ret = xfer_msg(dev, &msgs[i], i == num - 1);
		if (ret < 0)
			return ret;
		if (dev->bus_delay_us)
			udelay(dev->bus_delay_us);
	}
	return num;
}

static u32 davinci_i2c_func(struct i2c_adapter *adap)
{
	return I2C_FUNC_I2C | (I2C_FUNC_SMBUS_EMUL & ~I2C_FUNC_SMBUS_QUICK);
}

static const struct i2c_algorithm davinci_i2c_algo = {
	.master_xfer = davinci_i2c_xfer,
	.functionality = davinci_i2c_func,
};

static irqreturn_t davinci_i2c_isr(int irq, void *data)
{
	struct davinci_i2c *dev = data;
	unsigned int rounds = 0;
	u32 ivr;

	while ((ivr = rd(dev, ICIVR) & 7) != IVR_NONE) {
		if (rounds++ == MAX_IRQ_ROUNDS) {
			dev_warn(&dev->adap.dev, "Too much work in one IRQ\n");
			break;
		}
		switch (ivr) {
		case IVR_AL:
			dev->cmd_err |= STR_AL;
			dev->buf_len = 0;
			complete(&dev->done);
			break;
		case IVR_NACK:
			dev->cmd_err |= STR_NACK;
			dev->buf_len = 0;
			complete(&dev->done);
			break;
		case IVR_ARDY:
			wr(dev, ICSTR, STR_ARDY);
			if ((dev->buf_len == 0 && dev->stop) || (dev->cmd_err & STR_NACK))
				wr(dev, ICMDR, rd(dev, ICMDR) | MDR_STP);
			complete(&dev->done);
			break;
		case IVR_RDR:
			if (dev->buf_len) {
				*dev->buf++ = (u8)rd(dev, ICDRR);
				dev->buf_len--;
			} else {
				(void)rd(dev, ICDRR);
			}
			if (!dev->buf_len)
				wr(dev, ICIMR, rd(dev, ICIMR) & ~STR_RRDY);
			break;
		case IVR_XRDY:
			if (dev->buf_len) {
				wr(dev, ICDXR, *dev->buf++);
				dev->buf_len--;
			}
			if (!dev->buf_len)
				wr(dev, ICIMR, rd(dev, ICIMR) & ~STR_XRDY);
			break;
		case IVR_SCD:
			wr(dev, ICSTR, STR_SCD);
			complete(&dev->done);
			break;
		default:
			break;
		}
	}
	return rounds ? IRQ_HANDLED : IRQ_NONE;
}

int da8xx_register_i2c(int instance, struct davinci_i2c_platform_data *pdata)
{
	struct davinci_i2c *dev;
	int ret;

	might_sleep();
	if (instance < 0 || instance >= (int)ARRAY_SIZE(i2c_devs))
		return -EINVAL;
	dev = &i2c_devs[instance];
	if (dev->added)
		return -EBUSY;
	memset(dev, 0, sizeof(*dev));
	dev->irq = instances[instance].irq;
	dev->clock_hz = instances[instance].clock_hz;
	dev->bus_freq_khz = pdata && pdata->bus_freq ? pdata->bus_freq : 100;
	dev->bus_delay_us = pdata ? pdata->bus_delay : 0;
	dev->has_pfunc = pdata && pdata->has_pfunc;
	init_completion(&dev->done);
	dev->base = ioremap(instances[instance].base, SZ_4K);
	if (!dev->base)
		return -ENOMEM;
	davinci_i2c_init(dev);
	ret = request_irq(dev->irq, davinci_i2c_isr, 0, "i2c_davinci", dev);
	if (ret)
		goto unmap;
	dev->adap.algo = &davinci_i2c_algo;
	dev->adap.timeout = HZ;
	dev->adap.nr = instance + 1;
	snprintf(dev->adap.name, sizeof(dev->adap.name), "DaVinci I2C adapter");
	i2c_set_adapdata(&dev->adap, dev);
	ret = i2c_add_numbered_adapter(&dev->adap);
	if (ret)
		goto free_irq;
	dev->added = true;
	return 0;

free_irq:
	free_irq(dev->irq, dev);
unmap:
	wr(dev, ICMDR, 0);
	iounmap(dev->base);
	return ret;
}

void da8xx_unregister_i2c(int instance)
{
	struct davinci_i2c *dev;

	if (instance < 0 || instance >= (int)ARRAY_SIZE(i2c_devs) || !i2c_devs[instance].added)
		return;
	dev = &i2c_devs[instance];
	i2c_del_adapter(&dev->adap);
	free_irq(dev->irq, dev);
	wr(dev, ICMDR, 0);
	iounmap(dev->base);
	dev->added = false;
}

/* Forgets the controllers of a previous boot. */
void lx_davinci_i2c_boot(void)
{
	memset(i2c_devs, 0, sizeof(i2c_devs));
}

/*
 * i2c-algo-bit.c — I2C bit-banged through a struct i2c_algo_bit_data's
 * callbacks (linux/i2c-algo-bit.h states the contract), with Linux 6.1's
 * timing: each SCL half period is the data's udelay, SDA changes half way
 * through SCL's low phase, SCL may be stretched by a slave for timeout
 * jiffies when it can be read.
 */
#include <linux/i2c-algo-bit.h>
#include <linux/delay.h>
#include <linux/kernel.h>
#include <linux/jiffies.h>

static void setsda(struct i2c_algo_bit_data *bit, int state)
{
	bit->setsda(bit->data, state);
}

static void setscl(struct i2c_algo_bit_data *bit, int state)
{
	bit->setscl(bit->data, state);
}

static int getsda(struct i2c_algo_bit_data *bit)
{
	return bit->getsda(bit->data);
}

/* SDA low, then a quarter period. */
static void sdalo(struct i2c_algo_bit_data *bit)
{
	setsda(bit, 0);
	udelay((unsigned long)(bit->udelay + 1) / 2);
}

/* SDA released high, then a quarter period. */
static void sdahi(struct i2c_algo_bit_data *bit)
{
	setsda(bit, 1);
	udelay((unsigned long)(bit->udelay + 1) / 2);
}

/* SCL low, then a quarter period. */
static void scllo(struct i2c_algo_bit_data *bit)
{
	setscl(bit, 0);
	udelay((unsigned long)bit->udelay / 2);
}

/* SCL released high; waits while a slave stretches it (polled every
 * microsecond, so the wait is timed by the delays themselves even where the
 * tick cannot advance jiffies), then a half period: 0 or -ETIMEDOUT. */
static int sclhi(struct i2c_algo_bit_data *bit)
{
	unsigned long waited_us = 0;
	unsigned long limit_us = (unsigned long)bit->timeout * (1000000UL / HZ);

	setscl(bit, 1);
	if (bit->getscl) {
		while (!bit->getscl(bit->data)) {
			if (waited_us >= limit_us)
				return -ETIMEDOUT;
			udelay(1);
			waited_us++;
		}
	}
	udelay((unsigned long)bit->udelay);
	return 0;
}

/* START: SDA falls while SCL is high. */
static void i2c_start(struct i2c_algo_bit_data *bit)
{
	setsda(bit, 0);
	udelay((unsigned long)bit->udelay);
	scllo(bit);
}

/* Repeated START: both lines high again, then a START. */
static void i2c_repstart(struct i2c_algo_bit_data *bit)
{
	sdahi(bit);
	sclhi(bit);
	setsda(bit, 0);
	udelay((unsigned long)bit->udelay);
	scllo(bit);
}

/* STOP: SDA rises while SCL is high. */
static void i2c_stop(struct i2c_algo_bit_data *bit)
{
	sdalo(bit);
	sclhi(bit);
	setsda(bit, 1);
	udelay((unsigned long)bit->udelay);
}

/* Sends c MSB first and reads the slave's acknowledge: 1 ACK, 0 NACK,
 * -ETIMEDOUT (SCL held), -EAGAIN (a 1 sent but SDA low: arbitration lost). */
static int i2c_outb(struct i2c_algo_bit_data *bit, unsigned char c)
{
	int i, ack;

	for (i = 7; i >= 0; i--) {
		int sb = (c >> i) & 1;

		setsda(bit, sb);
		udelay((unsigned long)(bit->udelay + 1) / 2);
		if (sclhi(bit) < 0)
			return -ETIMEDOUT;
		if (sb && !getsda(bit)) {
			scllo(bit);
			return -EAGAIN;
		}
		scllo(bit);
	}
	sdahi(bit);
	if (sclhi(bit) < 0)
		return -ETIMEDOUT;
	ack = !getsda(bit);
	scllo(bit);
	return ack;
}

/* Reads one byte MSB first (the acknowledge is acknak's): the byte or -ETIMEDOUT. */
static int i2c_inb(struct i2c_algo_bit_data *bit)
{
	int i, indata = 0;

	sdahi(bit);
	for (i = 0; i < 8; i++) {
		if (sclhi(bit) < 0)
			return -ETIMEDOUT;
		indata <<= 1;
		if (getsda(bit))
			indata |= 1;
		setscl(bit, 0);
		udelay((unsigned long)(i == 7 ? bit->udelay / 2 : bit->udelay));
	}
	return indata;
}

/* The master's ACK (is_ack) or NACK on the ninth clock: 0 or -ETIMEDOUT. */
static int acknak(struct i2c_algo_bit_data *bit, int is_ack)
{
	if (is_ack)
		setsda(bit, 0);
	udelay((unsigned long)(bit->udelay + 1) / 2);
	if (sclhi(bit) < 0)
		return -ETIMEDOUT;
	scllo(bit);
	return 0;
}

/* Sends the address byte, retrying a NACK after a STOP and START up to
 * retries times: as i2c_outb. */
static int try_address(struct i2c_algo_bit_data *bit, unsigned char addr, int retries)
{
	int i, ret = 0;

	for (i = 0; i <= retries; i++) {
		ret = i2c_outb(bit, addr);
		if (ret == 1 || i == retries)
			break;
		i2c_stop(bit);
		udelay((unsigned long)bit->udelay);
		i2c_start(bit);
	}
	return ret;
}

/* Addresses msg's slave (7- or 10-bit, read or write): 0, -ENXIO if nobody
 * answers, or i2c_outb's error. */
static int bit_do_address(struct i2c_adapter *adap, struct i2c_msg *msg)
{
	struct i2c_algo_bit_data *bit = adap->algo_data;
	unsigned short flags = msg->flags;
	unsigned char addr;
	int ret;

	if (flags & I2C_M_TEN) {
		addr = (unsigned char)(0xf0 | ((msg->addr >> 7) & 0x06));
		ret = try_address(bit, addr, adap->retries);
		if (ret == 1)
			ret = i2c_outb(bit, (unsigned char)(msg->addr & 0xff));
		if (ret == 1 && (flags & I2C_M_RD)) {
			i2c_repstart(bit);
			ret = try_address(bit, addr | 1, adap->retries);
		}
	} else {
		addr = i2c_8bit_addr_from_msg(msg);
		if (flags & I2C_M_REV_DIR_ADDR)
			addr ^= 1;
		ret = try_address(bit, addr, adap->retries);
	}
	if (ret < 0)
		return ret;
	return ret == 1 ? 0 : -ENXIO;
}

/* Writes msg's bytes: the count sent, -EREMOTEIO at a NACK (unless
 * I2C_M_IGNORE_NAK), or i2c_outb's error. */
static int sendbytes(struct i2c_adapter *adap, struct i2c_msg *msg)
{
	struct i2c_algo_bit_data *bit = adap->algo_data;
	bool nak_ok = msg->flags & I2C_M_IGNORE_NAK;
	int i, ret;

	for (i = 0; i < msg->len; i++) {
		ret = i2c_outb(bit, msg->buf[i]);
		if (ret < 0)
			return ret;
		if (ret == 0 && !nak_ok) {
			dev_err(&adap->dev, "sendbytes: NAK bailout.\n");
			return -EREMOTEIO;
		}
	}
	return i;
}

/* Reads msg's bytes, ACKing all but the last (I2C_M_RECV_LEN: the first
 * byte is the count that follows): the count read, -EPROTO for a bad block
 * length, or -ETIMEDOUT. */
static int readbytes(struct i2c_adapter *adap, struct i2c_msg *msg)
{
	struct i2c_algo_bit_data *bit = adap->algo_data;
	unsigned int count = msg->len;
	unsigned char *temp = msg->buf;
	int rdcount = 0;

	while (count > 0) {
		int inval = i2c_inb(bit);

		if (inval < 0)
			return inval;
		*temp++ = (unsigned char)inval;
		rdcount++;
		count--;
		if (rdcount == 1 && (msg->flags & I2C_M_RECV_LEN)) {
			if (inval <= 0 || inval > I2C_SMBUS_BLOCK_MAX) {
				if (!(msg->flags & I2C_M_NO_RD_ACK))
					acknak(bit, 0);
				dev_err(&adap->dev, "readbytes: invalid block length (%d)\n", inval);
				return -EPROTO;
			}
			count += (unsigned int)inval;
			msg->len = (u16)(msg->len + inval);
		}
		if (!(msg->flags & I2C_M_NO_RD_ACK)) {
			int ret = acknak(bit, count > 0);

			if (ret < 0)
				return ret;
		}
	}
	return rdcount;
}

/* The messages as one transaction: START, each message (a repeated START,
 * or STOP and START after an I2C_M_STOP message, before all but the
 * first), STOP.  num, or the first error. */
static int bit_xfer(struct i2c_adapter *adap, struct i2c_msg msgs[], int num)
{
	struct i2c_algo_bit_data *bit = adap->algo_data;
	int i, ret;

	if (bit->pre_xfer) {
		ret = bit->pre_xfer(adap);
		if (ret < 0)
			return ret;
	}
	i2c_start(bit);
	for (i = 0; i < num; i++) {
		struct i2c_msg *pmsg = &msgs[i];
		bool nak_ok = pmsg->flags & I2C_M_IGNORE_NAK;

		if (!(pmsg->flags & I2C_M_NOSTART)) {
			if (i) {
				if (msgs[i - 1].flags & I2C_M_STOP) {
					i2c_stop(bit);
					udelay((unsigned long)bit->udelay);
					i2c_start(bit);
				} else {
					i2c_repstart(bit);
				}
			}
			ret = bit_do_address(adap, pmsg);
			if (ret && !(nak_ok && ret == -ENXIO)) {
				dev_dbg(&adap->dev, "NAK from device addr 0x%02x msg #%d\n", pmsg->addr, i);
				goto bailout;
			}
		}
		ret = (pmsg->flags & I2C_M_RD) ? readbytes(adap, pmsg) : sendbytes(adap, pmsg);
		if (ret < pmsg->len) {
			if (ret >= 0)
				ret = -EIO;
			goto bailout;
		}
	}
	ret = i;
bailout:
	i2c_stop(bit);
	if (bit->post_xfer)
		bit->post_xfer(adap);
	return ret;
}

/* bit_xfer for callers that may not sleep, if the callbacks never do. */
static int bit_xfer_atomic(struct i2c_adapter *adap, struct i2c_msg msgs[], int num)
{
	struct i2c_algo_bit_data *bit = adap->algo_data;

	return bit->can_do_atomic ? bit_xfer(adap, msgs, num) : -EOPNOTSUPP;
}

static u32 bit_func(struct i2c_adapter *adap)
{
	return I2C_FUNC_I2C | I2C_FUNC_NOSTART | I2C_FUNC_SMBUS_EMUL_ALL |
	       I2C_FUNC_10BIT_ADDR | I2C_FUNC_PROTOCOL_MANGLING;
}

const struct i2c_algorithm i2c_bit_algo = {
	.master_xfer = bit_xfer,
	.master_xfer_atomic = bit_xfer_atomic,
	.functionality = bit_func,
};

/* Checks the callbacks, idles the lines high, gives adap the algorithm and registers it with add. */
static int bit_add(struct i2c_adapter *adap, int (*add)(struct i2c_adapter *))
{
	struct i2c_algo_bit_data *bit = adap ? adap->algo_data : NULL;

	if (!bit || !bit->setsda || !bit->setscl || !bit->getsda) {
		pr_err("i2c-algo-bit: adapter '%s': setsda, setscl and getsda are required\n",
		       adap ? adap->name : "");
		return -EINVAL;
	}
	if (bit->timeout <= 0)
		bit->timeout = HZ / 10;
	setsda(bit, 1);
	setscl(bit, 1);
	adap->algo = &i2c_bit_algo;
	adap->retries = 3;
	return add(adap);
}

int i2c_bit_add_bus(struct i2c_adapter *adap)
{
	return bit_add(adap, i2c_add_adapter);
}

int i2c_bit_add_numbered_bus(struct i2c_adapter *adap)
{
	return bit_add(adap, i2c_add_numbered_adapter);
}

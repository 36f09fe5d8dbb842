/*
 * linux/i2c.h — the I2C core as Linux 6.1 has it (drivers/i2c/i2c-core-base.c
 * and i2c-core-smbus.c): adapters with their algorithm, clients created from
 * board info, client drivers matched by of_match_table or id_table on the
 * I2C bus, i2c_transfer and the SMBus calls emulated over master_xfer.
 *
 * Adapters are named "i2c-<nr>"; a client is "<nr>-<addr, 4 hex digits>"
 * (0xa000 added for a 10-bit address), a child of its adapter.  Transfers
 * take the adapter's bus lock (a mutex) and may sleep: called where a task
 * may not sleep they are reported as linux_compat reports such calls, and
 * fail with -EAGAIN unless the algorithm has a master_xfer_atomic.
 * Differences: the bus lock is a plain mutex (no rt_mutex, no mux locking);
 * no i2c-dev, sysfs new_device or detect/address_list probing; the driver's
 * probe is Linux 6.3's union of the one-argument probe and probe_new (the
 * two-argument 6.1 probe is not provided).
 */
#ifndef _LINUX_I2C_H
#define _LINUX_I2C_H

#include <linux/types.h>
#include <linux/bits.h>
#include <linux/device.h>
#include <linux/errno.h>
#include <linux/list.h>
#include <linux/mod_devicetable.h>
#include <linux/mutex.h>
#include <linux/of.h>
#include <linux/platform_device.h>   /* module_driver */
#include <linux/swab.h>

/* ---- messages and functionality (Linux's uapi/linux/i2c.h) ---- */

struct i2c_msg {
	__u16 addr;
	__u16 flags;
#define I2C_M_RD		0x0001
#define I2C_M_TEN		0x0010
#define I2C_M_DMA_SAFE		0x0200
#define I2C_M_RECV_LEN		0x0400
#define I2C_M_NO_RD_ACK		0x0800
#define I2C_M_IGNORE_NAK	0x1000
#define I2C_M_REV_DIR_ADDR	0x2000
#define I2C_M_NOSTART		0x4000
#define I2C_M_STOP		0x8000
	__u16 len;
	__u8 *buf;
};

#define I2C_FUNC_I2C			0x00000001
#define I2C_FUNC_10BIT_ADDR		0x00000002
#define I2C_FUNC_PROTOCOL_MANGLING	0x00000004
#define I2C_FUNC_SMBUS_PEC		0x00000008
#define I2C_FUNC_NOSTART		0x00000010
#define I2C_FUNC_SLAVE			0x00000020
#define I2C_FUNC_SMBUS_BLOCK_PROC_CALL	0x00008000
#define I2C_FUNC_SMBUS_QUICK		0x00010000
#define I2C_FUNC_SMBUS_READ_BYTE	0x00020000
#define I2C_FUNC_SMBUS_WRITE_BYTE	0x00040000
#define I2C_FUNC_SMBUS_READ_BYTE_DATA	0x00080000
#define I2C_FUNC_SMBUS_WRITE_BYTE_DATA	0x00100000
#define I2C_FUNC_SMBUS_READ_WORD_DATA	0x00200000
#define I2C_FUNC_SMBUS_WRITE_WORD_DATA	0x00400000
#define I2C_FUNC_SMBUS_PROC_CALL	0x00800000
#define I2C_FUNC_SMBUS_READ_BLOCK_DATA	0x01000000
#define I2C_FUNC_SMBUS_WRITE_BLOCK_DATA	0x02000000
#define I2C_FUNC_SMBUS_READ_I2C_BLOCK	0x04000000
#define I2C_FUNC_SMBUS_WRITE_I2C_BLOCK	0x08000000
#define I2C_FUNC_SMBUS_HOST_NOTIFY	0x10000000

#define I2C_FUNC_SMBUS_BYTE		(I2C_FUNC_SMBUS_READ_BYTE | I2C_FUNC_SMBUS_WRITE_BYTE)
#define I2C_FUNC_SMBUS_BYTE_DATA	(I2C_FUNC_SMBUS_READ_BYTE_DATA | I2C_FUNC_SMBUS_WRITE_BYTE_DATA)
#define I2C_FUNC_SMBUS_WORD_DATA	(I2C_FUNC_SMBUS_READ_WORD_DATA | I2C_FUNC_SMBUS_WRITE_WORD_DATA)
#define I2C_FUNC_SMBUS_BLOCK_DATA	(I2C_FUNC_SMBUS_READ_BLOCK_DATA | I2C_FUNC_SMBUS_WRITE_BLOCK_DATA)
#define I2C_FUNC_SMBUS_I2C_BLOCK	(I2C_FUNC_SMBUS_READ_I2C_BLOCK | I2C_FUNC_SMBUS_WRITE_I2C_BLOCK)

#define I2C_FUNC_SMBUS_EMUL	(I2C_FUNC_SMBUS_QUICK | I2C_FUNC_SMBUS_BYTE | I2C_FUNC_SMBUS_BYTE_DATA | \
				 I2C_FUNC_SMBUS_WORD_DATA | I2C_FUNC_SMBUS_PROC_CALL | \
				 I2C_FUNC_SMBUS_WRITE_BLOCK_DATA | I2C_FUNC_SMBUS_I2C_BLOCK | \
				 I2C_FUNC_SMBUS_PEC)
#define I2C_FUNC_SMBUS_EMUL_ALL	(I2C_FUNC_SMBUS_EMUL | I2C_FUNC_SMBUS_READ_BLOCK_DATA | \
				 I2C_FUNC_SMBUS_BLOCK_PROC_CALL)

#define I2C_SMBUS_BLOCK_MAX	32

union i2c_smbus_data {
	__u8 byte;
	__u16 word;
	__u8 block[I2C_SMBUS_BLOCK_MAX + 2];   /* block[0] is the length */
};

#define I2C_SMBUS_READ		1
#define I2C_SMBUS_WRITE		0

#define I2C_SMBUS_QUICK			0
#define I2C_SMBUS_BYTE			1
#define I2C_SMBUS_BYTE_DATA		2
#define I2C_SMBUS_WORD_DATA		3
#define I2C_SMBUS_PROC_CALL		4
#define I2C_SMBUS_BLOCK_DATA		5
#define I2C_SMBUS_I2C_BLOCK_BROKEN	6
#define I2C_SMBUS_BLOCK_PROC_CALL	7
#define I2C_SMBUS_I2C_BLOCK_DATA	8

struct i2c_adapter;
struct i2c_client;

extern struct bus_type i2c_bus_type;

/* ---- the algorithm an adapter runs ---- */

struct i2c_algorithm {
	/* msgs[0..num) as one combined transaction: num, or -errno */
	int (*master_xfer)(struct i2c_adapter *adap, struct i2c_msg *msgs, int num);
	/* the same, for callers that may not sleep */
	int (*master_xfer_atomic)(struct i2c_adapter *adap, struct i2c_msg *msgs, int num);
	/* native SMBus (else emulated over master_xfer) */
	int (*smbus_xfer)(struct i2c_adapter *adap, u16 addr, unsigned short flags, char read_write,
			  u8 command, int size, union i2c_smbus_data *data);
	int (*smbus_xfer_atomic)(struct i2c_adapter *adap, u16 addr, unsigned short flags,
				 char read_write, u8 command, int size, union i2c_smbus_data *data);
	/* I2C_FUNC_* the adapter supports */
	u32 (*functionality)(struct i2c_adapter *adap);
};

struct i2c_adapter_quirks;
struct i2c_bus_recovery_info;

struct i2c_adapter {
	struct module *owner;
	unsigned int class;
	const struct i2c_algorithm *algo;
	void *algo_data;
	struct mutex bus_lock;          /* Linux: an rt_mutex */
	int timeout;                    /* in jiffies (i2c_add_adapter sets HZ if 0) */
	int retries;                    /* resends after -EAGAIN (arbitration lost) */
	struct device dev;
	int nr;
	char name[48];
	const struct i2c_adapter_quirks *quirks;
	struct i2c_bus_recovery_info *bus_recovery_info;
	struct list_head lx_node;       /* ev3lx: on the adapter list */
	bool lx_added;                  /* ev3lx: between add and del */
};

#define to_i2c_adapter(d)	container_of(d, struct i2c_adapter, dev)

#define I2C_CLASS_HWMON		(1 << 0)
#define I2C_CLASS_DDC		(1 << 3)
#define I2C_CLASS_SPD		(1 << 7)
#define I2C_CLASS_DEPRECATED	(1 << 8)

/* i2c_lock_bus flags */
#define I2C_LOCK_ROOT_ADAPTER	BIT(0)
#define I2C_LOCK_SEGMENT	BIT(1)

static inline void *i2c_get_adapdata(const struct i2c_adapter *adap)
{
	return dev_get_drvdata(&adap->dev);
}

static inline void i2c_set_adapdata(struct i2c_adapter *adap, void *data)
{
	dev_set_drvdata(&adap->dev, data);
}

static inline int i2c_adapter_id(struct i2c_adapter *adap)
{
	return adap->nr;
}

/* Takes the adapter's bus lock (process context). */
void i2c_lock_bus(struct i2c_adapter *adap, unsigned int flags);
/* Takes it if free: 1, else 0. */
int i2c_trylock_bus(struct i2c_adapter *adap, unsigned int flags);
void i2c_unlock_bus(struct i2c_adapter *adap, unsigned int flags);

/* Registers adap with the lowest free number above the board-info buses:
 * 0 or -errno (-EINVAL without algo or name). */
int i2c_add_adapter(struct i2c_adapter *adap);
/* Registers adap as bus adap->nr (-1: as i2c_add_adapter), creating the
 * clients of i2c_register_board_info for that bus: 0, -EBUSY if taken. */
int i2c_add_numbered_adapter(struct i2c_adapter *adap);
/* Unregisters every client on adap, then adap. */
void i2c_del_adapter(struct i2c_adapter *adap);
/* i2c_add_adapter, undone when dev's driver unbinds. */
int devm_i2c_add_adapter(struct device *dev, struct i2c_adapter *adap);
/* The registered adapter numbered nr, with a reference (NULL if none). */
struct i2c_adapter *i2c_get_adapter(int nr);
void i2c_put_adapter(struct i2c_adapter *adap);

u32 i2c_get_functionality(struct i2c_adapter *adap);

static inline int i2c_check_functionality(struct i2c_adapter *adap, u32 func)
{
	return (func & i2c_get_functionality(adap)) == func;
}

/* ---- clients and their drivers ---- */

#define I2C_CLIENT_PEC		0x04
#define I2C_CLIENT_TEN		0x10
#define I2C_CLIENT_SLAVE	0x20
#define I2C_CLIENT_HOST_NOTIFY	0x40
#define I2C_CLIENT_WAKE		0x80
#define I2C_CLIENT_SCCB		0x9000

struct i2c_client {
	unsigned short flags;
	unsigned short addr;            /* 7-bit (or 10-bit with I2C_CLIENT_TEN) */
	char name[I2C_NAME_SIZE];
	struct i2c_adapter *adapter;
	struct device dev;
	int init_irq;
	int irq;
	struct list_head detected;
	void *devres_group_id;
	struct list_head lx_node;       /* ev3lx: on the client list */
};

#define to_i2c_client(d)	container_of(d, struct i2c_client, dev)

static inline void *i2c_get_clientdata(const struct i2c_client *client)
{
	return dev_get_drvdata(&client->dev);
}

static inline void i2c_set_clientdata(struct i2c_client *client, void *data)
{
	dev_set_drvdata(&client->dev, data);
}

/* dev as an I2C client, or NULL if it is not one. */
struct i2c_client *i2c_verify_client(struct device *dev);

struct i2c_board_info {
	char type[I2C_NAME_SIZE];
	unsigned short flags;
	unsigned short addr;
	const char *dev_name;
	void *platform_data;
	struct device_node *of_node;
	const struct resource *resources;
	unsigned int num_resources;
	int irq;
};

#define I2C_BOARD_INFO(dev_type, dev_addr)	.type = dev_type, .addr = (dev_addr)

/* A client of info's type at info's address on adap, bound to a driver if
 * one matches: the client, or ERR_PTR(-EINVAL) for a bad address,
 * -EBUSY for an address in use, -ENOMEM.  Process context. */
struct i2c_client *i2c_new_client_device(struct i2c_adapter *adap, const struct i2c_board_info *info);
/* A client named name at address with no driver bound ("dummy"). */
struct i2c_client *i2c_new_dummy_device(struct i2c_adapter *adap, u16 address);
struct i2c_client *devm_i2c_new_dummy_device(struct device *dev, struct i2c_adapter *adap, u16 address);
/* Unbinds and frees client (NULL or an error pointer: nothing). */
void i2c_unregister_device(struct i2c_client *client);
/* The board's clients for bus busnum, created when that adapter is added
 * with i2c_add_numbered_adapter (the table is copied): 0 or -ENOMEM. */
int i2c_register_board_info(int busnum, struct i2c_board_info const *info, unsigned int n);

struct i2c_driver {
	unsigned int class;             /* the adapter classes detect() is tried on */
	union {
		/* bind to client: 0, or -errno (Linux 6.3+) */
		int (*probe)(struct i2c_client *client);
		/* the same under its 6.1 name */
		int (*probe_new)(struct i2c_client *client);
	};
	void (*remove)(struct i2c_client *client);
	void (*shutdown)(struct i2c_client *client);
	int (*command)(struct i2c_client *client, unsigned int cmd, void *arg);
	struct device_driver driver;
	const struct i2c_device_id *id_table;
	/* Auto-detection (Linux's i2c_detect): on each adapter whose class
	 * shares a bit with class, every address of address_list (ending in
	 * I2C_CLIENT_END) free and answering a probe is offered to detect,
	 * which fills info->type (0) or declines (-ENODEV); a client of that
	 * type is then created, and removed with the driver or adapter. */
	int (*detect)(struct i2c_client *client, struct i2c_board_info *info);
	const unsigned short *address_list;
	struct list_head clients;       /* the clients detect created */
	u32 flags;
	struct list_head lx_node;       /* ev3lx: on the list of registered drivers */
};

/* The end of a driver's address_list (Linux's value), and a list written inline. */
#define I2C_CLIENT_END	0xfffeU
#define I2C_ADDRS(addr, addrs...)	((const unsigned short []){ addr, ## addrs, I2C_CLIENT_END })

#define to_i2c_driver(d)	container_of(d, struct i2c_driver, driver)

/* Registers driver on the I2C bus and binds every matching client: 0 or -errno. */
int i2c_register_driver(struct module *owner, struct i2c_driver *driver);
void i2c_del_driver(struct i2c_driver *driver);

#define i2c_add_driver(driver)	i2c_register_driver(THIS_MODULE, driver)

#define module_i2c_driver(__i2c_driver)	\
	module_driver(__i2c_driver, i2c_add_driver, i2c_del_driver)

/* The id_table entry naming client, or NULL. */
const struct i2c_device_id *i2c_match_id(const struct i2c_device_id *id, const struct i2c_client *client);
/* The id_table entry of the driver bound to client that names it, or NULL (Linux 6.3). */
const struct i2c_device_id *i2c_client_get_device_id(const struct i2c_client *client);
/* The of_match_table entry matching client's node, or NULL. */
const struct of_device_id *i2c_of_match_device(const struct of_device_id *matches,
					       struct i2c_client *client);
/* The match data of the driver bound to client: of_match_table's, else id_table's. */
const void *i2c_get_match_data(const struct i2c_client *client);

/* ---- transfers ---- */

/* msgs[0..num) as one combined transaction under the bus lock: the number
 * of messages transferred, or -errno: -ENXIO / -EREMOTEIO when the slave
 * NACKs its address / a byte (as the algorithm reports it), -EAGAIN for a
 * lost arbitration after adap->retries resends, -ETIMEDOUT, -EOPNOTSUPP if
 * the adapter has no master_xfer, -EINVAL for a message without a buffer.
 * May sleep. */
int i2c_transfer(struct i2c_adapter *adap, struct i2c_msg *msgs, int num);
/* i2c_transfer with the bus lock already held. */
int __i2c_transfer(struct i2c_adapter *adap, struct i2c_msg *msgs, int num);
/* One message of count bytes to or from client (flags: I2C_M_RD and the
 * client's): count, or -errno. */
int i2c_transfer_buffer_flags(const struct i2c_client *client, char *buf, int count, u16 flags);

static inline int i2c_master_recv(const struct i2c_client *client, char *buf, int count)
{
	return i2c_transfer_buffer_flags(client, buf, count, I2C_M_RD);
}

static inline int i2c_master_recv_dmasafe(const struct i2c_client *client, char *buf, int count)
{
	return i2c_transfer_buffer_flags(client, buf, count, I2C_M_RD | I2C_M_DMA_SAFE);
}

static inline int i2c_master_send(const struct i2c_client *client, const char *buf, int count)
{
	return i2c_transfer_buffer_flags(client, (char *)buf, count, 0);
}

static inline int i2c_master_send_dmasafe(const struct i2c_client *client, const char *buf, int count)
{
	return i2c_transfer_buffer_flags(client, (char *)buf, count, I2C_M_DMA_SAFE);
}

/* The 8-bit address byte of msg (address << 1 | read). */
static inline u8 i2c_8bit_addr_from_msg(const struct i2c_msg *msg)
{
	return (u8)((msg->addr << 1) | (msg->flags & I2C_M_RD));
}

/* ---- SMBus, over the adapter's smbus_xfer or emulated with I2C messages ---- */

/* One SMBus transaction (I2C_SMBUS_*): 0, or -errno as i2c_transfer's, or
 * -EOPNOTSUPP for a size the adapter cannot do, -EPROTO for a block length
 * over I2C_SMBUS_BLOCK_MAX. */
s32 i2c_smbus_xfer(struct i2c_adapter *adapter, u16 addr, unsigned short flags, char read_write,
		   u8 command, int protocol, union i2c_smbus_data *data);
s32 __i2c_smbus_xfer(struct i2c_adapter *adapter, u16 addr, unsigned short flags, char read_write,
		     u8 command, int protocol, union i2c_smbus_data *data);

/* Each returns the value read (0..255 / 0..65535), the byte count, 0 for a
 * write, or -errno. */
s32 i2c_smbus_read_byte(const struct i2c_client *client);
s32 i2c_smbus_write_byte(const struct i2c_client *client, u8 value);
s32 i2c_smbus_read_byte_data(const struct i2c_client *client, u8 command);
s32 i2c_smbus_write_byte_data(const struct i2c_client *client, u8 command, u8 value);
s32 i2c_smbus_read_word_data(const struct i2c_client *client, u8 command);
s32 i2c_smbus_write_word_data(const struct i2c_client *client, u8 command, u16 value);
s32 i2c_smbus_process_call(const struct i2c_client *client, u8 command, u16 value);
s32 i2c_smbus_read_block_data(const struct i2c_client *client, u8 command, u8 *values);
s32 i2c_smbus_write_block_data(const struct i2c_client *client, u8 command, u8 length, const u8 *values);
s32 i2c_smbus_read_i2c_block_data(const struct i2c_client *client, u8 command, u8 length, u8 *values);
s32 i2c_smbus_write_i2c_block_data(const struct i2c_client *client, u8 command, u8 length,
				   const u8 *values);
/* Reads length bytes from command on: as an I2C block read if the adapter
 * can, else word by word, else byte by byte. */
s32 i2c_smbus_read_i2c_block_data_or_emulated(const struct i2c_client *client, u8 command, u8 length,
					      u8 *values);

/* The word with its bytes swapped (devices that send the MSB first). */
static inline s32 i2c_smbus_read_word_swapped(const struct i2c_client *client, u8 command)
{
	s32 value = i2c_smbus_read_word_data(client, command);

	return (value < 0) ? value : (s32)swab16((u16)value);
}

static inline s32 i2c_smbus_write_word_swapped(const struct i2c_client *client, u8 command, u16 value)
{
	return i2c_smbus_write_word_data(client, command, swab16(value));
}

#endif /* _LINUX_I2C_H */

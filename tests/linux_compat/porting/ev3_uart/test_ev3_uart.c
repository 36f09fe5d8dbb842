/*
 * test_ev3_uart.c — an upstream-style tty line discipline taken unchanged:
 * ev3_uart.c (tty_register_ldisc, open/close/receive_buf, the handshake
 * and keep-alive in work items, tty_set_termios for the speed, a misc
 * device for the readings) is included verbatim, as a hack file does; the
 * hack's init gives the board's part first — input port 1's TX buffer
 * enabled and UART1 registered as /dev/ttyS1 (mach/serial.h) — then runs
 * the driver's init.  The test attaches the discipline the way user space
 * does, TIOCSETD on the opened tty, and host_sim's EV3 colour sensor goes
 * through its whole introduction at 2400 baud, the switch to 57600 and
 * its data, a mode change, and seconds of keep-alive.
 */
#define KBUILD_MODNAME "ev3_uart"
#define LX_HACK_DRIVER_INIT uart_ldisc_init
#define LX_HACK_DRIVER_EXIT uart_ldisc_exit
#include "ev3_uart.c"

#include "driver_common.h"

#include "lx_log_test.h"
#include <linux/delay.h>
#include <linux/gpio.h>
#include <mach/da8xx.h>
#include <mach/irqs.h>
#include <mach/serial.h>
#include <linux_compat/devfs.h>
#include "host_sim/board.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/ev3_ports.h"
#include "host_sim/devices/uart_sensor.h"

#define PORT1_TX_BUFFER	GPIO_TO_PIN(8, 11)      /* low: input port 1's TX buffer on (EV3 EP2 board) */

static const struct davinci_uart_port port1_uart = {
	.line = 1, .mapbase = DA8XX_UART1_BASE, .irq = IRQ_DA8XX_UARTINT1,
	.uartclk = 132000000,                   /* ASYNC3 from PLL1, as LEGO's kernel sets it */
};

/* The board file's part (port 1's UART as ttyS1, its TX buffer on), then the driver. */
static int __init hack_init(void)
{
	int ret = gpio_request_one(PORT1_TX_BUFFER, GPIOF_OUT_INIT_LOW, "in1 tx buffer");

	if (!ret)
		ret = davinci_serial_add(&port1_uart);
	return ret ? ret : uart_ldisc_init();
}
module_init(hack_init);

static void __exit hack_exit(void)
{
	uart_ldisc_exit();
	davinci_serial_del(1);
	gpio_free(PORT1_TX_BUFFER);
}
module_exit(hack_exit);

static void body(void)
{
	static const struct uart_sensor_scene scene = { .reflect_pct = 37, .color = 5 };
	struct uart_sensor *sensor;
	struct ev3_uart_reading r = { 0 };
	struct ev3_uart_info info = { 0 };
	struct file *tty = NULL, *dev = NULL;
	int disc = N_DEVELOPMENT, got = -1, i, mode;
	uint32_t resets;

	/* plugged in once the system runs: its power-up timing starts now */
	is_int(ev3_attach_uart_sensor(0, UART_SENSOR_TYPE_COLOR, NULL), E_OK, "EV3 colour sensor on input port 1");
	is_int(ev3_set_scene(0, &scene), E_OK, "reflecting 37 %%, red");
	sensor = ev3_input_uart_sensor(0);
	is_int(lx_dev_open("/dev/ttyS1", O_RDWR, &tty), 0, "open /dev/ttyS1");
	if (!tty)
		return;
	is_int(lx_dev_open("/dev/ttyS0", O_RDWR, &dev), -ENODEV, "ttyS0 has no UART on this board: -ENODEV");
	is_int((int)lx_dev_ioctl_kernel(tty, TIOCGETD, &got), 0, "TIOCGETD");
	is_int(got, N_TTY, "a tty starts with N_TTY");
	is_int((int)lx_dev_ioctl_kernel(tty, TIOCSETD, &disc), 0, "TIOCSETD N_DEVELOPMENT, as user space attaches it");
	ok(lx_dev_exists("ev3_uart_ttyS1"), "the discipline's /dev/ev3_uart_ttyS1");
	is_int(lx_dev_open("/dev/ev3_uart_ttyS1", O_RDONLY, &dev), 0, "open it");
	if (!dev)
		return;
	is_int((int)lx_dev_ioctl_kernel(dev, EV3_UART_SET_MODE, &(int){ 1 }), -EAGAIN,
	       "no mode change before the sensor has introduced itself: -EAGAIN");

	is_int((int)lx_dev_read(dev, (char __user *)&r, sizeof(r), NULL), (int)sizeof(r),
	       "a blocking read returns the first data frame");
	is_int((int)lx_dev_ioctl_kernel(dev, EV3_UART_INFO, &info), 0, "EV3_UART_INFO");
	ok(info.type == 29 && info.modes == 6 && info.speed == 57600,
	   "the colour sensor's introduction: type 29, 6 modes, 57600 baud (%u, %u, %u)",
	   info.type, info.modes, info.speed);
	ok(!strcmp(info.name[0], "COL-REFLECT") && !strcmp(info.name[2], "COL-COLOR"),
	   "mode names from the INFO messages (%s, %s)", info.name[0], info.name[2]);
	is_int((int)uart_sensor_baud(sensor), 57600, "the sensor runs at 57600 after the discipline's ACK");
	ok(r.mode == 0 && r.datasets == 1 && r.value[0] == 37, "COL-REFLECT: one value, the scene's 37 %% (mode %u, %u values, %d)",
	   r.mode, r.datasets, r.value[0]);

	mode = 2;
	is_int((int)lx_dev_ioctl_kernel(dev, EV3_UART_SET_MODE, &mode), 0, "EV3_UART_SET_MODE 2");
	for (i = 0; i < 50 && r.mode != 2; i++)
		(void)lx_dev_read(dev, (char __user *)&r, sizeof(r), NULL);
	ok(r.mode == 2 && r.value[0] == 5, "COL-COLOR frames follow: colour 5, red (mode %u, %d)", r.mode, r.value[0]);
	is_int((int)uart_sensor_mode(sensor), 2, "the sensor switched to mode 2");

	resets = uart_sensor_get_stats(sensor)->resets;
	msleep(3000);
	ok(uart_sensor_get_stats(sensor)->resets == resets && uart_sensor_get_state(sensor) == UART_SENSOR_DATA,
	   "three seconds later the keep-alive NACKs have kept it streaming (resets %u)",
	   uart_sensor_get_stats(sensor)->resets);
	ok(uart_sensor_get_stats(sensor)->nacks >= 25, "about one NACK every 100 ms (%u)",
	   uart_sensor_get_stats(sensor)->nacks);
	(void)lx_dev_read(dev, (char __user *)&r, sizeof(r), NULL);
	ok(r.frames > 25, "a COL-COLOR frame after each NACK: frames counted (%u)", r.frames);

	lx_dev_close(dev);
	disc = N_TTY;
	is_int((int)lx_dev_ioctl_kernel(tty, TIOCSETD, &disc), 0, "TIOCSETD N_TTY");
	ok(!lx_dev_exists("ev3_uart_ttyS1"), "the discipline's device went with it");
	lx_dev_close(tty);
}

int main(void)
{
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	tap_plan(26);
	is_int(hs_board_init(&board), E_OK, "host_sim EV3 board");
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}

/*
 * lms_suart26_hack.c — the genuine 2.6-era module lms_suart26 included
 * verbatim; its interface for the test, in C types only.
 */
#define KBUILD_MODNAME "lms_suart26"
#define LX_HACK_DRIVER_INIT lms_suart26_driver_init
#define LX_HACK_DRIVER_EXIT lms_suart26_driver_exit

#include "drivers/lms_suart26.c"

#include <linux_compat/hack.h>
#include <linux_compat/firmware.h>
#include <mach/irqs.h>
#include "lms_suart26_hack.h"

/* The board's soft-UART device, laid out as TI's DaVinci 2.6.33 board code
 * (devices-da8xx.c, da8xx_register_pru_suart) declares it. */
static struct resource board_suart_resources[] = {
	{ .start = 0x01C30000, .end = 0x01C30000 + 0xFFFF, .flags = IORESOURCE_MEM },          /* PRUSS */
	{ .start = 0x01D00000, .end = 0x01D00000 + SZ_1K * 12 - 1, .flags = IORESOURCE_MEM },  /* McASP0 */
	{ .start = 0x01C10000, .end = 0x01C10000 + SZ_1K * 3 - 1, .flags = IORESOURCE_MEM },   /* PSC0 */
	{ .start = 0x01E27000, .end = 0x01E27000 + SZ_1K * 3 - 1, .flags = IORESOURCE_MEM },   /* PSC1 */
	{ .start = 0x80000000, .end = 0x80000000 + SZ_1K * 8 - 1, .flags = IORESOURCE_MEM },   /* shared RAM */
	{ .start = IRQ_DA8XX_EVTOUT0, .end = IRQ_DA8XX_EVTOUT0, .flags = IORESOURCE_IRQ },
};

static struct ti_pru_suart_platform_data board_suart_pdata = { .version = 1 };

/* Static board devices are never freed. */
static void board_suart_release(struct device *dev)
{
}

static struct platform_device board_suart_device = {
	.name = "ti_omapl_pru_suart", .id = 1,
	.num_resources = ARRAY_SIZE(board_suart_resources), .resource = board_suart_resources,
	.dev = { .platform_data = &board_suart_pdata, .release = board_suart_release },
};

/* The PRU image the board ships; the model does not execute PRU code, any non-empty image serves. */
static const unsigned int board_suart_image[16] = { 0x2EFF8180U, 0x24000080U };

int lms_suart26_board(int present)
{
	int ret = 0;

	if (present) {
		ret = lx_firmware_add("PRU_SUART.bin", board_suart_image, sizeof(board_suart_image));
		if (ret == 0)
			ret = platform_device_register(&board_suart_device);
	} else {
		platform_device_unregister(&board_suart_device);
		ret = lx_firmware_remove("PRU_SUART.bin");
	}
	return ret;
}

int lms_suart26_missing_firmware(void)
{
	const struct firmware *fw = (const struct firmware *)1;
	int ret = request_firmware(&fw, "no_such.bin", NULL);

	return fw == NULL ? ret : 0;
}

int lms_suart26_load(void)
{
	return lms_suart26_driver_init();
}

void lms_suart26_unload(void)
{
	lms_suart26_driver_exit();
}

void lms_suart26_set_baud(unsigned int baud)
{
	SuartSetBaud(baud);
}

int lms_suart26_write(const unsigned char *data, int size)
{
	return SuartWrite(data, size);
}

int lms_suart26_read(unsigned char *data, int size)
{
	return SuartRead(data, size);
}

unsigned int lms_suart26_timeout(void)
{
	return SuartTimeout();
}

int lms_suart26_tx_idle(void)
{
	return SuartTxIdle() != 0;
}

void lms_suart26_counts(int *irqs, int *halves, int *timeouts)
{
	*irqs = SuartIrqs;
	*halves = SuartHalves;
	*timeouts = SuartTimeouts;
}

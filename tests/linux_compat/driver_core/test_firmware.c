/*
 * test_firmware.c — request_firmware from the board's table (linux/firmware.h,
 * linux_compat/firmware.h): a registered blob is handed out by name without a
 * copy, a missing one is -ENOENT with Linux's message (none with
 * firmware_request_nowarn), a held blob cannot be removed until released,
 * names are unique, the table is bounded, bad arguments are -EINVAL.
 */
#define KBUILD_MODNAME "fwtest"
#include "lx_log_test.h"
#include <linux/errno.h>
#include <linux/firmware.h>
#include <linux_compat/firmware.h>
#include "host_sim/board.h"

static const unsigned char blob[] = { 1, 2, 3, 4, 5 };

static void body(void)
{
	const struct firmware *fw = NULL, *fw2 = NULL;
	char name[16];
	int i;

	is_int(lx_firmware_add("test.bin", blob, sizeof(blob)), 0, "a blob registered as test.bin");
	is_int(lx_firmware_add("test.bin", blob, 1), -EEXIST, "the name again: -EEXIST");
	is_int(request_firmware(&fw, "test.bin", NULL), 0, "request_firmware(test.bin)");
	ok(fw && fw->data == blob && fw->size == sizeof(blob), "its data is the table's, its size the blob's");
	is_int(request_firmware(&fw2, "test.bin", NULL), 0, "a second holder");
	is_int(lx_firmware_remove("test.bin"), -EBUSY, "held: cannot be removed");
	release_firmware(fw);
	release_firmware(fw2);
	release_firmware(NULL);
	is_int(lx_firmware_remove("test.bin"), 0, "released by both: removed");
	is_int(lx_firmware_remove("test.bin"), -ENOENT, "removing it again: -ENOENT");

	dc_log_start();
	fw = (const struct firmware *)blob;
	is_int(request_firmware(&fw, "test.bin", NULL), -ENOENT, "request_firmware of a missing name: -ENOENT");
	ok(fw == NULL, "and *fw is NULL");
	ok(dc_logged("Direct firmware load for test.bin failed with error -2"), "with Linux's message");
	dc_log_start();
	is_int(firmware_request_nowarn(&fw, "test.bin", NULL), -ENOENT, "firmware_request_nowarn: -ENOENT");
	ok(!dc_logged("test.bin"), "without a message");

	is_int(request_firmware(NULL, "x", NULL), -EINVAL, "no fw pointer: -EINVAL");
	is_int(request_firmware(&fw, "", NULL), -EINVAL, "an empty name: -EINVAL");
	is_int(lx_firmware_add("x", NULL, 1), -EINVAL, "no data: -EINVAL");
	for (i = 0; i < LX_FIRMWARE_ENTRIES; i++) {
		snprintf(name, sizeof(name), "fw%d", i);
		if (lx_firmware_add(name, blob, 1) != 0)
			break;
	}
	is_int(i, LX_FIRMWARE_ENTRIES, "the table holds LX_FIRMWARE_ENTRIES blobs");
	is_int(lx_firmware_add("one_more", blob, 1), -ENOSPC, "one more: -ENOSPC");
	for (i = 0; i < LX_FIRMWARE_ENTRIES; i++) {
		snprintf(name, sizeof(name), "fw%d", i);
		lx_firmware_remove(name);
	}
}

int main(void)
{
	tap_plan(20);
	is_int(hs_board_init(NULL), E_OK, "host_sim board");
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}

/*
 * boot_refusal_test.h — booting a configuration the host kernel must refuse.
 * The refusal's message goes to stderr by design (a user's bad configuration
 * must say what is wrong); a test of the refusal captures it, so that the
 * suite's output shows only messages nobody expected, and checks that it is
 * the boot error the kernel reports.  The including test defines
 * _POSIX_C_SOURCE 200809L before its first include (stderr_capture.h).
 */
#ifndef EV3LX_TESTS_BOOT_REFUSAL_TEST_H
#define EV3LX_TESTS_BOOT_REFUSAL_TEST_H

#include <string.h>
#include "rtos_host.h"
#include "stderr_capture.h"
#include "tap.h"

/* Boots cfg, which must be refused: its error code; false in *said_so unless
 * stderr got exactly "rtos_host_boot: <the boot error>". */
static inline ER rt_boot_refused(const struct rtos_cfg *cfg, bool *said_so)
{
	struct stderr_capture cap;
	char want[600];
	const char *got;
	ER ercd;

	stderr_capture_begin(&cap);
	ercd = rtos_host_boot(cfg);
	got = stderr_capture_end(&cap);
	snprintf(want, sizeof(want), "rtos_host_boot: %s\n", rtos_host_boot_error());
	if (strcmp(got, want) != 0) {
		*said_so = false;
		tap_diag("  boot of %s: stderr \"%s\", expected \"%s\"", cfg->name ? cfg->name : "?", got, want);
	}
	return ercd;
}

#endif /* EV3LX_TESTS_BOOT_REFUSAL_TEST_H */

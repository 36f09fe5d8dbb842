/*
 * board.c — creating and tearing down the simulated AM1808: the core
 * peripherals, the device models of the configuration, the MMIO handler in
 * rtos_stub and the pointer-access trap.  Host only.
 */
#include <string.h>

#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/regs.h"
#include "../core/core_parts.h"
#include "../core/space_internal.h"
#include "soc_parts.h"

#define MAX_DEVICES 32U

static struct {
	bool active;
	bool started;
	bool traps;
	struct hs_board_cfg cfg;
	struct {
		const struct hs_device *dev;
		void *ctx;
	} devices[MAX_DEVICES];
	unsigned ndevices;
} board;

/* Creates one device model and remembers it. */
static ER device_create(const struct hs_device *dev)
{
	void *ctx = NULL;
	ER er;

	if (!dev || !dev->name || !dev->create) {
		rtos_host_bug("host_sim", "hs_board: a device needs a name and a create function");
		return E_PAR;
	}
	if (board.ndevices == MAX_DEVICES) {
		rtos_host_bug("host_sim", "hs_board: more than %u devices", MAX_DEVICES);
		return E_NOMEM;
	}
	er = dev->create(&board.cfg, &ctx);
	if (er != E_OK) {
		rtos_host_bug("host_sim", "hs_board: device %s failed to create (error %d)", dev->name, (int)er);
		return er;
	}
	board.devices[board.ndevices].dev = dev;
	board.devices[board.ndevices].ctx = ctx;
	board.ndevices++;
	return E_OK;
}

/* Creates the core peripherals in dependency order (PSC and SYSCFG before GPIO). */
static ER core_create(bool cold)
{
	ER er = hs_psc_create(cold);

	if (er == E_OK)
		er = hs_syscfg_create(cold);
	if (er == E_OK)
		er = hs_pllc_create(cold);
	if (er == E_OK)
		er = hs_aintc_create(cold);
	if (er == E_OK)
		er = hs_timer64p3_create(cold);
	if (er == E_OK)
		er = hs_timer64p1_create(cold);
	if (er == E_OK)
		er = hs_gpio_create(cold, !board.cfg.no_pinmux_check);
	return er;
}

ER hs_board_init(const struct hs_board_cfg *cfg)
{
	ER er;

	if (board.active)
		return E_OBJ;
	memset(&board, 0, sizeof(board));
	if (cfg)
		board.cfg = *cfg;
	if (!board.cfg.access_ns)
		board.cfg.access_ns = HS_ACCESS_NS_DEFAULT;
	if (hs_space_init(board.cfg.access_ns) != 0) {
		rtos_host_bug("host_sim", "hs_board_init: cannot reserve the register window space");
		return E_NOMEM;
	}
	board.active = true;
	er = core_create(board.cfg.cold_reset);
	for (unsigned i = 0; er == E_OK && board.cfg.devices && board.cfg.devices[i]; i++)
		er = device_create(board.cfg.devices[i]);
	if (er != E_OK) {
		hs_board_shutdown();
		return er;
	}
	hs_space_install_handler();
	board.traps = !board.cfg.no_trap && hs_trap_install();
	return E_OK;
}

ER hs_board_add_device(const struct hs_device *dev)
{
	ER er;

	if (!board.active)
		return E_OBJ;
	er = device_create(dev);
	if (er == E_OK && board.started && dev->start)
		dev->start(board.devices[board.ndevices - 1U].ctx);
	return er;
}

void hs_board_start(void)
{
	if (!board.active || board.started)
		return;
	board.started = true;
	for (unsigned i = 0; i < board.ndevices; i++)
		if (board.devices[i].dev->start)
			board.devices[i].dev->start(board.devices[i].ctx);
}

void hs_board_shutdown(void)
{
	if (!board.active)
		return;
	for (unsigned i = board.ndevices; i-- > 0;)
		if (board.devices[i].dev->destroy)
			board.devices[i].dev->destroy(board.devices[i].ctx);
	hs_trace_reset();
	hs_trap_remove();
	hs_space_remove_handler();
	hs_gpio_destroy();
	hs_timer64p3_destroy();
	hs_timer64p1_destroy();
	hs_aintc_destroy();
	hs_syscfg_destroy();
	hs_psc_destroy();
	hs_space_fini();
	memset(&board, 0, sizeof(board));
}

bool hs_board_active(void)
{
	return board.active;
}

const struct hs_board_cfg *hs_board_config(void)
{
	return board.active ? &board.cfg : NULL;
}

bool hs_board_traps_pointers(void)
{
	return board.active && board.traps;
}

const char *hs_board_trap_unavailable_reason(void)
{
	if (board.active && board.cfg.no_trap)
		return "trapping disabled by the board configuration (no_trap)";
	return hs_trap_reason();
}

/*
 * i2c.h — the AM1808's I2C controllers I2C0 and I2C1 as bus masters, and
 * the slaves a board or a test connects to their buses.  Host only.
 *
 * Registers (AM1808 TRM, "Inter-Integrated Circuit (I2C) Module"): ICOAR
 * 0x00, ICIMR 0x04, ICSTR 0x08, ICCLKL 0x0C, ICCLKH 0x10, ICCNT 0x14, ICDRR
 * 0x18, ICSAR 0x1C, ICDXR 0x20, ICMDR 0x24, ICIVR 0x28, ICEMDR 0x2C, ICPSC
 * 0x30, REVID1/2 0x34/0x38, ICPFUNC..ICPDCLR 0x48..0x5C (stored only).
 * Modelled: master transmitter and receiver, 7-bit addresses.  ICMDR.IRS = 0
 * holds the module in reset (ICSTR back to XSMT | ICXRDY, bus free).
 * ICMDR.STT starts (or, while the module holds the bus after ARDY, restarts)
 * a transfer: the address to ICSAR's slave, then ICCNT bytes (RM = 1: until
 * STP) from ICDXR (TRX = 1, each ACKed or NACKed by the slave) or into
 * ICDRR (TRX = 0, each ACKed by the master but the last); a byte to send
 * waits for ICDXR (ICXRDY set), a byte received waits while ICDRR is still
 * full (ICRRDY: SCL is held, nothing is overrun).  At the count's end STP
 * gives a STOP (BB and MST clear, SCD set), else ARDY with the bus held.
 * A NACK sets NACK and waits for STP.  Each byte takes 9 SCL periods of
 * (ICCLKL + d) + (ICCLKH + d) cycles of the module clock / (ICPSC + 1), d =
 * 7, 6, 5 for ICPSC 0, 1, more; START and STOP one period each.  ICIVR
 * returns the highest-priority enabled flag (1 AL, 2 NACK, 3 ARDY, 4 ICRRDY,
 * 5 ICXRDY, 6 SCD) and clears it, except ICRRDY (cleared by reading ICDRR)
 * and ICXRDY (by writing ICDXR); ICSTR's flags are write-1-to-clear.  The
 * interrupt line (I2CINT0 15, I2CINT1 51) is high while an ICIMR-enabled
 * flag is set.  Module clocks: I2C0 the 24 MHz oscillator (PLL0 AUXCLK),
 * I2C1 ASYNC3 (132 MHz on the EV3); I2C1 is PSC1 module 11.
 */
#ifndef HOST_SIM_DEVICES_I2C_H
#define HOST_SIM_DEVICES_I2C_H

#include <stdbool.h>
#include <stdint.h>
#include "host_sim/board.h"

#define HS_I2C_BUSES		2U
#define HS_I2C0_BASE		0x01C22000U
#define HS_I2C1_BASE		0x01E28000U
#define HS_I2C0_INTNO		15U
#define HS_I2C1_INTNO		51U
#define HS_I2C_MAX_SLAVES	4U

/* A slave on a bus: called in virtual time as the master reaches it. */
struct hs_i2c_slave_ops {
	/* START (or repeated START) with this slave's address: ACK (true) or NACK. */
	bool (*start)(void *ctx, bool read);
	/* A byte the master wrote: ACK or NACK. */
	bool (*write)(void *ctx, uint8_t byte);
	/* The next byte the master reads. */
	uint8_t (*read)(void *ctx);
	/* STOP (may be NULL). */
	void (*stop)(void *ctx);
};

/* Connects a slave at 7-bit address addr on bus (0: I2C0, 1: I2C1), before or
 * after the controller exists.  E_ID bad bus, E_PAR bad address, E_OBJ the
 * address is taken, E_NOMEM no slot. */
ER hs_i2c_attach(unsigned bus, uint8_t addr, const struct hs_i2c_slave_ops *ops, void *ctx);
/* Disconnects the slave at addr, if any. */
void hs_i2c_detach(unsigned bus, uint8_t addr);

/* A register-file slave (an EEPROM's or a sensor's): the first byte written
 * after the address sets the pointer, later ones are stored there, reads
 * return from it; the pointer increments, wrapping at 256. */
struct hs_i2c_regfile {
	uint8_t regs[256];
	uint8_t pointer;
	bool pointer_next;          /* the next byte written is the pointer */
};
extern const struct hs_i2c_slave_ops hs_i2c_regfile_ops;

/* The next count address phases on bus lose arbitration (ICSTR.AL, the
 * module leaves master mode), as another master would win them. */
void hs_i2c_lose_arbitration(unsigned bus, unsigned count);

struct hs_i2c_stats {
	uint32_t starts, repeated_starts, stops;
	uint32_t address_nacks, bytes_written, bytes_read, data_nacks;
	uint32_t arbitration_lost;
	uint32_t scl_period_ns;     /* of the last transfer */
};
/* The bus's counters (zero if the controller does not exist). */
struct hs_i2c_stats hs_i2c_get_stats(unsigned bus);

/* The board devices creating the controllers (no board adds them by default). */
extern const struct hs_device hs_i2c0_device;
extern const struct hs_device hs_i2c1_device;

#endif /* HOST_SIM_DEVICES_I2C_H */

/*
 * test_pru_suart.c — the PRU soft UART model at its registers: the PRU
 * INTC's events through CMR and HMR to PRU_EVTOUT0 (AINTC line 3), GER, HIER
 * and the enables; CONTROL's RUNSTATE; a transmit request's bytes at the
 * McASP transmit clock times the channel's prescaler, then COMPLETE and
 * the channel's event; reception into the double FIFO (an event per half,
 * the FIFO index bit), the idle time-out, a break, a sender at the wrong
 * speed, and nothing received while the serializer is inactive or the PRU
 * halted.
 */
#include "devtest.h"
#include "host_sim/intc.h"
#include "host_sim/devices/pru_suart.h"

#define PRU        HS_PRUSS_BASE
#define MCASP      HS_MCASP0_BASE
#define SRAM       HS_SHARED_RAM_BASE
#define INTC       (PRU + 0x4000U)
#define SISR       (INTC + 0x20U)
#define SICR       (INTC + 0x24U)
#define EISR       (INTC + 0x28U)
#define EICR       (INTC + 0x2CU)
#define HIEISR     (INTC + 0x34U)
#define SECR1      (INTC + 0x284U)
#define CMR(n)     (INTC + 0x400U + 4U * (n))
#define HMR(n)     (INTC + 0x800U + 4U * (n))
#define GER        (INTC + 0x10U)
#define CONTROL    (PRU + 0x7000U)
#define CH(n, r)   (PRU + 16U * (n) + (r))
#define IMR        (PRU + 0x80U)
#define ISR        (PRU + 0x82U)
#define TIMEOUT    (PRU + 0x88U)
#define EVTOUT0    3U

static uint8_t sent[64];
static uint64_t sent_at[64];
static unsigned nsent;
static uint32_t sent_baud;

static void capture(void *ctx, unsigned ser, uint8_t byte, uint32_t baud)
{
	(void)ctx;
	if (ser == 3U && nsent < 64U) {
		sent_at[nsent] = hs_now();
		sent[nsent++] = byte;
		sent_baud = baud;
	}
}

static uint8_t rd8(uint32_t phys)
{
	return sil_reb_mem(rtos_host_map_io(phys, 1));
}

static void wr8(uint32_t phys, uint8_t v)
{
	sil_wrb_mem(rtos_host_map_io(phys, 1), v);
}

/* The INTC, McASP clocks and the two channels of soft UART 1 as TI's driver sets them; PRU0 running. */
static void setup(void)
{
	hs_psc_force(HS_PSC0_MODULE(HS_LPSC0_PRU), HS_PSC_ENABLE);
	hs_psc_force(HS_PSC1_MODULE(HS_LPSC1_MCASP0), HS_PSC_ENABLE);
	wr32(MCASP + 0xB4, 0x8000U | 208U);     /* AHCLKXCTL: 24 MHz / 209 */
	wr32(MCASP + 0xB0, 0xE0U);
	wr32(MCASP + 0x74, 0x8000U | 25U);      /* AHCLKRCTL: 24 MHz / 26, 8 samples a bit */
	wr32(MCASP + 0x70, 0xA0U);
	wr32(MCASP + 0x180 + 4U * 1U, 0x0EU);   /* SRCTL1: receive */
	wr32(GER, 1);
	wr32(HMR(0), 0x03020100U);
	wr32(CMR(8), 0x02020100U);              /* events 34, 35: channel 2 -> host 2 = PRU_EVTOUT0 */
	wr32(HIEISR, 2);
	wr32(EISR, 34);
	wr32(EISR, 35);
	wr16(CH(0, 0), 3U << 8 | 1U);           /* TX on serializer 3 */
	wr16(CH(0, 2), 48);                     /* prescaler 48 */
	wr16(CH(0, 4), 10);                     /* 10 bits a character */
	wr16(CH(1, 0), 1U << 8 | 2U);           /* RX on serializer 1 */
	wr16(CH(1, 2), 48);
	wr16(CH(1, 4), 15U << 8 | 10U);         /* halves of 16 bytes */
	wr32(CH(1, 8), SRAM + 0x100U);
	wr16(IMR, 0x3);
	wr16(TIMEOUT, 1152);                    /* 1152 receive frames of 8.67 us: 10 ms */
	wr32(PRU + 0x8000U, 0x12345678U);       /* some code in the instruction RAM */
	wr32(CONTROL, 0xA);
}

static void request(unsigned ch, uint16_t mode)
{
	wr16(CH(ch, 0), (uint16_t)((rd16(CH(ch, 0)) & ~7U) | mode | 4U));
	wr32(SISR, 32);
}

static void intc_checks(void)
{
	wr32(SISR, 34);
	ok(hs_intc_pending(EVTOUT0) && (rd32(SECR1) & 0x4U), "event 34 -> channel 2 -> host 2: PRU_EVTOUT0 (AINTC 3)");
	wr32(GER, 0);
	ok(!hs_intc_pending(EVTOUT0), "GER off: the line drops");
	wr32(GER, 1);
	wr32(EICR, 34);
	ok(!hs_intc_pending(EVTOUT0) && (rd32(SECR1) & 0x4U), "EICR 34: disabled, still pending in SECR1");
	wr32(EISR, 34);
	wr32(SICR, 34);
	ok(!hs_intc_pending(EVTOUT0) && !(rd32(SECR1) & 0x4U), "SICR 34 clears it");
	ok(rd32(CONTROL) & 0x8000U, "CONTROL.RUNSTATE while ENABLE");
}

static void tx_checks(void)
{
	uint64_t t0;

	wr8(SRAM, 0x40);
	wr8(SRAM + 1, 0x1D);
	wr8(SRAM + 2, 0xA2);
	wr16(CH(0, 4), (uint16_t)(2U << 8 | 10U));
	wr32(CH(0, 8), SRAM);
	t0 = hs_now();
	request(0, 1);
	ok(rd8(CH(0, 6)) & 0x01 && !(rd16(CH(0, 0)) & 4U) && (rd8(CH(0, 7)) & 0x80),
	   "TX request: SR cleared, READY and channel-active set");
	hs_sim_run_for(20 * MS);
	ok(nsent == 3 && sent[0] == 0x40 && sent[2] == 0xA2, "DATALEN + 1 = 3 bytes from the shared RAM, in order");
	is_int((int)sent_baud, 2392, "at 24 MHz / 209 / 48");
	ok(nsent == 3 && sent_at[2] - t0 > 12500000U && sent_at[2] - t0 < 12600000U,
	   "three 10-bit characters: %.2f ms", nsent == 3 ? (double)(sent_at[2] - t0) / 1e6 : 0.0);
	ok((rd8(CH(0, 6)) & 0x03) == 0x02 && (rd16(ISR) & 1U) && (rd32(SECR1) & 0x4U) && hs_intc_pending(EVTOUT0),
	   "done: COMPLETE, READY cleared, ISR bit 0 and event 34");
	wr32(SICR, 34);
	wr16(ISR, 0);
	wr16(IMR, 0x2);
	request(0, 1);
	hs_sim_run_for(20 * MS);
	ok(!(rd32(SECR1) & 0x4U) && !(rd16(ISR) & 1U), "with its IMR bit clear the channel raises nothing");
	wr16(IMR, 0x3);
}

static void rx_checks(struct hs_pru_suart *s)
{
	unsigned n;

	request(1, 2);
	ok((rd8(CH(1, 6)) & 0x01) && (rd8(CH(1, 7)) & 0x80), "RX request: READY, channel active");
	for (n = 0; n < 16; n++)
		hs_pru_suart_rx_byte(s, 1, (uint8_t)(0x80U + n), 2400);
	ok((rd32(SECR1) & 0x8U) && !(rd8(CH(1, 6)) & 0x02) && rd8(SRAM + 0x100) == 0x80 && rd8(SRAM + 0x10F) == 0x8F,
	   "16 bytes: the first half, event 35, FIFO index clear");
	wr32(SICR, 35);
	for (n = 0; n < 16; n++)
		hs_pru_suart_rx_byte(s, 1, (uint8_t)n, 2400);
	ok((rd32(SECR1) & 0x8U) && (rd8(CH(1, 6)) & 0x02) && rd8(CH(1, 12)) == 0 && rd8(SRAM + 0x11F) == 15,
	   "32: the second half, FIFO index set, the counter back to 0");
	wr32(SICR, 35);
	wr16(CH(1, 2), (uint16_t)(rd16(CH(1, 2)) | 0x4000U));
	for (n = 0; n < 3; n++)
		hs_pru_suart_rx_byte(s, 1, 0x55, 2400);
	hs_sim_run_for(9 * MS);
	ok(!(rd32(SECR1) & 0x8U), "3 bytes: no event before the time-out");
	hs_sim_run_for(2 * MS);
	ok((rd32(SECR1) & 0x8U) && (rd8(CH(1, 6)) & 0x40) && rd8(CH(1, 12)) == 3 && !(rd16(CH(1, 2)) & 0x4000U),
	   "10 ms idle: TIMEOUT, 3 bytes counted, its enable cleared");
	wr32(SICR, 35);
	wr8(CH(1, 12), 0);
	request(1, 2);
	ok(!(rd8(CH(1, 6)) & 0x40), "a new request clears TIMEOUT");
	hs_pru_suart_rx_byte(s, 1, 0x55, 57600);
	ok(rd8(SRAM + 0x100) != 0x55 && hs_pru_suart_get_stats(s)->rx_garbled == 1, "a 57600-baud byte at 2400 is garbled");
	wr16(CH(1, 2), (uint16_t)(rd16(CH(1, 2)) | 0x2000U));
	wr16(IMR, (uint16_t)(rd16(IMR) | 0x200U));
	hs_pru_suart_rx_line(s, 1, false);
	hs_sim_run_for(5 * MS);
	hs_pru_suart_rx_line(s, 1, true);
	ok((rd8(CH(1, 6)) & 0x24) == 0x24 && (rd16(ISR) & 0x200U) && (rd32(SECR1) & 0x8U),
	   "the line low a character time: BI and ERR, global error bit, the event");
	wr32(SICR, 35);
	wr32(MCASP + 0x180 + 4U * 1U, 0x0CU);
	n = hs_pru_suart_get_stats(s)->rx_bytes;
	hs_pru_suart_rx_byte(s, 1, 0x11, 2400);
	ok(hs_pru_suart_get_stats(s)->rx_bytes == n, "serializer inactive: nothing received");
	request(1, 2);
	ok((rd32(MCASP + 0x180 + 4U * 1U) & 3U) == 2U, "a receive request re-activates the serializer, as the firmware does");
	wr32(CONTROL, 0);
	hs_pru_suart_rx_byte(s, 1, 0x11, 2400);
	ok(hs_pru_suart_get_stats(s)->rx_bytes == n && !(rd32(CONTROL) & 0x8000U), "PRU0 halted: nothing received");
}

int main(void)
{
	struct hs_pru_suart *s;

	tap_plan(24);
	devtest_boot(3, NULL);
	s = hs_pru_suart();
	ok(s != NULL, "the EV3 board has the PRU soft UART");
	hs_pru_suart_set_peer(s, &(struct hs_pru_suart_peer){ capture, NULL });
	setup();
	intc_checks();
	tx_checks();
	rx_checks(s);
	ok(rtos_host_bug_count() == 0, "no bug reports");
	hs_sim_shutdown();
	return tap_done();
}

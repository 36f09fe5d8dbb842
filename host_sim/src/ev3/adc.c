/*
 * adc.c — the EV3's analog-to-digital converter, a TI ADS7957 in manual
 * mode on SPI0 (spi_adc.h; ADS7957 data sheet, "Manual mode"): each frame
 * shifts out the conversion of the channel selected two frames before.
 * The voltages come from the board's analog front end (ev3_adc_channel_source).
 */
#include <math.h>
#include "rtos_host.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/spi_adc.h"

#define ADS7957_CHANNELS 16U

static struct {
	unsigned next;              /* channel selected by the previous frame */
	uint16_t result;            /* conversion shifted out in the next frame */
	bool range_5v;
	const double *noise_mv;     /* the board's ADC noise (ev3_adc_noise_mv_ref) */
	struct ev3_adc_source source[ADS7957_CHANNELS];   /* what each channel measures */
} adc;

/* ADS7957 output word for mV of the 0-5 V scale (full scale and above: 1023):
 * channel in 15-12, 10-bit result in 11-2. */
static inline uint16_t ads7957_word_of(unsigned ch, uint64_t mv)
{
	uint32_t code = mv >= 5000U ? 1023U : (uint32_t)((mv * 1023U + 2500U) / 5000U);

	return (uint16_t)(((ch & 0xFU) << 12) | (code << 2));
}

uint16_t ads7957_word(unsigned ch, uint32_t mv)
{
	return ads7957_word_of(ch, mv);
}

/* adc_sample_mv with noise of standard deviation sigma mV: a draw from the
 * board's noise stream, rounded to the nearest mV after scaling and clamping.
 * Out of line: the noise-free path, taken on nearly every frame, then needs
 * no floating-point registers saved. */
static __attribute__((noinline)) uint32_t adc_noisy_sample_mv(uint32_t mv, double sigma)
{
	double noisy = mv + sigma * ev3_adc_noise_sample();

	if (!adc.range_5v)
		noisy *= 2.0;
	noisy = noisy < 0 ? 0 : noisy > 5000 ? 5000 : noisy;
	return (uint32_t)lround(noisy);
}

/* The sampled channel's voltage mv as the converter's input sees it, in mV
 * of its 0-5 V scale: with the board's noise, doubled in the 0-2.5 V range,
 * clamped (noise-free: left to ads7957_word_of, whose code is the same at
 * and above full scale).  Without noise everything is a whole number of mV,
 * so integer arithmetic gives what the rounded floating-point sum gives,
 * cheaper (the ADC samples ten thousand times per second). */
static inline uint64_t adc_sample_mv(uint32_t mv)
{
	if (*adc.noise_mv > 0)
		return adc_noisy_sample_mv(mv, *adc.noise_mv);
	return adc.range_5v ? mv : 2ULL * mv;   /* 0-2.5 V range: full scale at half the voltage */
}

/* The converter's side of one frame starting now: returns what it shifts
 * out, samples the channel selected last frame, then decodes cmd. */
static uint16_t adc_frame(void *ctx, uint16_t cmd)
{
	uint16_t out = adc.result;
	const struct ev3_adc_source *src = &adc.source[adc.next];

	adc.result = ads7957_word_of(adc.next, adc_sample_mv(src->mv(src->arg)));
	if ((cmd & 0xF800U) == 0x1800U) {               /* mode 1 with bit 11: a new channel */
		adc.next = (cmd >> 7) & 0xFU;
		adc.range_5v = cmd & 0x0040U;
	} else if ((cmd >> 13) == 0x1U) {               /* mode 2 or 3 */
		rtos_host_bug("host_sim", "SPI0 ADC: command 0x%04x selects an auto mode, which is not modelled "
			      "(the EV3 uses manual mode)", cmd);
	}
	/* mode 1 without bit 11 keeps the channel; 0x4xxx programs GPIOs, 0x8xxx-0x9xxx auto sequences */
	return out;
}

/* Connects the converter to SPI0 in its power-up state. */
static ER adc_create(const struct hs_board_cfg *cfg, void **ctx)
{
	adc.next = 0;
	adc.result = 0;
	adc.range_5v = true;
	adc.noise_mv = ev3_adc_noise_mv_ref();
	for (unsigned ch = 0; ch < ADS7957_CHANNELS; ch++)
		adc.source[ch] = ev3_adc_channel_source(ch);
	hs_spi_connect(0, &(struct hs_spi_peer){ .frame = adc_frame });
	*ctx = &adc;
	return E_OK;
}

static void adc_destroy(void *ctx)
{
	hs_spi_connect(0, NULL);
}

const struct hs_device ev3_adc_device = { "ADS7957", adc_create, NULL, adc_destroy };

// SPDX-License-Identifier: GPL-2.0
/*
 * d_sound.c - LEGO EV3 speaker (/dev/lms_sound).
 *
 * Interface-compatible with LEGO's lms2012 d_sound (see lms_sound.h).  The speaker is driven by
 * eHRPWM0 output B through an amplifier enabled by a GPIO:
 *   tone  the time base divided by 128 (132 MHz / 128 = 1 031 250 Hz), TBPRD = 1031250 / f - 1,
 *         CMPB = TBPRD * level / 200: the PWM itself makes the square wave; a timed tone ends
 *         with a one-shot hrtimer;
 *   PCM   an undivided time base with TBPRD = 132 MHz / 64 kHz (a 64 kHz carrier, 8 periods per
 *         sample) and a 125 us hrtimer writing CMPB = level * sample for each sample.  When the
 *         timer is served late (a coarse timer tick) the samples that fell due meanwhile are
 *         skipped, so that playback keeps its pace and pitch.  Running dry ends playback.
 * Both modes: CMPB shadowed and loaded at counter zero, AQCTLB = output high at zero, low at
 * CMPB while counting up, so that the duty is CMPB / (TBPRD + 1).  Stopping freezes the counter
 * and switches the amplifier off.
 *
 * Hardware (AM1808 TRM, eHRPWM chapter; LEGO's EV3 board): eHRPWM0 at 0x01F00000 (PSC1 module
 * 17, its time base clocked while SYSCFG0 CFGCHIP1.TBCLKSYNC is set), EPWM0B on PINMUX3[7:4] = 2,
 * amplifier enable GP6_15 (PINMUX13[3:0] = 8 GPIO, high = on).  The module clock is the ASYNC3
 * domain LEGO runs at 132 MHz (module parameter pwm_clock_hz).
 */
#include <linux/module.h>
#include <linux/init.h>
#include <linux/kernel.h>
#include <linux/types.h>
#include <linux/errno.h>
#include <linux/bits.h>
#include <linux/fs.h>
#include <linux/miscdevice.h>
#include <linux/mm.h>
#include <linux/slab.h>
#include <linux/io.h>
#include <linux/delay.h>
#include <linux/ioport.h>
#include <linux/gpio.h>
#include <linux/hrtimer.h>
#include <linux/ktime.h>
#include <linux/spinlock.h>
#include <linux/uaccess.h>

#include "lms_sound.h"

#define GP(bank, bit)		((bank) * 16 + (bit))	/* DaVinci GPIO number */

static int amp_gpio = GP(6, 15);
module_param(amp_gpio, int, 0444);
MODULE_PARM_DESC(amp_gpio, "GPIO of the amplifier enable, high = on (default GP6_15)");

static uint pwm_clock_hz = 132000000;
module_param(pwm_clock_hz, uint, 0444);
MODULE_PARM_DESC(pwm_clock_hz, "eHRPWM0 module clock in Hz (default 132 MHz, as LEGO sets PLL1)");

#define SYSCFG0_PHYS		0x01C14000
#define SYSCFG0_SIZE		0x200
#define SYSCFG0_KICK0R		0x38
#define SYSCFG0_KICK1R		0x3C
#define SYSCFG0_KICK0_KEY	0x83E70B13
#define SYSCFG0_KICK1_KEY	0x95A4F1E0
#define SYSCFG0_PINMUX(n)	(0x120 + 4 * (n))
#define SYSCFG0_CFGCHIP1	0x180
#define CFGCHIP1_TBCLKSYNC	BIT(12)

#define PSC1_PHYS		0x01E27000
#define PSC1_SIZE		0x1000
#define PSC_PTCMD		0x120
#define PSC_PTSTAT		0x128
#define PSC_MDCTL(n)		(0xA00 + 4 * (n))
#define PSC1_LPSC_EHRPWM	17
#define PSC_STATE_ENABLE	3
#define PSC_GO_MASK		3
#define PSC_POLL_LIMIT		1000

#define EHRPWM0_PHYS		0x01F00000
#define EHRPWM_SIZE		0x80
#define EPWM_TBCTL		0x00
#define EPWM_TBPHS		0x06
#define EPWM_TBCNT		0x08
#define EPWM_TBPRD		0x0A
#define EPWM_CMPCTL		0x0E
#define EPWM_CMPB		0x14
#define EPWM_AQCTLB		0x18

#define TBCTL_PCM		0xC030	/* up-count, free run, no prescale, sync-out off */
#define TBCTL_TONE		0xDC30	/* the same with CLKDIV /128 */
#define TBCTL_STOP		0xC033	/* counter frozen */
#define TONE_DIVIDER		128
#define AQCTLB_HIGH_ZERO_LOW_CMPB 0x0102
#define PCM_CARRIER_HZ		64000
#define SAMPLE_NS		(NSEC_PER_SEC / LMS_SOUND_RATE)

#define PINMUX3_EPWM0B_SHIFT	4
#define PINMUX3_EPWM0B		2
#define PINMUX13_GP6_15_SHIFT	0
#define PINMUX_GPIO		8

#define TONE_CMD_LEN		6
#define PLAY_CMD_LEN		2

struct sound_slot {
	u16 sample[LMS_SOUND_SLOT_SAMPLES];
	u8 count;			/* samples queued; 0 = free */
};

enum sound_mode { SOUND_IDLE, SOUND_TONE, SOUND_PCM };

static struct {
	u8 __iomem *syscfg0;
	u8 __iomem *psc1;
	u8 __iomem *pwm;
	u8 *status;			/* the shared page; byte 0 is the status */
	spinlock_t lock;		/* everything below: file ops and the timers */
	enum sound_mode mode;
	u8 level;
	struct sound_slot slot[LMS_SOUND_SLOTS];
	unsigned int play_slot, play_pos, write_slot;
	struct hrtimer sample_timer;	/* 125 us while PCM plays */
	ktime_t pcm_start;		/* when PCM playback started */
	u64 pcm_played;			/* samples taken since then */
	struct hrtimer tone_timer;	/* ends a timed tone */
} snd;

/* ---- hardware ---- */

static void sound_amp(bool on)
{
	gpio_set_value(amp_gpio, on);
}

/* Freezes the counter with the output low and the amplifier off.  Lock held. */
static void sound_halt_locked(void)
{
	sound_amp(false);
	writew(0, snd.pwm + EPWM_CMPB);
	writew(TBCTL_STOP, snd.pwm + EPWM_TBCTL);
	snd.mode = SOUND_IDLE;
}

/* A sound ended (or was broken off): halted, status OK.  Lock held. */
static void sound_stop_locked(void)
{
	sound_halt_locked();
	WRITE_ONCE(snd.status[0], LMS_SOUND_OK);
}

/* Programs the time base for a period of prd + 1 counts of tbctl's clock. */
static void sound_pwm_setup(u16 tbctl, u16 prd, u16 cmpb)
{
	writew(TBCTL_STOP, snd.pwm + EPWM_TBCTL);
	writew(0, snd.pwm + EPWM_TBPHS);
	writew(0, snd.pwm + EPWM_TBCNT);
	writew(prd, snd.pwm + EPWM_TBPRD);
	writew(0, snd.pwm + EPWM_CMPCTL);
	writew(AQCTLB_HIGH_ZERO_LOW_CMPB, snd.pwm + EPWM_AQCTLB);
	writew(cmpb, snd.pwm + EPWM_CMPB);
	writew(tbctl, snd.pwm + EPWM_TBCTL);
}

/* ---- timers ---- */

/* The next queued sample, or -1 when every slot is empty.  Lock held. */
static int sound_next_sample(void)
{
	struct sound_slot *s = &snd.slot[snd.play_slot];
	int sample;

	if (!s->count)
		return -1;
	sample = s->sample[snd.play_pos++];
	if (snd.play_pos >= s->count) {
		s->count = 0;
		snd.play_pos = 0;
		snd.play_slot = (snd.play_slot + 1) % LMS_SOUND_SLOTS;
	}
	return sample;
}

static enum hrtimer_restart sound_sample_due(struct hrtimer *timer)
{
	enum hrtimer_restart ret = HRTIMER_RESTART;
	unsigned long flags;
	u64 due;
	int sample = 0;
	bool took = false;

	spin_lock_irqsave(&snd.lock, flags);
	if (snd.mode != SOUND_PCM) {
		ret = HRTIMER_NORESTART;
		goto unlock;
	}
	/*
	 * One sample per SAMPLE_NS since playback started, the newest one played.  They are
	 * counted from the clock, not from hrtimer_forward's overruns: where the timers'
	 * resolution is coarser than a sample (hrtimer_resolution is a tick without
	 * high-resolution timers) the period is rounded up and each expiry covers several.
	 */
	due = div_u64(ktime_to_ns(ktime_sub(hrtimer_cb_get_time(timer), snd.pcm_start)), SAMPLE_NS);
	for (; snd.pcm_played < due && sample >= 0; snd.pcm_played++) {
		sample = sound_next_sample();
		took = true;
	}
	hrtimer_forward_now(timer, ns_to_ktime(SAMPLE_NS));
	if (sample < 0) {
		sound_stop_locked();
		ret = HRTIMER_NORESTART;
	} else if (took) {
		writew(min_t(u32, (u32)snd.level * (u32)sample, U16_MAX), snd.pwm + EPWM_CMPB);
	}
unlock:
	spin_unlock_irqrestore(&snd.lock, flags);
	return ret;
}

static enum hrtimer_restart sound_tone_end(struct hrtimer *timer)
{
	unsigned long flags;

	spin_lock_irqsave(&snd.lock, flags);
	if (snd.mode == SOUND_TONE)
		sound_stop_locked();
	spin_unlock_irqrestore(&snd.lock, flags);
	return HRTIMER_NORESTART;
}

/* ---- commands ---- */

/* Cancels the timers and halts; a BREAK also reports the status OK. */
static void sound_halt(bool report)
{
	hrtimer_cancel(&snd.sample_timer);
	hrtimer_cancel(&snd.tone_timer);
	spin_lock_irq(&snd.lock);
	if (report)
		sound_stop_locked();
	else
		sound_halt_locked();
	spin_unlock_irq(&snd.lock);
}

static void sound_tone(u8 level, u16 freq, u16 ms)
{
	u32 prd;

	sound_halt(false);	/* the status stays as user space set it (BUSY) */
	level = min_t(u8, level, LMS_SOUND_MAX_LEVEL);
	freq = clamp_t(u16, freq, LMS_SOUND_MIN_FREQ, LMS_SOUND_MAX_FREQ);
	prd = pwm_clock_hz / TONE_DIVIDER / freq - 1;
	spin_lock_irq(&snd.lock);
	snd.mode = SOUND_TONE;
	snd.level = level;
	sound_pwm_setup(TBCTL_TONE, prd, prd * level / 200);
	sound_amp(true);
	spin_unlock_irq(&snd.lock);
	if (ms)
		hrtimer_start(&snd.tone_timer, ms_to_ktime(ms), HRTIMER_MODE_REL);
}

static void sound_play(u8 level)
{
	sound_halt(false);
	spin_lock_irq(&snd.lock);
	snd.mode = SOUND_PCM;
	snd.level = level;
	memset(snd.slot, 0, sizeof(snd.slot));
	snd.play_slot = snd.play_pos = snd.write_slot = 0;
	sound_pwm_setup(TBCTL_PCM, pwm_clock_hz / PCM_CARRIER_HZ, 0);
	sound_amp(level != 0);
	snd.pcm_start = ktime_get();
	snd.pcm_played = 0;
	spin_unlock_irq(&snd.lock);
	hrtimer_start(&snd.sample_timer, ns_to_ktime(SAMPLE_NS), HRTIMER_MODE_REL);
}

/* Queues samples in the next slot if it is free: the count taken, or 0. */
static ssize_t sound_service(const u8 *samples, size_t n)
{
	struct sound_slot *s;
	ssize_t ret = 0;
	size_t i;

	spin_lock_irq(&snd.lock);
	s = &snd.slot[snd.write_slot];
	if (!s->count && n) {
		for (i = 0; i < n; i++)
			s->sample[i] = samples[i] ? samples[i] : 1;
		s->count = n;
		snd.write_slot = (snd.write_slot + 1) % LMS_SOUND_SLOTS;
		ret = n;
	}
	spin_unlock_irq(&snd.lock);
	return ret;
}

/* ---- file operations ---- */

static ssize_t sound_write(struct file *file, const char __user *buf, size_t count, loff_t *ppos)
{
	u8 cmd[1 + LMS_SOUND_SLOT_SAMPLES];
	size_t n = min(count, sizeof(cmd));

	if (!count)
		return 0;
	if (copy_from_user(cmd, buf, n))
		return -EFAULT;
	switch (cmd[0]) {
	case LMS_SOUND_BREAK:
		sound_halt(true);
		return 0;
	case LMS_SOUND_TONE:
		if (n < TONE_CMD_LEN)
			return -EINVAL;
		sound_tone(cmd[1], cmd[2] | cmd[3] << 8, cmd[4] | cmd[5] << 8);
		return 0;
	case LMS_SOUND_PLAY:
		if (n < PLAY_CMD_LEN)
			return -EINVAL;
		sound_play(cmd[1]);
		return PLAY_CMD_LEN;
	case LMS_SOUND_REPEAT:
		return 0;
	case LMS_SOUND_SERVICE:
		return sound_service(cmd + 1, n - 1);
	default:
		return -EINVAL;
	}
}

static ssize_t sound_read(struct file *file, char __user *buf, size_t count, loff_t *ppos)
{
	static const char text[] = LMS_SOUND_DEVICE_NAME "\r";

	return simple_read_from_buffer(buf, count, ppos, text, sizeof(text) - 1);
}

/* Maps the status page from offset 0. */
static int sound_mmap(struct file *file, struct vm_area_struct *vma)
{
	unsigned long len = vma->vm_end - vma->vm_start;

	if (vma->vm_pgoff || len > LMS_SOUND_MAP_SIZE)
		return -EINVAL;
	if (remap_pfn_range(vma, vma->vm_start, virt_to_phys(snd.status) >> PAGE_SHIFT, len,
			    vma->vm_page_prot))
		return -EAGAIN;
	return 0;
}

static const struct file_operations sound_fops = {
	.owner		= THIS_MODULE,
	.read		= sound_read,
	.write		= sound_write,
	.mmap		= sound_mmap,
	.llseek		= noop_llseek,
};

static struct miscdevice sound_misc = {
	.minor	= MISC_DYNAMIC_MINOR,
	.name	= LMS_SOUND_DEVICE_NAME,
	.fops	= &sound_fops,
};

/* ---- module ---- */

/* Powers eHRPWM0 through PSC1; -ETIMEDOUT if the transition hangs. */
static int sound_power_on(void)
{
	int i;

	writel(readl(snd.psc1 + PSC_MDCTL(PSC1_LPSC_EHRPWM)) | PSC_STATE_ENABLE,
	       snd.psc1 + PSC_MDCTL(PSC1_LPSC_EHRPWM));
	writel(readl(snd.psc1 + PSC_PTCMD) | PSC_GO_MASK, snd.psc1 + PSC_PTCMD);
	for (i = 0; i < PSC_POLL_LIMIT; i++) {
		if (!(readl(snd.psc1 + PSC_PTSTAT) & PSC_GO_MASK))
			return 0;
		udelay(1);
	}
	return -ETIMEDOUT;
}

static void sound_pinmux(unsigned int reg, unsigned int shift, u32 function)
{
	u8 __iomem *p = snd.syscfg0 + SYSCFG0_PINMUX(reg);

	writel((readl(p) & ~(0xFU << shift)) | function << shift, p);
}

/* Routes EPWM0B and the amplifier pin, starts the eHRPWM time base clocks (never stopped). */
static void sound_syscfg_setup(void)
{
	writel(SYSCFG0_KICK0_KEY, snd.syscfg0 + SYSCFG0_KICK0R);
	writel(SYSCFG0_KICK1_KEY, snd.syscfg0 + SYSCFG0_KICK1R);
	sound_pinmux(3, PINMUX3_EPWM0B_SHIFT, PINMUX3_EPWM0B);
	sound_pinmux(13, PINMUX13_GP6_15_SHIFT, PINMUX_GPIO);
	writel(readl(snd.syscfg0 + SYSCFG0_CFGCHIP1) | CFGCHIP1_TBCLKSYNC,
	       snd.syscfg0 + SYSCFG0_CFGCHIP1);
	writel(0, snd.syscfg0 + SYSCFG0_KICK0R);
	writel(0, snd.syscfg0 + SYSCFG0_KICK1R);
}

static void sound_unmap(void)
{
	if (snd.pwm) {
		iounmap(snd.pwm);
		release_mem_region(EHRPWM0_PHYS, EHRPWM_SIZE);
	}
	if (snd.psc1)
		iounmap(snd.psc1);
	if (snd.syscfg0)
		iounmap(snd.syscfg0);
	snd.pwm = snd.psc1 = snd.syscfg0 = NULL;
}

static int sound_map(void)
{
	if (!request_mem_region(EHRPWM0_PHYS, EHRPWM_SIZE, LMS_SOUND_DEVICE_NAME))
		return -EBUSY;
	snd.pwm = ioremap(EHRPWM0_PHYS, EHRPWM_SIZE);
	if (!snd.pwm) {
		release_mem_region(EHRPWM0_PHYS, EHRPWM_SIZE);
		return -ENOMEM;
	}
	/* PSC1 and SYSCFG0 are shared with every other driver: mapped, not claimed */
	snd.psc1 = ioremap(PSC1_PHYS, PSC1_SIZE);
	snd.syscfg0 = ioremap(SYSCFG0_PHYS, SYSCFG0_SIZE);
	if (!snd.psc1 || !snd.syscfg0) {
		sound_unmap();
		return -ENOMEM;
	}
	return 0;
}

static int __init d_sound_init(void)
{
	int ret;

	memset(&snd, 0, sizeof(snd));
	spin_lock_init(&snd.lock);
	hrtimer_init(&snd.sample_timer, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	snd.sample_timer.function = sound_sample_due;
	hrtimer_init(&snd.tone_timer, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	snd.tone_timer.function = sound_tone_end;
	if (pwm_clock_hz / TONE_DIVIDER / LMS_SOUND_MAX_FREQ < 2 ||
	    pwm_clock_hz / TONE_DIVIDER / LMS_SOUND_MIN_FREQ > U16_MAX ||
	    pwm_clock_hz / PCM_CARRIER_HZ > U16_MAX) {
		pr_err("d_sound: pwm_clock_hz %u out of range\n", pwm_clock_hz);
		return -EINVAL;
	}

	snd.status = kzalloc(LMS_SOUND_MAP_SIZE, GFP_KERNEL);
	if (!snd.status)
		return -ENOMEM;
	SetPageReserved(virt_to_page(snd.status));
	ret = sound_map();
	if (ret)
		goto free_page;
	ret = gpio_request(amp_gpio, "d_sound amplifier");
	if (ret) {
		pr_err("d_sound: amplifier GPIO %d: %d\n", amp_gpio, ret);
		goto unmap;
	}
	ret = gpio_direction_output(amp_gpio, 0);
	if (ret)
		goto free_gpio;
	sound_syscfg_setup();
	ret = sound_power_on();
	if (ret) {
		pr_err("d_sound: eHRPWM0 does not power up\n");
		goto free_gpio;
	}
	writew(TBCTL_STOP, snd.pwm + EPWM_TBCTL);
	ret = misc_register(&sound_misc);
	if (ret)
		goto free_gpio;
	return 0;

free_gpio:
	gpio_free(amp_gpio);
unmap:
	sound_unmap();
free_page:
	ClearPageReserved(virt_to_page(snd.status));
	kfree(snd.status);
	snd.status = NULL;
	return ret;
}

static void __exit d_sound_exit(void)
{
	misc_deregister(&sound_misc);
	sound_halt(true);
	gpio_free(amp_gpio);
	sound_unmap();
	ClearPageReserved(virt_to_page(snd.status));
	kfree(snd.status);
	snd.status = NULL;
}

module_init(d_sound_init);
module_exit(d_sound_exit);

MODULE_LICENSE("GPL");
MODULE_AUTHOR("ev3lx");
MODULE_DESCRIPTION("LEGO EV3 speaker (/dev/lms_sound)");

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sim_pluto.c - the Pluto-P model behind sim_parport (sim_pluto.h; facts: pluto.md).
 * Configuration: nInit (control bit 2) low resets the FPGA; while it is high every
 * rising edge of control bit 0 (the nStrobe pulse) clocks data bit 0 in, bytes LSB
 * first. After exactly PLUTO_IMAGE_BYTES bytes the design runs and answers EPP
 * cycles; before that, or while sim-parport.N.pluto.epp-timeout is TRUE, every EPP
 * cycle times out. Pins (sim-parport.N.pluto.):
 *   config-bits (u32 OUT) clocks since the last reset; config-sum (u32 OUT) the sum of
 *     (i + 1) * byte i over the reassembled bytes, mod 2^32, so a test that knows the
 *     image can check length, order and bit order; configured (bit OUT);
 *   epp-timeout (bit IN); inputs (u32 IN) the design's input word (servo: pluto.md
 *     §4.1 word 4, step: §5.1); outputs (u32 OUT) the outputs word as last written;
 *   watchdog-enabled, watchdog-bitten (bit OUT): bitten 127 watchdog clocks (~6.5 ms,
 *     host time) after the last write that set bit 14 of the outputs word;
 *   servo: pwm.M (u32 OUT) PWM words as written; encoder.M.count (s32 IN) the
 *     counter (14 bits used; in test mode encoder 0 also counts OUT0/OUT1 as A/B);
 *     encoder.M.index (bit IN) a rising edge latches the count as index position;
 *   step: stepgen.M.rate (s32 OUT) the 12-bit velocity register; stepgen.M.steps (s32
 *     OUT) the position in whole steps, integrated over host time at one velocity
 *     addition per 1.6 us tick; timing (u32 OUT) the timing word. */
#include "rtapi.h"
#include "hal.h"
#include "sim_pluto.h"

#define PLUTO_IMAGE_BYTES 19895		/* what the EP1K10 takes (pluto.md §1) */
#define WDT_CLOCKS 127			/* watchdog clocks until it bites (§4.5) */

struct sim_pluto {		/* HAL memory; touched only by port accesses */
	enum sim_pluto_design design;
	hal_u32_t *config_bits, *config_sum, *inputs, *outputs, *timing;
	hal_bit_t *configured, *epp_timeout, *wdt_enabled, *wdt_bitten;
	hal_u32_t *pwm[4];
	hal_s32_t *enc_count[4];
	hal_bit_t *enc_index[4];
	hal_s32_t *rate[4], *steps[4];
	/* configuration */
	unsigned char last_control, shift;
	rtapi_u32 bits;
	/* design state */
	unsigned char addr, low;
	rtapi_u32 buf;
	rtapi_u16 wreg[8];
	int index_prev[4], index_seen[4];
	rtapi_u32 index_pos[4];
	rtapi_s32 test_delta;		/* encoder 0's counts from test mode */
	int test_ab, test_z;
	long long wdt_pet;		/* rtapi_get_time of the last watchdog write */
	long long step_time;		/* step model: time up to which ticks were added */
	rtapi_s64 pos[4];		/* step positions, 1/2048 step units */
};

static int pin_u32(hal_pin_dir_t dir, hal_u32_t **p, int comp_id, int n, const char *what)
{
	return hal_pin_u32_newf(dir, p, comp_id, "sim-parport.%d.pluto.%s", n, what);
}

static int pin_bit(hal_pin_dir_t dir, hal_bit_t **p, int comp_id, int n, const char *what)
{
	return hal_pin_bit_newf(dir, p, comp_id, "sim-parport.%d.pluto.%s", n, what);
}

/* Power-on / nConfig: the design is gone, its registers cleared. */
static void reset_fpga(struct sim_pluto *p)
{
	int i;

	p->bits = 0;
	p->shift = 0;
	*p->config_bits = 0;
	*p->config_sum = 0;
	*p->configured = 0;
	*p->outputs = 0;
	*p->wdt_enabled = *p->wdt_bitten = 0;
	p->addr = p->low = 0;
	p->buf = 0;
	p->test_delta = 0;
	p->test_ab = p->test_z = 0;
	for (i = 0; i < 8; i++)
		p->wreg[i] = 0;
	for (i = 0; i < 4; i++) {
		p->index_seen[i] = 0;
		p->index_pos[i] = 0;
		p->pos[i] = 0;
		if (p->design == SIM_PLUTO_SERVO)
			*p->pwm[i] = 0;
		else
			*p->rate[i] = *p->steps[i] = 0;
	}
	if (p->design == SIM_PLUTO_STEP)
		*p->timing = 0;
}

struct sim_pluto *sim_pluto_new(int comp_id, int n, enum sim_pluto_design design)
{
	struct sim_pluto *p = hal_malloc(sizeof(*p));
	int m, err;

	if (!p) {
		rtapi_print_msg(RTAPI_MSG_ERR, "sim_parport: out of HAL memory\n");
		return 0;
	}
	p->design = design;
	err = pin_u32(HAL_OUT, &p->config_bits, comp_id, n, "config-bits");
	if (!err) err = pin_u32(HAL_OUT, &p->config_sum, comp_id, n, "config-sum");
	if (!err) err = pin_bit(HAL_OUT, &p->configured, comp_id, n, "configured");
	if (!err) err = pin_bit(HAL_IN, &p->epp_timeout, comp_id, n, "epp-timeout");
	if (!err) err = pin_u32(HAL_IN, &p->inputs, comp_id, n, "inputs");
	if (!err) err = pin_u32(HAL_OUT, &p->outputs, comp_id, n, "outputs");
	if (!err) err = pin_bit(HAL_OUT, &p->wdt_enabled, comp_id, n, "watchdog-enabled");
	if (!err) err = pin_bit(HAL_OUT, &p->wdt_bitten, comp_id, n, "watchdog-bitten");
	for (m = 0; !err && m < 4; m++) {
		if (design == SIM_PLUTO_SERVO) {
			err = hal_pin_u32_newf(HAL_OUT, &p->pwm[m], comp_id,
					       "sim-parport.%d.pluto.pwm.%d", n, m);
			if (!err)
				err = hal_pin_s32_newf(HAL_IN, &p->enc_count[m], comp_id,
						       "sim-parport.%d.pluto.encoder.%d.count", n, m);
			if (!err)
				err = hal_pin_bit_newf(HAL_IN, &p->enc_index[m], comp_id,
						       "sim-parport.%d.pluto.encoder.%d.index", n, m);
		} else {
			err = hal_pin_s32_newf(HAL_OUT, &p->rate[m], comp_id,
					       "sim-parport.%d.pluto.stepgen.%d.rate", n, m);
			if (!err)
				err = hal_pin_s32_newf(HAL_OUT, &p->steps[m], comp_id,
						       "sim-parport.%d.pluto.stepgen.%d.steps", n, m);
		}
	}
	if (!err && design == SIM_PLUTO_STEP)
		err = pin_u32(HAL_OUT, &p->timing, comp_id, n, "timing");
	if (err)
		return 0;
	p->last_control = 0;
	p->wdt_pet = p->step_time = 0;
	for (m = 0; m < 4; m++)
		p->index_prev[m] = 0;
	reset_fpga(p);
	return p;
}

void sim_pluto_spp(struct sim_pluto *p, unsigned char data, unsigned char control)
{
	unsigned char prev = p->last_control;

	p->last_control = control;
	if (!(control & 0x04)) {
		if (p->bits || *p->configured)
			reset_fpga(p);
		return;
	}
	if ((prev & 0x01) || !(control & 0x01) || !(prev & 0x04))
		return;		/* not a rising edge of the clock with nConfig high */
	p->bits++;
	*p->config_bits = p->bits;
	if (*p->configured)
		return;		/* clocks after configuration are ignored */
	p->shift |= (unsigned char)((data & 1) << ((p->bits - 1) & 7));
	if ((p->bits & 7) == 0) {
		*p->config_sum += (p->bits >> 3) * (rtapi_u32)p->shift;
		p->shift = 0;
		if (p->bits == PLUTO_IMAGE_BYTES * 8)
			*p->configured = 1;
	}
}

/* The watchdog, evaluated at each access (the model has no clock of its own). */
static void watchdog(struct sim_pluto *p, long long now)
{
	long long clk = p->design == SIM_PLUTO_SERVO ? 2047 : 2048;

	if (*p->wdt_enabled && now - p->wdt_pet > WDT_CLOCKS * clk * 25)
		*p->wdt_bitten = 1;
}

/* The step generators' positions up to 'now', one velocity addition per 1.6 us. */
static void integrate(struct sim_pluto *p, long long now)
{
	long long dt = now - p->step_time;
	rtapi_s64 ticks;
	int i;

	if (dt < 1600)
		return;
	if (dt > 1000000000LL)		/* a pause of the host: at most one second */
		dt = 1000000000LL;
	ticks = (rtapi_s64)rtapi_div_u64((rtapi_u64)dt, 1600);
	p->step_time = now - (dt - ticks * 1600);
	for (i = 0; i < 4; i++) {
		rtapi_s32 v = p->wreg[i] & 0xfff;

		if (v & 0x800)
			v -= 0x1000;
		p->pos[i] += (rtapi_s64)v * ticks;
		*p->steps[i] = (rtapi_s32)(p->pos[i] >> 11);
	}
}

/* The design runs on its own clock whether or not the cycle gets through. */
static int answering(struct sim_pluto *p)
{
	long long now;

	if (!*p->configured)
		return 0;
	now = rtapi_get_time();
	watchdog(p, now);
	if (p->design == SIM_PLUTO_STEP)
		integrate(p, now);
	return !*p->epp_timeout;
}

int sim_pluto_epp_addr(struct sim_pluto *p, unsigned char addr)
{
	if (!answering(p))
		return -1;
	p->addr = addr & 31;
	return 0;
}

static rtapi_u32 servo_word(struct sim_pluto *p, int w)
{
	rtapi_u32 count;
	int idx;

	if (w == 4)
		return *p->inputs & 0xfffff;
	if (w > 4)
		return 0;
	count = (rtapi_u32)(*p->enc_count[w] + (w == 0 ? p->test_delta : 0)) & 0x3fff;
	idx = *p->enc_index[w] != 0;
	if (idx && !p->index_prev[w]) {
		p->index_pos[w] = count;
		p->index_seen[w] = 1;
	}
	p->index_prev[w] = idx;
	return count | p->index_pos[w] << 14 | (rtapi_u32)p->index_seen[w] << 28;
}

static rtapi_u32 step_word(struct sim_pluto *p, int w)
{
	if (w == 4)
		return *p->inputs & 0xffff;
	if (w > 4)
		return 0;
	return (rtapi_u32)p->pos[w] & 0x1fffff;
}

int sim_pluto_epp_read(struct sim_pluto *p, unsigned char *byte)
{
	int w = p->addr >> 2;

	if (!answering(p)) {
		*byte = 0xff;
		return -1;
	}
	if ((p->addr & 3) == 0) {
		p->buf = p->design == SIM_PLUTO_SERVO ? servo_word(p, w) : step_word(p, w);
		if (p->design == SIM_PLUTO_SERVO && w < 4)
			p->index_seen[w] = 0;
	} else if (p->design == SIM_PLUTO_SERVO && w < 4) {
		p->index_seen[w] = 0;	/* any read in the word clears the flag */
	}
	*byte = (unsigned char)(p->buf >> (8 * (p->addr & 3)));
	p->addr = (p->addr + 1) & 31;
	return 0;
}

/* Test mode (servo outputs word bit 13): OUT0/OUT1/OUT2 are encoder 0's A/B/Z. */
static void test_encoder(struct sim_pluto *p, rtapi_u16 out)
{
	int ab = out & 3, z = ((out >> 2) ^ (out >> 15)) & 1;
	int changed = ab ^ p->test_ab;

	if (changed == 1 || changed == 2)	/* exactly one of A, B: x4 count */
		p->test_delta += ((ab & 1) ^ ((p->test_ab >> 1) & 1)) ? 1 : -1;
	if (z && !p->test_z) {
		p->index_pos[0] = (rtapi_u32)(*p->enc_count[0] + p->test_delta) & 0x3fff;
		p->index_seen[0] = 1;
	}
	p->test_ab = ab;
	p->test_z = z;
}

static void commit(struct sim_pluto *p, int reg, rtapi_u16 v)
{
	p->wreg[reg] = v;
	if (reg < 4) {
		if (p->design == SIM_PLUTO_SERVO) {
			*p->pwm[reg] = v;
		} else {
			rtapi_s32 r = v & 0xfff;

			*p->rate[reg] = r & 0x800 ? r - 0x1000 : r;
		}
	} else if (reg == 4) {
		*p->outputs = v;
		if (v & 0x4000) {	/* enable (only reconfiguration clears it), pet */
			*p->wdt_enabled = 1;
			*p->wdt_bitten = 0;
			p->wdt_pet = rtapi_get_time();
		}
		if (p->design == SIM_PLUTO_SERVO && (v & 0x2000))
			test_encoder(p, v);
	} else if (reg == 5 && p->design == SIM_PLUTO_STEP) {
		*p->timing = v;
	}
}

int sim_pluto_epp_write(struct sim_pluto *p, unsigned char byte)
{
	int nregs = p->design == SIM_PLUTO_SERVO ? 5 : 6;

	if (!answering(p))
		return -1;
	if ((p->addr & 1) && (p->addr >> 1) < nregs)
		commit(p, p->addr >> 1, (rtapi_u16)(byte << 8 | p->low));
	else
		p->low = byte;
	p->addr = (p->addr + 1) & 31;
	return 0;
}

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_dpll.c - HM2DPLL (GTag 26, hostmot2.md 7.8): MD check and HAL objects. There is
 * one DPLL with four timers; num_dplls=0 disables it (no timer-select registers are
 * then written by the encoder and stepgen). Register values are computed in
 * hm2_dpll_fp.c. */
#include "rtapi.h"
#include "hal.h"
#include "hm2.h"

#define REG_CONTROL1 3
#define REG_PHASE 6

int hm2_dpll_parse(struct hostmot2 *hm2, const struct hm2_md *md)
{
	struct hm2_dpll *d = &hm2->dpll;
	char err[HM2_ERRLEN];
	int rc;

	if (hm2_md_is_consistent(md, err, sizeof(err))) {
		HM2_ERR(hm2, "%s", err);
		return -EINVAL;
	}
	if (hm2->cfg.num[HM2_NUM_DPLLS] == 0)
		return 0;
	d->md = md;
	rc = hm2_tram_add_read(hm2, hm2_md_addr(md, REG_CONTROL1, 0), 4, &d->control1_rd);
	if (!rc)
		rc = hm2_tram_add_read(hm2, hm2_md_addr(md, REG_PHASE, 0), 4, &d->phase_rd);
	return rc;
}

int hm2_dpll_export(struct hostmot2 *hm2)
{
	struct hm2_dpll *d = &hm2->dpll;
	const char *b = hm2->llio->name;
	int id = hm2->llio->comp_id, i, rc = 0;

	if (!d->md)
		return 0;
	for (i = 0; i < 4 && !rc; i++)
		rc = hal_pin_float_newf(HAL_IN, &d->timer_us[i], id, "%s.dpll.%02d.timer-us", b, i + 1);
	if (!rc) rc = hal_pin_float_newf(HAL_IN, &d->base_freq_khz, id, "%s.dpll.base-freq-khz", b);
	if (!rc) rc = hal_pin_float_newf(HAL_OUT, &d->phase_error_us, id, "%s.dpll.phase-error-us", b);
	if (!rc) rc = hal_pin_u32_newf(HAL_IN, &d->time_const, id, "%s.dpll.time-const", b);
	if (!rc) rc = hal_pin_u32_newf(HAL_IN, &d->plimit, id, "%s.dpll.plimit", b);
	if (!rc) rc = hal_pin_u32_newf(HAL_OUT, &d->ddsize, id, "%s.dpll.ddsize", b);
	if (!rc) rc = hal_pin_u32_newf(HAL_IN, &d->prescale, id, "%s.dpll.prescale", b);
	if (rc)
		return rc;
	*d->time_const = 2000;
	*d->plimit = 0x400000;
	*d->prescale = 1;
	d->force = 1;
	return 0;
}

void hm2_dpll_force_write(struct hostmot2 *hm2)
{
	hm2->dpll.force = 1;
}

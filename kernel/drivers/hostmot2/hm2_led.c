/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_led.c - LED (GTag 128, hostmot2.md 7.3): pins led.CR01.. (as many as the board
 * driver declares, clipped by num_leds); CR01 is bit 31. Written when it changes. */
#include "rtapi.h"
#include "hal.h"
#include "hm2.h"

int hm2_led_parse(struct hostmot2 *hm2, const struct hm2_md *md)
{
	struct hm2_led *led = &hm2->led;
	char err[HM2_ERRLEN];
	int n = hm2->llio->num_leds;

	if (hm2_md_is_consistent(md, err, sizeof(err))) {
		HM2_ERR(hm2, "%s", err);
		return -EINVAL;
	}
	if (n > 32)
		n = 32;
	if (hm2->cfg.num[HM2_NUM_LEDS] >= 0 && hm2->cfg.num[HM2_NUM_LEDS] < n)
		n = hm2->cfg.num[HM2_NUM_LEDS];
	led->md = md;
	led->num = n;
	return 0;
}

int hm2_led_export(struct hostmot2 *hm2)
{
	struct hm2_led *led = &hm2->led;
	int i, rc = 0;

	if (!led->md || !led->num)
		return 0;
	led->led = hal_malloc(led->num * sizeof(*led->led));
	if (!led->led)
		return -ENOMEM;
	for (i = 0; i < led->num && !rc; i++)
		rc = hal_pin_bit_newf(HAL_IN, &led->led[i], hm2->llio->comp_id, "%s.led.CR%02d",
				      hm2->llio->name, i + 1);
	led->force = 1;
	return rc;
}

void hm2_led_write(struct hostmot2 *hm2)
{
	struct hm2_led *led = &hm2->led;
	rtapi_u32 v = 0;
	int i;

	if (!led->md || !led->num)
		return;
	for (i = 0; i < led->num; i++)
		if (*led->led[i])
			v |= 1u << (31 - i);
	if (v != led->written || led->force) {
		hm2_write_now(hm2, hm2_md_addr(led->md, 0, 0), &v, 4);
		led->written = v;
		led->force = 0;
	}
}

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_watchdog.c - Watchdog (GTag 2, hostmot2.md 7.2). Asleep (timer bit 31 set) until
 * the first write(), which arms it with timeout_ns (default 5 ms); every write()
 * pets it through the per-cycle write list. A bite (status bit 0) sets has_bit and
 * makes the firmware release every IO pin; clearing has_bit makes the next write()
 * force-write every module, which restores the pins. Integer-only. */
#include "rtapi.h"
#include "hal.h"
#include "hm2.h"

#define REG_TIMER 0
#define REG_STATUS 1
#define REG_RESET 2
#define TIMER_DISABLED 0x80000000u
#define PET 0x5A000000u

int hm2_watchdog_parse(struct hostmot2 *hm2, const struct hm2_md *md)
{
	struct hm2_watchdog *wd = &hm2->watchdog;
	char err[HM2_ERRLEN];
	int rc;

	if (hm2_md_is_consistent(md, err, sizeof(err))) {
		HM2_ERR(hm2, "%s", err);
		return -EINVAL;
	}
	if (md->instances != 1)
		HM2_WARN(hm2, "watchdog: %u instances, using the first", md->instances);
	wd->md = md;
	rc = hm2_tram_add_read(hm2, hm2_md_addr(md, REG_STATUS, 0), 4, &wd->status_rd);
	if (!rc)
		rc = hm2_tram_add_write(hm2, hm2_md_addr(md, REG_RESET, 0), 4, &wd->reset_wr);
	return rc;
}

int hm2_watchdog_export(struct hostmot2 *hm2)
{
	struct hm2_watchdog *wd = &hm2->watchdog;
	int id = hm2->llio->comp_id, rc;

	if (!wd->md)
		return 0;
	rc = hal_pin_bit_newf(HAL_IO, &wd->has_bit, id, "%s.watchdog.has_bit", hm2->llio->name);
	if (!rc)
		rc = hal_param_u32_newf(HAL_RW, &wd->timeout_ns, id, "%s.watchdog.timeout_ns",
					hm2->llio->name);
	wd->timeout_ns = 5000000;
	*wd->reset_wr = PET;
	return rc;
}

/* timeout in clocks - 1, clamped; the param is rewritten to what the timer does */
static rtapi_u32 timer_value(struct hostmot2 *hm2)
{
	struct hm2_watchdog *wd = &hm2->watchdog;
	rtapi_u32 clk = wd->md->clock_freq;
	rtapi_u64 ticks = rtapi_div_u64((rtapi_u64)wd->timeout_ns * clk, 1000000000u);

	if (ticks > 0x80000000ull) {
		ticks = 0x80000000ull;
		wd->timeout_ns = (rtapi_u32)rtapi_div_u64(ticks * 1000000000ull, clk);
	}
	return ticks ? (rtapi_u32)(ticks - 1) : 0;
}

void hm2_watchdog_force_write(struct hostmot2 *hm2)
{
	struct hm2_watchdog *wd = &hm2->watchdog;
	rtapi_u32 timer, status = 0;

	if (!wd->md)
		return;
	timer = wd->enable ? timer_value(hm2) : TIMER_DISABLED;
	hm2_write_now(hm2, hm2_md_addr(wd->md, REG_TIMER, 0), &timer, 4);
	hm2_write_now(hm2, hm2_md_addr(wd->md, REG_STATUS, 0), &status, 4);
	wd->written_timeout_ns = wd->timeout_ns;
}

void hm2_watchdog_read(struct hostmot2 *hm2)
{
	struct hm2_watchdog *wd = &hm2->watchdog;

	if (!wd->md || wd->needs_force_write)
		return;
	if (*wd->status_rd & 1) {
		HM2_ERR(hm2, "watchdog has bit: board outputs released; clear %s.watchdog.has_bit to resume",
			hm2->llio->name);
		*wd->has_bit = 1;
		wd->needs_force_write = 1;
	}
}

/* Before the per-cycle writes: arm on the first call, recover after a bite or an
 * io_error, rewrite the timer when timeout_ns changed. */
void hm2_watchdog_write(struct hostmot2 *hm2, long period)
{
	struct hm2_watchdog *wd = &hm2->watchdog;

	if (!wd->md)
		return;
	*wd->reset_wr = PET;
	if (*wd->has_bit)
		return;
	if (!wd->enable) {
		wd->enable = 1;
		wd->written_timeout_ns = wd->timeout_ns + 1;	/* forces the write below */
	}
	if (wd->timeout_ns != wd->written_timeout_ns) {
		rtapi_u32 timer;

		if ((rtapi_u64)wd->timeout_ns * 2 < (rtapi_u64)period * 3)
			HM2_WARN(hm2, "watchdog timeout_ns %u is less than 1.5 thread periods (%ld ns)",
				 wd->timeout_ns, period);
		timer = timer_value(hm2);
		hm2_write_now(hm2, hm2_md_addr(wd->md, REG_TIMER, 0), &timer, 4);
		wd->written_timeout_ns = wd->timeout_ns;
	}
}

/* Unregister: make the board safe at once. */
void hm2_watchdog_bite_now(struct hostmot2 *hm2)
{
	struct hm2_watchdog *wd = &hm2->watchdog;
	rtapi_u32 timer = 0, pet = PET;

	if (!wd->md)
		return;
	/* not queued: no write() will run to flush a queue */
	hm2->llio->write(hm2->llio, hm2_md_addr(wd->md, REG_TIMER, 0), &timer, 4);
	hm2->llio->write(hm2->llio, hm2_md_addr(wd->md, REG_RESET, 0), &pet, 4);
}

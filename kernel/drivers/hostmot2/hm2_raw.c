/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_raw.c - raw mode (config keyword enable_raw, hostmot2.md 7.12): peek and poke
 * any register from HAL. The read rides in the per-cycle read batch (queued by
 * hm2_tram_request_reads); the write happens in write() when write_strobe is set,
 * which is then cleared. dump_state prints the driver's view of the board. */
#include "rtapi.h"
#include "hal.h"
#include "hm2.h"

int hm2_raw_export(struct hostmot2 *hm2)
{
	struct hm2_raw *r = &hm2->raw;
	const char *b = hm2->llio->name;
	int id = hm2->llio->comp_id, rc;

	if (!hm2->cfg.enable_raw)
		return 0;
	rc = hal_pin_u32_newf(HAL_IN, &r->read_address, id, "%s.raw.read_address", b);
	if (!rc)
		rc = hal_pin_u32_newf(HAL_OUT, &r->read_data, id, "%s.raw.read_data", b);
	if (!rc)
		rc = hal_pin_u32_newf(HAL_IN, &r->write_address, id, "%s.raw.write_address", b);
	if (!rc)
		rc = hal_pin_u32_newf(HAL_IN, &r->write_data, id, "%s.raw.write_data", b);
	if (!rc)
		rc = hal_pin_bit_newf(HAL_IN, &r->write_strobe, id, "%s.raw.write_strobe", b);
	if (!rc)
		rc = hal_pin_bit_newf(HAL_IO, &r->dump_state, id, "%s.raw.dump_state", b);
	if (!rc)
		r->on = 1;
	return rc;
}

static void dump_state(struct hostmot2 *hm2)
{
	const struct hm2_idrom *id = &hm2->idrom;
	int i;

	HM2_INFO(hm2, "IDROM type %u at 0x%04X: board '%s', %u IOPorts x %u pins, clocks %u/%u Hz",
		 id->idrom_type, hm2->idrom_offset, id->board_name, id->io_ports, id->port_width,
		 id->clock_low, id->clock_high);
	for (i = 0; i < hm2->num_mds; i++) {
		const struct hm2_md *md = &hm2->md[i];
		const char *n = hm2_gtag_name(md->gtag);

		HM2_INFO(hm2, "MD %d: %s (GTag %u) v%u, %u instances at 0x%04X, clock %u Hz", i,
			 n ? n : "unsupported", md->gtag, md->version, md->instances,
			 md->base_address, md->clock_freq);
	}
	HM2_INFO(hm2, "per-cycle transfers: %d read blocks (%d bytes), %d write blocks (%d bytes)",
		 hm2->tram.num_rd, hm2->tram.rd_bytes, hm2->tram.num_wr, hm2->tram.wr_bytes);
	hm2_ioport_print_pins(hm2);
}

void hm2_raw_read(struct hostmot2 *hm2)
{
	if (hm2->raw.on)
		*hm2->raw.read_data = hm2->raw.rd_word;
}

void hm2_raw_write(struct hostmot2 *hm2)
{
	struct hm2_raw *r = &hm2->raw;

	if (!r->on)
		return;
	if (*r->write_strobe) {
		rtapi_u32 v = *r->write_data;

		hm2_write_now(hm2, *r->write_address & 0xFFFF, &v, 4);
		*r->write_strobe = 0;
	}
	if (*r->dump_state) {
		dump_state(hm2);
		*r->dump_state = 0;
	}
}

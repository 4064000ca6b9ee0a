/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_idrom.c - IDROM header, module and pin descriptor decoding and the checks the
 * driver makes before trusting them (hostmot2.md sections 2-6). No HAL, no I/O. */
#include "rtapi.h"
#include "rtapi_string.h"
#include "hm2_idrom.h"

int hm2_idrom_check_cookie(const rtapi_u32 words[3], char *err, int errlen)
{
	char name[HM2_CONFIGNAME_LEN + 1];
	int i;

	if (words[0] != HM2_IOCOOKIE) {
		rtapi_snprintf(err, errlen, "FPGA failed to initialize: IO cookie at 0x%04X is 0x%08X, "
			       "expected 0x%08X", HM2_ADDR_IOCOOKIE, words[0], HM2_IOCOOKIE);
		return -EINVAL;
	}
	for (i = 0; i < HM2_CONFIGNAME_LEN; i++) {
		char c = (char)(words[1 + i / 4] >> (8 * (i % 4)));

		name[i] = (c >= 0x20 && c < 0x7f) ? c : '?';
	}
	name[HM2_CONFIGNAME_LEN] = 0;
	if (memcmp(name, HM2_CONFIGNAME, HM2_CONFIGNAME_LEN) != 0) {
		rtapi_snprintf(err, errlen, "config name at 0x%04X is '%s', expected '%s'",
			       HM2_ADDR_CONFIGNAME, name, HM2_CONFIGNAME);
		return -EINVAL;
	}
	return 0;
}

rtapi_u32 hm2_idrom_offset(rtapi_u32 word)
{
	return word & 0xFFFF;
}

static void ascii8(char out[9], rtapi_u32 lo, rtapi_u32 hi)
{
	int i;

	for (i = 0; i < 8; i++) {
		char c = (char)((i < 4 ? lo : hi) >> (8 * (i % 4)));

		out[i] = (c >= 0x20 && c < 0x7f) ? c : '?';
	}
	out[8] = 0;
}

int hm2_idrom_parse(const rtapi_u32 w[HM2_IDROM_WORDS], const struct hm2_board_shape *shape,
		    struct hm2_idrom *r, char *err, int errlen)
{
	r->idrom_type = w[0];
	r->offset_to_modules = w[1];
	r->offset_to_pin_desc = w[2];
	ascii8(r->board_name, w[3], w[4]);
	r->fpga_size = w[5];
	r->fpga_pins = w[6];
	r->io_ports = w[7];
	r->io_width = w[8];
	r->port_width = w[9];
	r->clock_low = w[10];
	r->clock_high = w[11];
	r->instance_stride0 = w[12];
	r->instance_stride1 = w[13];
	r->register_stride0 = w[14];
	r->register_stride1 = w[15];

	/* the documented order: type, port width, io width, ports, pin limit, clocks */
	if (r->idrom_type != 2 && r->idrom_type != 3) {
		rtapi_snprintf(err, errlen, "invalid IDROM type %u, expected 2 or 3", r->idrom_type);
		return -EINVAL;
	}
	if (r->port_width != (rtapi_u32)shape->pins_per_connector) {
		rtapi_snprintf(err, errlen, "IDROM PortWidth is %u, this board has %d pins per connector",
			       r->port_width, shape->pins_per_connector);
		return -EINVAL;
	}
	if (r->io_width != r->io_ports * r->port_width) {
		rtapi_snprintf(err, errlen, "IDROM IOWidth is %u, but IOPorts (%u) x PortWidth (%u) is %u",
			       r->io_width, r->io_ports, r->port_width, r->io_ports * r->port_width);
		return -EINVAL;
	}
	if (r->io_ports != (rtapi_u32)shape->num_ioport_connectors) {
		rtapi_snprintf(err, errlen, "IDROM IOPorts is %u, this board has %d connectors",
			       r->io_ports, shape->num_ioport_connectors);
		return -EINVAL;
	}
	if (r->io_width > HM2_MAX_PIN_DESCRIPTORS) {
		rtapi_snprintf(err, errlen, "IDROM IOWidth is %u, the driver handles at most %d pins",
			       r->io_width, HM2_MAX_PIN_DESCRIPTORS);
		return -EINVAL;
	}
	if (r->clock_low < HM2_MIN_CLOCK_HZ) {
		rtapi_snprintf(err, errlen, "IDROM ClockLow is %u Hz, below the minimum of %u Hz",
			       r->clock_low, HM2_MIN_CLOCK_HZ);
		return -EINVAL;
	}
	if (r->clock_high < HM2_MIN_CLOCK_HZ) {
		rtapi_snprintf(err, errlen, "IDROM ClockHigh is %u Hz, below the minimum of %u Hz",
			       r->clock_high, HM2_MIN_CLOCK_HZ);
		return -EINVAL;
	}
	return 0;
}

int hm2_md_parse(const rtapi_u32 w[3], const struct hm2_idrom *idrom, struct hm2_md *md,
		 char *err, int errlen)
{
	int rsel, isel;

	md->gtag = w[0] & 0xFF;
	md->version = (w[0] >> 8) & 0xFF;
	md->clock_tag = (w[0] >> 16) & 0xFF;
	md->instances = (w[0] >> 24) & 0xFF;
	md->base_address = w[1] & 0xFFFF;
	md->num_registers = (w[1] >> 16) & 0xFF;
	rsel = (w[1] >> 24) & 0xF;
	isel = (w[1] >> 28) & 0xF;
	md->multiple_registers = w[2];
	if (md->gtag == HM2_GTAG_END)
		return 1;
	if (md->clock_tag == 1) {
		md->clock_freq = idrom->clock_low;
	} else if (md->clock_tag == 2) {
		md->clock_freq = idrom->clock_high;
	} else {
		rtapi_snprintf(err, errlen, "module descriptor for GTag %u has invalid clock tag %u "
			       "(1 = ClockLow, 2 = ClockHigh)", md->gtag, md->clock_tag);
		return -EINVAL;
	}
	if (rsel > 1 || isel > 1) {
		rtapi_snprintf(err, errlen, "module descriptor for GTag %u has invalid %s stride "
			       "selector %d (0 or 1)", md->gtag, rsel > 1 ? "register" : "instance",
			       rsel > 1 ? rsel : isel);
		return -EINVAL;
	}
	md->register_stride = rsel ? idrom->register_stride1 : idrom->register_stride0;
	md->instance_stride = isel ? idrom->instance_stride1 : idrom->instance_stride0;
	return 0;
}

int hm2_pd_parse(rtapi_u32 word, int pin, struct hm2_pd *pd, char *err, int errlen)
{
	pd->sec_pin = word & 0xFF;
	pd->sec_tag = (word >> 8) & 0xFF;
	pd->sec_unit = (word >> 16) & 0xFF;
	pd->primary_tag = (word >> 24) & 0xFF;
	if (pd->primary_tag == 0) {
		rtapi_snprintf(err, errlen, "pin descriptor %d: found end-of-list sentinel early "
			       "(IOWidth promises more pins)", pin);
		return -EINVAL;
	}
	if (pd->primary_tag != HM2_GTAG_IOPORT) {
		rtapi_snprintf(err, errlen, "pin descriptor %d: primary tag %u, expected %d (IOPort)",
			       pin, pd->primary_tag, HM2_GTAG_IOPORT);
		return -EINVAL;
	}
	return 0;
}

/* What each module driver accepts (hostmot2.md section 4). */
struct md_rule {
	rtapi_u8 gtag;
	const char *name;
	rtapi_u8 versions[6];		/* accepted versions; list ends at the first 0xFF */
	rtapi_u8 num_registers;
	rtapi_u32 instance_stride;
	rtapi_u32 multiple_registers;
	rtapi_u32 alt_instance_stride;	/* also accepted (0: none) */
};

/* The UART's registers are addressed through the MD's own stride, so besides the
 * 0x10 of older builds it accepts the 0x40 that current IDROMs offer as stride 1. */
static const struct md_rule rules[] = {
	{ HM2_GTAG_WATCHDOG, "watchdog", { 0, 0xFF }, 3, 4, 0x0, 0 },
	{ HM2_GTAG_IOPORT, "ioport", { 0, 0xFF }, 5, 4, 0x1F, 0 },
	{ HM2_GTAG_LED, "led", { 0, 0xFF }, 1, 4, 0x0, 0 },
	{ HM2_GTAG_ENCODER, "encoder", { 1, 2, 3, 0x83, 0xFF }, 5, 4, 0x03, 0 },
	{ HM2_GTAG_MUXED_ENCODER, "muxed encoder", { 2, 3, 4, 0x84, 0xFF }, 5, 4, 0x03, 0 },
	{ HM2_GTAG_STEPGEN, "stepgen", { 0, 1, 2, 0x42, 0xC2, 0xFF }, 10, 4, 0x1FF, 0 },
	{ HM2_GTAG_PWMGEN, "pwmgen", { 0, 1, 0xFF }, 5, 4, 0x03, 0 },
	{ HM2_GTAG_TPPWM, "3pwmgen", { 0, 0xFF }, 4, 4, 0x03, 0 },
	{ HM2_GTAG_HM2DPLL, "dpll", { 0, 0xFF }, 7, 4, 0x0, 0 },
	{ HM2_GTAG_BSPI, "bspi", { 0, 0xFF }, 3, 0x40, 0x07, 0 },
	{ HM2_GTAG_UART_TX, "uart tx", { 0, 0xFF }, 4, 0x10, 0x0F, 0x40 },
	{ HM2_GTAG_UART_RX, "uart rx", { 0, 0xFF }, 4, 0x10, 0x0F, 0x40 },
};

static const struct md_rule *rule_for(int gtag)
{
	unsigned i;

	for (i = 0; i < sizeof(rules) / sizeof(rules[0]); i++)
		if (rules[i].gtag == gtag)
			return &rules[i];
	return 0;
}

const char *hm2_gtag_name(int gtag)
{
	const struct md_rule *r = rule_for(gtag);

	return r ? r->name : 0;
}

int hm2_md_is_consistent(const struct hm2_md *md, char *err, int errlen)
{
	const struct md_rule *r = rule_for(md->gtag);
	int i, ok = 0;

	if (!r)
		return 0;	/* not ours: ignored by the caller */
	for (i = 0; i < 6 && r->versions[i] != 0xFF; i++)
		if (r->versions[i] == md->version)
			ok = 1;
	if (!ok) {
		rtapi_snprintf(err, errlen, "%s: unsupported module version %u", r->name, md->version);
		return -EINVAL;
	}
	if (md->num_registers != r->num_registers ||
	    (md->instance_stride != r->instance_stride &&
	     (!r->alt_instance_stride || md->instance_stride != r->alt_instance_stride)) ||
	    md->multiple_registers != r->multiple_registers) {
		rtapi_snprintf(err, errlen, "%s: inconsistent module descriptor: %u registers, instance "
			       "stride 0x%X, multiple-registers 0x%X (expected %u, 0x%X, 0x%X)", r->name,
			       md->num_registers, md->instance_stride, md->multiple_registers,
			       r->num_registers, r->instance_stride, r->multiple_registers);
		return -EINVAL;
	}
	return 0;
}

int hm2_connector_pin(int port_width, int bit)
{
	static const rtapi_u8 db25[17] = { 1, 14, 2, 15, 3, 16, 4, 17, 5, 6, 7, 8, 9, 10, 11, 12, 13 };

	if (port_width == 24)
		return 2 * bit + 1;
	if (port_width == 17 && bit < 17)
		return db25[bit];
	return bit + 1;
}

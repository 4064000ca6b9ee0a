/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_ioport.c - IOPort (GTag 3): pin ownership, the GPIO HAL interface of every IO
 * pin, and the five per-connector registers (hostmot2.md 6, 7.1).
 *
 * Full GPIO pins: gpio.NNN.in/in_not/out, params is_output/is_opendrain/invert_output.
 * Module input pins: in/in_not. Module output pins: is_opendrain/invert_output.
 * Module outputs are driven (DDR set) only from the first write(): nothing is
 * driven until HAL runs. Configuration changes are written in the order invert,
 * open-drain, (alt-source at load only), DDR last, so no pin is driven before its
 * source and polarity are right. */
#include "rtapi.h"
#include "hal.h"
#include "hm2.h"

#define REG_DATA 0
#define REG_DDR 1
#define REG_ALTSOURCE 2
#define REG_OPENDRAIN 3
#define REG_INVERT 4

int hm2_ioport_parse(struct hostmot2 *hm2, const struct hm2_md *md)
{
	struct hm2_ioport *io = &hm2->ioport;
	char err[HM2_ERRLEN];
	int rc;

	if (hm2_md_is_consistent(md, err, sizeof(err))) {
		HM2_ERR(hm2, "%s", err);
		return -EINVAL;
	}
	if (md->instances != hm2->idrom.io_ports) {
		HM2_ERR(hm2, "ioport: %u instances, but the IDROM says %u IOPorts", md->instances,
			hm2->idrom.io_ports);
		return -EINVAL;
	}
	io->md = md;
	io->num = md->instances;
	rc = hm2_tram_add_read(hm2, hm2_md_addr(md, REG_DATA, 0), io->num * 4, &io->data_rd);
	if (!rc)
		rc = hm2_tram_add_write(hm2, hm2_md_addr(md, REG_DATA, 0), io->num * 4, &io->data_wr);
	return rc;
}

void hm2_pins_allocate(struct hostmot2 *hm2, int gtag, int n)
{
	int i;

	for (i = 0; i < hm2->num_pins; i++) {
		struct hm2_pin *p = &hm2->pin[i];
		int unit = p->pd.sec_unit, out = p->pd.sec_pin & 0x80;

		if (p->pd.sec_tag != gtag || n <= 0)
			continue;
		if (!(unit & 0x80) && unit >= n)
			continue;
		if (gtag == HM2_GTAG_STEPGEN && out && (p->pd.sec_pin & 0x7F) > hm2->cfg.stepgen_width)
			continue;	/* masked by stepgen_width: stays GPIO */
		p->gtag = gtag;
		p->dir = out ? HM2_PIN_OUT : HM2_PIN_IN;
	}
}

int hm2_ioport_export(struct hostmot2 *hm2)
{
	const char *b = hm2->llio->name;
	int id = hm2->llio->comp_id, i, rc = 0;

	for (i = 0; i < hm2->num_pins && !rc; i++) {
		struct hm2_pin *p = &hm2->pin[i];
		struct hm2_gpio *g = &p->gpio;
		int gpio = p->gtag == HM2_GTAG_IOPORT;

		if (gpio || p->dir == HM2_PIN_IN) {
			rc = hal_pin_bit_newf(HAL_OUT, &g->in, id, "%s.gpio.%03d.in", b, i);
			if (!rc)
				rc = hal_pin_bit_newf(HAL_OUT, &g->in_not, id, "%s.gpio.%03d.in_not", b, i);
		}
		if (!rc && gpio) {
			rc = hal_pin_bit_newf(HAL_IN, &g->out, id, "%s.gpio.%03d.out", b, i);
			if (!rc)
				rc = hal_param_bit_newf(HAL_RW, &g->is_output, id, "%s.gpio.%03d.is_output", b, i);
		}
		if (!rc && (gpio || p->dir == HM2_PIN_OUT)) {
			rc = hal_param_bit_newf(HAL_RW, &g->is_opendrain, id, "%s.gpio.%03d.is_opendrain",
						b, i);
			if (!rc)
				rc = hal_param_bit_newf(HAL_RW, &g->invert_output, id,
							"%s.gpio.%03d.invert_output", b, i);
		}
	}
	return rc;
}

/* Outputs of these modules are driven from load on (hostmot2.md 6): a serial bus or
 * the encoder multiplexer must idle correctly before HAL runs; all other module
 * outputs wait for the first write(). */
static int drives_at_load(int gtag)
{
	return gtag == HM2_GTAG_BSPI || gtag == HM2_GTAG_UART_TX || gtag == HM2_GTAG_MUXED_ENCODER_SEL;
}

/* Registers as the HAL settings ask for them now. */
static void compute(struct hostmot2 *hm2)
{
	struct hm2_ioport *io = &hm2->ioport;
	int i;

	for (i = 0; i < io->num; i++) {
		io->ddr[i] = io->alt[i] = io->od[i] = 0;
		io->inv[i] = io->w_inv[i];
	}
	for (i = 0; i < hm2->num_pins; i++) {
		struct hm2_pin *p = &hm2->pin[i];
		rtapi_u32 m = 1u << p->bit;
		int output;

		if (p->gtag == HM2_GTAG_IOPORT) {
			output = p->gpio.is_output;
		} else {
			io->alt[p->port] |= m;
			output = p->dir == HM2_PIN_OUT && (io->module_outputs_on || drives_at_load(p->gtag));
		}
		if (output) {
			io->ddr[p->port] |= m;
			if (p->gpio.is_opendrain)
				io->od[p->port] |= m;
			if (p->gpio.invert_output)
				io->inv[p->port] |= m;
			else
				io->inv[p->port] &= ~m;
		}
	}
}

static void write_reg(struct hostmot2 *hm2, int reg, rtapi_u32 *vals)
{
	hm2_write_now(hm2, hm2_md_addr(hm2->ioport.md, reg, 0), vals, hm2->ioport.num * 4);
}

void hm2_ioport_force_write(struct hostmot2 *hm2)
{
	struct hm2_ioport *io = &hm2->ioport;
	int i;

	compute(hm2);
	write_reg(hm2, REG_INVERT, io->inv);
	write_reg(hm2, REG_OPENDRAIN, io->od);
	write_reg(hm2, REG_ALTSOURCE, io->alt);
	write_reg(hm2, REG_DDR, io->ddr);
	for (i = 0; i < io->num; i++) {
		io->w_inv[i] = io->inv[i];
		io->w_od[i] = io->od[i];
		io->w_ddr[i] = io->ddr[i];
	}
}

static int changed(rtapi_u32 *now, rtapi_u32 *written, int n)
{
	int i, c = 0;

	for (i = 0; i < n; i++) {
		if (now[i] != written[i])
			c = 1;
		written[i] = now[i];
	}
	return c;
}

void hm2_ioport_write(struct hostmot2 *hm2)
{
	struct hm2_ioport *io = &hm2->ioport;
	int i;

	for (i = 0; i < io->num; i++)
		io->data_wr[i] = 0;
	for (i = 0; i < hm2->num_pins; i++) {
		struct hm2_pin *p = &hm2->pin[i];

		if (p->gtag == HM2_GTAG_IOPORT && *p->gpio.out)
			io->data_wr[p->port] |= 1u << p->bit;
	}
	compute(hm2);
	if (changed(io->inv, io->w_inv, io->num))
		write_reg(hm2, REG_INVERT, io->inv);
	if (changed(io->od, io->w_od, io->num))
		write_reg(hm2, REG_OPENDRAIN, io->od);
	if (changed(io->ddr, io->w_ddr, io->num))
		write_reg(hm2, REG_DDR, io->ddr);
}

void hm2_ioport_read(struct hostmot2 *hm2)
{
	int i;

	for (i = 0; i < hm2->num_pins; i++) {
		struct hm2_pin *p = &hm2->pin[i];
		int v;

		if (!p->gpio.in)
			continue;
		v = (hm2->ioport.data_rd[p->port] >> p->bit) & 1;
		*p->gpio.in = v;
		*p->gpio.in_not = !v;
	}
}

static const char *owner_name(int gtag)
{
	const char *n = hm2_gtag_name(gtag);

	if (gtag == HM2_GTAG_MUXED_ENCODER_SEL)
		return "muxed encoder select";
	return n ? n : "unknown module";
}

void hm2_ioport_print_pins(struct hostmot2 *hm2)
{
	int i;

	for (i = 0; i < hm2->num_pins; i++) {
		struct hm2_pin *p = &hm2->pin[i];
		const char *conn = hm2->llio->ioport_connector_name[p->port];

		if (p->gtag == HM2_GTAG_IOPORT)
			HM2_INFO(hm2, "IO pin %03d (%s-%02d): GPIO", i, conn ? conn : "?",
				 hm2_connector_pin(hm2->idrom.port_width, p->bit));
		else
			HM2_INFO(hm2, "IO pin %03d (%s-%02d): %s #%d, pin code 0x%02X (%s)", i,
				 conn ? conn : "?", hm2_connector_pin(hm2->idrom.port_width, p->bit),
				 owner_name(p->gtag), p->pd.sec_unit & 0x7F, p->pd.sec_pin,
				 p->dir == HM2_PIN_OUT ? "output" : "input");
	}
}

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* mesa_7i65.c - the Mesa 7i65 octuple servo card on a HostMot2 buffered SPI port,
 * mesa_7i65(9):
 *   loadrt mesa_7i65 bspi_chans=hm2_5i23.0.bspi.0[,hm2_5i23.0.bspi.1...]
 * One instance mesa-7i65.N per BSPI name (printed when the board loads). It has no
 * HAL functions of its own: hostmot2 runs its frames inside the board's read and
 * write (hm2_serial.h), so add those to the servo thread as usual. Glue only
 * (integer); the per-cycle work is in mesa_7i65_fp.c. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "hal.h"
#include "hm2_serial.h"
#include "mesa_7i65.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("Mesa 7i65 servo card on a hostmot2 BSPI port");

#define MAX_CARDS 8

static char *bspi_chans[MAX_CARDS];
RTAPI_MP_ARRAY_STRING(bspi_chans, MAX_CARDS, "BSPI instances with a 7i65, e.g. hm2_5i23.0.bspi.0");

static int comp_id;
static struct m7i65 *cards;
static int num_cards;

static int export_pins(struct m7i65 *c, int n)
{
	int i, rc = 0;

	for (i = 0; i < M7I65_CHANNELS && !rc; i++) {
		rc = hal_pin_float_newf(HAL_IN, &c->out[i], comp_id, "mesa-7i65.%d.analogue.%d.out", n, i);
		if (!rc)
			rc = hal_pin_float_newf(HAL_OUT, &c->in[i], comp_id, "mesa-7i65.%d.analogue.%d.in", n, i);
		if (!rc)
			rc = hal_pin_bit_newf(HAL_IN, &c->enable[i], comp_id, "mesa-7i65.%d.enable.%d.out", n, i);
		if (!rc)
			rc = hal_param_float_newf(HAL_RW, &c->scale[i], comp_id, "mesa-7i65.%d.scale-%d", n, i);
		if (!rc)
			rc = hal_param_bit_newf(HAL_RW, &c->bipolar[i], comp_id, "mesa-7i65.%d.is-bipolar-%d", n, i);
		c->bipolar[i] = 1;
	}
	for (i = 0; i < M7I65_INPUTS && !rc; i++)
		rc = hal_pin_bit_newf(HAL_OUT, &c->din[i], comp_id, "mesa-7i65.%d.digital.%d.in", n, i);
	if (!rc)
		rc = hal_pin_bit_newf(HAL_OUT, &c->has_bit, comp_id, "mesa-7i65.%d.watchdog.has-bit", n);
	return rc;
}

/* chip selects as the card wires them; then the frames of one cycle */
static int setup_bspi(struct m7i65 *c)
{
	const char *b = c->bspi;
	int i, rc;

	rc = hm2_bspi_setup_chan(b, M7I65_CHAN_DAC0, 1, 24, 25000, 0, 0, 1, 0, 1);
	if (!rc) rc = hm2_bspi_setup_chan(b, M7I65_CHAN_DAC1, 2, 24, 25000, 0, 0, 1, 0, 1);
	if (!rc) rc = hm2_bspi_setup_chan(b, M7I65_CHAN_ADC, 3, 16, 6000, 0, 1, 0, 0, 0);
	if (!rc) rc = hm2_bspi_setup_chan(b, M7I65_CHAN_CPLD, 4, 12, 6000, 0, 0, 0, 0, 0);
	for (i = 0; i < M7I65_CHANNELS && !rc; i++)
		rc = hm2_tram_add_bspi_frame(b, i < 4 ? M7I65_CHAN_DAC0 : M7I65_CHAN_DAC1, &c->dac_wr[i],
					     &c->dac_rd[i]);
	for (i = 0; i < M7I65_CHANNELS && !rc; i++)
		rc = hm2_tram_add_bspi_frame(b, M7I65_CHAN_ADC, &c->adc_wr[i], &c->adc_rd[i]);
	if (!rc) rc = hm2_tram_add_bspi_frame(b, M7I65_CHAN_CPLD, &c->cpld_wr, &c->cpld_rd);
	if (!rc) rc = hm2_bspi_set_write_function(b, m7i65_write_fp, c);
	if (!rc) rc = hm2_bspi_set_read_function(b, m7i65_read_fp, c);
	if (!rc) rc = hm2_allocate_bspi_tram(b);
	return rc;
}

static void release_all(void)
{
	int i;

	for (i = 0; i < num_cards; i++)
		if (!cards[i].released) {
			hm2_bspi_release(cards[i].bspi);
			cards[i].released = 1;
		}
}

int rtapi_app_main(void)
{
	int i, rc = 0;
	const char *name;

	comp_id = hal_init("mesa_7i65");
	if (comp_id < 0)
		return comp_id;
	for (num_cards = 0; num_cards < MAX_CARDS && bspi_chans[num_cards] && *bspi_chans[num_cards];)
		num_cards++;
	if (!num_cards) {
		rtapi_print_msg(RTAPI_MSG_ERR, "mesa_7i65: bspi_chans= is required (the BSPI names "
				"hostmot2 printed, e.g. hm2_5i23.0.bspi.0)\n");
		hal_exit(comp_id);
		return -EINVAL;
	}
	cards = hal_malloc(num_cards * sizeof(*cards));
	if (!cards) {
		hal_exit(comp_id);
		return -ENOMEM;
	}
	memset(cards, 0, num_cards * sizeof(*cards));
	for (i = 0; i < num_cards; i++)
		cards[i].released = 1;
	for (i = 0; i < num_cards && !rc; i++) {
		for (name = bspi_chans[i]; *name == ' '; name++)
			;	/* "a, b" as the page writes it */
		rtapi_strlcpy(cards[i].bspi, name, sizeof(cards[i].bspi));
		rc = export_pins(&cards[i], i);
		rtapi_fpu_begin();
		m7i65_init_fp(&cards[i]);
		rtapi_fpu_end();
		if (!rc) {
			cards[i].released = 0;
			rc = setup_bspi(&cards[i]);
		}
		if (rc)
			rtapi_print_msg(RTAPI_MSG_ERR, "mesa_7i65: bspi_chans=%s: cannot use it (%d)\n",
					cards[i].bspi, rc);
	}
	if (rc) {
		release_all();
		hal_exit(comp_id);
		return rc;
	}
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	release_all();
	hal_exit(comp_id);
}

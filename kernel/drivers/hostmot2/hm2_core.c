/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_core.c - the hostmot2 module: its parameters, hm2_register()/hm2_unregister()
 * for board drivers, and each board's HAL functions read, write, read-request,
 * read_gpio, write_gpio (hostmot2(9) FUNCTIONS; order of work: hostmot2.md 9).
 * Integer-only: the float parts of read/write are the modules' *_fp.c functions,
 * called from here inside the FP thread (read/write are exported with uses_fp). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "hal.h"
#include "hm2.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("Driver core for the Mesa HostMot2 FPGA firmware");

static int debug_idrom;
RTAPI_MP_INT(debug_idrom, "log the IDROM header");
static int debug_module_descriptors;
RTAPI_MP_INT(debug_module_descriptors, "log the module descriptors");
static int debug_pin_descriptors;
RTAPI_MP_INT(debug_pin_descriptors, "log the pin descriptors");
static int debug_modules;
RTAPI_MP_INT(debug_modules, "log the modules used");
static int use_serial_numbers;
RTAPI_MP_INT(use_serial_numbers, "name smart-serial pins by serial number");

static int comp_id;

/* Module types this driver knows but does not drive yet: their pins stay GPIO. */
static int is_known_unsupported(int gtag)
{
	return hm2_gtag_name(gtag) && gtag != HM2_GTAG_WATCHDOG && gtag != HM2_GTAG_IOPORT &&
	       gtag != HM2_GTAG_ENCODER && gtag != HM2_GTAG_STEPGEN && gtag != HM2_GTAG_PWMGEN &&
	       gtag != HM2_GTAG_HM2DPLL && gtag != HM2_GTAG_LED && gtag != HM2_GTAG_MUXED_ENCODER &&
	       gtag != HM2_GTAG_TPPWM && gtag != HM2_GTAG_BSPI && gtag != HM2_GTAG_UART_TX &&
	       gtag != HM2_GTAG_UART_RX;
}

static int read_words(struct hostmot2 *hm2, rtapi_u32 addr, rtapi_u32 *w, int n)
{
	int rc = hm2_read_now(hm2, addr, w, n * 4);

	if (rc < 0)
		HM2_ERR(hm2, "cannot read %d words at 0x%04X (%d)", n, addr, rc);
	return rc < 0 ? rc : 0;
}

/* Checks 1-8 of hostmot2.md 2.1, in that order. */
static int read_idrom(struct hostmot2 *hm2)
{
	struct hm2_board_shape shape = { hm2->llio->num_ioport_connectors,
					 hm2->llio->pins_per_connector };
	rtapi_u32 w[HM2_IDROM_WORDS];
	char err[HM2_ERRLEN];
	int rc;

	rc = read_words(hm2, HM2_ADDR_IOCOOKIE, w, 3);
	if (rc)
		return rc;
	if (hm2_idrom_check_cookie(w, err, sizeof(err))) {
		HM2_ERR(hm2, "%s", err);
		return -EINVAL;
	}
	rc = read_words(hm2, HM2_ADDR_IDROM_OFFSET, w, 1);
	if (rc)
		return rc;
	hm2->idrom_offset = hm2_idrom_offset(w[0]);
	rc = read_words(hm2, hm2->idrom_offset, w, HM2_IDROM_WORDS);
	if (rc)
		return rc;
	if (hm2_idrom_parse(w, &shape, &hm2->idrom, err, sizeof(err))) {
		HM2_ERR(hm2, "%s", err);
		return -EINVAL;
	}
	if (debug_idrom)
		HM2_INFO(hm2, "IDROM at 0x%04X: type %u, board '%s', FPGA size %u pins %u, %u IOPorts "
			 "x %u = %u pins, clocks %u / %u Hz", hm2->idrom_offset, hm2->idrom.idrom_type,
			 hm2->idrom.board_name, hm2->idrom.fpga_size, hm2->idrom.fpga_pins,
			 hm2->idrom.io_ports, hm2->idrom.port_width, hm2->idrom.io_width,
			 hm2->idrom.clock_low, hm2->idrom.clock_high);
	return 0;
}

static int read_pin_descriptors(struct hostmot2 *hm2)
{
	int n = hm2->idrom.io_width, i, rc;
	rtapi_u32 *w;
	char err[HM2_ERRLEN];

	hm2->pin = hal_malloc(n * sizeof(*hm2->pin));
	w = hal_malloc(n * 4);
	if (!hm2->pin || !w)
		return -ENOMEM;
	hm2->num_pins = n;
	rc = read_words(hm2, hm2->idrom_offset + hm2->idrom.offset_to_pin_desc, w, n);
	if (rc)
		return rc;
	for (i = 0; i < n; i++) {
		struct hm2_pin *p = &hm2->pin[i];

		if (hm2_pd_parse(w[i], i, &p->pd, err, sizeof(err))) {
			HM2_ERR(hm2, "%s", err);
			return -EINVAL;
		}
		p->port = i / hm2->idrom.port_width;
		p->bit = i % hm2->idrom.port_width;
		p->gtag = HM2_GTAG_IOPORT;
		if (debug_pin_descriptors)
			HM2_INFO(hm2, "pin %03d: 0x%08X (secondary tag %u unit %u pin 0x%02X)", i, w[i],
				 p->pd.sec_tag, p->pd.sec_unit, p->pd.sec_pin);
	}
	return 0;
}

static int read_module_descriptors(struct hostmot2 *hm2)
{
	rtapi_u32 w[3];
	char err[HM2_ERRLEN];
	int i, j, rc;

	for (i = 0; i < HM2_MAX_MODULE_DESCRIPTORS; i++) {
		rc = read_words(hm2, hm2->idrom_offset + hm2->idrom.offset_to_modules + 12 * i, w, 3);
		if (rc)
			return rc;
		rc = hm2_md_parse(w, &hm2->idrom, &hm2->md[i], err, sizeof(err));
		if (rc == 1)
			break;
		if (rc) {
			HM2_ERR(hm2, "%s", err);
			return rc;
		}
		for (j = 0; j < i; j++) {
			if (hm2->md[j].gtag == hm2->md[i].gtag) {
				HM2_ERR(hm2, "inconsistent firmware: two module descriptors for GTag %u",
					hm2->md[i].gtag);
				return -EINVAL;
			}
		}
		if (debug_module_descriptors)
			HM2_INFO(hm2, "MD %d: GTag %u v%u, %u instances at 0x%04X, %u registers, clock %u Hz",
				 i, hm2->md[i].gtag, hm2->md[i].version, hm2->md[i].instances,
				 hm2->md[i].base_address, hm2->md[i].num_registers, hm2->md[i].clock_freq);
	}
	hm2->num_mds = i;
	return 0;
}

/* IOPort first (every other module needs the pin table), the DPLL next (encoder and
 * stepgen create timer-number only when it exists), then the rest in MD order. */
static int parse_module_descriptors(struct hostmot2 *hm2)
{
	int i, rc, have_ioport = 0;

	for (i = 0; i < hm2->num_mds; i++) {
		if (hm2->md[i].gtag == HM2_GTAG_IOPORT) {
			rc = hm2_ioport_parse(hm2, &hm2->md[i]);
			if (rc)
				return rc;
			have_ioport = 1;
		}
	}
	if (!have_ioport) {
		HM2_ERR(hm2, "the firmware has no IOPort module");
		return -EINVAL;
	}
	for (i = 0; i < hm2->num_mds; i++)
		if (hm2->md[i].gtag == HM2_GTAG_HM2DPLL && (rc = hm2_dpll_parse(hm2, &hm2->md[i])))
			return rc;
	for (i = 0; i < hm2->num_mds; i++) {
		const struct hm2_md *md = &hm2->md[i];

		switch (md->gtag) {
		case HM2_GTAG_IOPORT:
		case HM2_GTAG_HM2DPLL:
			rc = 0;
			break;
		case HM2_GTAG_WATCHDOG: rc = hm2_watchdog_parse(hm2, md); break;
		case HM2_GTAG_ENCODER:
		case HM2_GTAG_MUXED_ENCODER: rc = hm2_encoder_parse(hm2, md); break;
		case HM2_GTAG_TPPWM: rc = hm2_tppwm_parse(hm2, md); break;
		case HM2_GTAG_BSPI: rc = hm2_bspi_parse(hm2, md); break;
		case HM2_GTAG_UART_TX:
		case HM2_GTAG_UART_RX: rc = hm2_uart_parse(hm2, md); break;
		case HM2_GTAG_STEPGEN: rc = hm2_stepgen_parse(hm2, md); break;
		case HM2_GTAG_PWMGEN: rc = hm2_pwmgen_parse(hm2, md); break;
		case HM2_GTAG_LED: rc = hm2_led_parse(hm2, md); break;
		default:
			if (is_known_unsupported(md->gtag))
				HM2_WARN(hm2, "%s (GTag %u): not driven by this version; its pins stay GPIO",
					 hm2_gtag_name(md->gtag), md->gtag);
			else
				HM2_INFO(hm2, "ignoring unknown module GTag %u", md->gtag);
			rc = 0;
		}
		if (rc)
			return rc;
		if (debug_modules && hm2_gtag_name(md->gtag))
			HM2_INFO(hm2, "module %s: %u instances in the firmware", hm2_gtag_name(md->gtag),
				 md->instances);
	}
	return hm2_uart_allocate(hm2);
}

/* Config keywords naming modules this firmware does not have, or that this driver
 * does not drive: asking for instances of them cannot be satisfied. */
static int check_counts(struct hostmot2 *hm2)
{
	/* driven: the module's parse checked the count; only "none at all" is left */
	static const struct { int key, gtag, driven; } map[] = {
		{ HM2_NUM_3PWMGENS, HM2_GTAG_TPPWM, 1 }, { HM2_NUM_RCPWMGENS, HM2_GTAG_RCPWMGEN, 0 },
		{ HM2_NUM_RESOLVERS, HM2_GTAG_RESOLVER, 0 }, { HM2_NUM_BSPIS, HM2_GTAG_BSPI, 1 },
		{ HM2_NUM_UARTS, HM2_GTAG_UART_TX, 1 }, { HM2_NUM_PKTUARTS, HM2_GTAG_PKTUART_TX, 0 },
		{ HM2_NUM_INMS, HM2_GTAG_INM, 0 }, { HM2_NUM_INMUXS, HM2_GTAG_INMUX, 0 },
		{ HM2_NUM_OUTMS, HM2_GTAG_OUTM, 0 }, { HM2_NUM_SSRS, HM2_GTAG_SSR, 0 },
		{ HM2_NUM_ONESHOTS, HM2_GTAG_ONESHOT, 0 }, { HM2_NUM_PERIODMS, HM2_GTAG_PERIODM, 0 },
		{ HM2_NUM_XY2MODS, HM2_GTAG_XY2MOD, 0 },
	};
	char err[HM2_ERRLEN];
	unsigned k;
	int i;

	for (k = 0; k < sizeof(map) / sizeof(map[0]); k++) {
		int have = 0;

		for (i = 0; i < hm2->num_mds; i++)
			if (hm2->md[i].gtag == map[k].gtag)
				have = hm2->md[i].instances;
		if (hm2_config_instances(&hm2->cfg, map[k].key, have, err, sizeof(err)) < 0) {
			HM2_ERR(hm2, "%s", err);
			return -EINVAL;
		}
		if (have && !map[k].driven && hm2->cfg.num[map[k].key] > 0) {
			HM2_ERR(hm2, "config: %s=%d: this driver does not drive that module yet",
				hm2_config_count_name(map[k].key), hm2->cfg.num[map[k].key]);
			return -EINVAL;
		}
	}
	if (hm2->cfg.num[HM2_NUM_ENCODERS] > 0 && !hm2->encoder.md) {
		HM2_ERR(hm2, "config: num_encoders=%d, but the firmware has only 0",
			hm2->cfg.num[HM2_NUM_ENCODERS]);
		return -EINVAL;
	}
	if (hm2->cfg.num[HM2_NUM_STEPGENS] > 0 && !hm2->stepgen.md) {
		HM2_ERR(hm2, "config: num_stepgens=%d, but the firmware has only 0",
			hm2->cfg.num[HM2_NUM_STEPGENS]);
		return -EINVAL;
	}
	if (hm2->cfg.num[HM2_NUM_PWMGENS] > 0 && !hm2->pwmgen.md) {
		HM2_ERR(hm2, "config: num_pwmgens=%d, but the firmware has only 0",
			hm2->cfg.num[HM2_NUM_PWMGENS]);
		return -EINVAL;
	}
	for (i = 0; i < HM2_ABS_CHANNELS; i++) {
		if (hm2->cfg.ssi_format[i][0] || hm2->cfg.biss_format[i][0] || hm2->cfg.fanuc_format[i][0]) {
			HM2_ERR(hm2, "config: %s_chan_%d: this driver does not drive absolute encoders yet",
				hm2->cfg.ssi_format[i][0] ? "ssi" : hm2->cfg.biss_format[i][0] ? "biss" : "fanuc", i);
			return -EINVAL;
		}
	}
	if (hm2->cfg.num_sserials) {
		HM2_ERR(hm2, "config: sserial_port_%d: this driver does not drive smart serial yet",
			hm2->cfg.num_sserials - 1);
		return -EINVAL;
	}
	return 0;
}

static void force_write_all(struct hostmot2 *hm2)
{
	hm2_watchdog_force_write(hm2);
	hm2_ioport_force_write(hm2);
	hm2_encoder_force_write(hm2);
	hm2_pwmgen_force_write(hm2);
	hm2_stepgen_force_write(hm2);
	hm2_tppwm_force_write(hm2);
	hm2_bspi_force_write(hm2);
	hm2_uart_force_write(hm2);
	hm2_dpll_force_write(hm2);
	hm2->led.force = 1;
	hm2_led_write(hm2);
	hm2_tram_flush_writes(hm2);
}

/* ---- the HAL functions ---- */

static void hm2_read_request(void *arg, long period)
{
	struct hostmot2 *hm2 = arg;

	if (hm2->io_error || hm2->closing)
		return;
	if (hm2_tram_request_reads(hm2) == 0)
		hm2->read_requested = 1;
}

static void hm2_read(void *arg, long period)
{
	struct hostmot2 *hm2 = arg;

	if (hm2->io_error || hm2->closing)
		return;
	if (!hm2->read_requested)
		hm2_read_request(arg, period);
	if (!hm2->read_requested)
		return;
	hm2->read_requested = 0;
	if (hm2_tram_receive_reads(hm2))
		return;		/* -EAGAIN: no data this cycle; errors set io_error */
	hm2_watchdog_read(hm2);
	hm2_ioport_read(hm2);
	hm2_encoder_read_fp(hm2, period);
	hm2_stepgen_read_fp(hm2, period);
	hm2_bspi_read(hm2);
	hm2_tppwm_read(hm2);
	hm2_dpll_read_fp(hm2);
	hm2_raw_read(hm2);
}

static void hm2_write(void *arg, long period)
{
	struct hostmot2 *hm2 = arg;
	struct hm2_watchdog *wd = &hm2->watchdog;

	if (hm2->io_error || hm2->closing)
		return;
	hm2->period_ns = period;
	if (hm2->llio->needs_reset || (wd->needs_force_write && !*wd->has_bit)) {
		/* the user cleared io_error or has_bit: restore every register */
		hm2->llio->needs_reset = 0;
		wd->needs_force_write = 0;
		force_write_all(hm2);
	}
	hm2->ioport.module_outputs_on = 1;	/* deferred module pin directions */
	hm2_watchdog_write(hm2, period);
	hm2_ioport_write(hm2);
	hm2_pwmgen_prepare_write_fp(hm2);
	hm2_stepgen_prepare_write_fp(hm2, period);
	hm2_tppwm_prepare_write_fp(hm2);
	hm2_encoder_write_fp(hm2);
	hm2_tram_write(hm2);
	hm2_bspi_write(hm2);
	hm2_pwmgen_write(hm2);
	hm2_uart_write(hm2);
	hm2_tppwm_write(hm2);
	hm2_stepgen_write(hm2);
	hm2_encoder_write(hm2);
	hm2_dpll_write_fp(hm2, period);
	hm2_led_write(hm2);
	hm2_raw_write(hm2);
	hm2_tram_flush_writes(hm2);
}

static void hm2_read_gpio(void *arg, long period)
{
	struct hostmot2 *hm2 = arg;
	struct hm2_ioport *io = &hm2->ioport;

	if (hm2->io_error || hm2->closing)
		return;
	if (hm2_read_now(hm2, hm2_md_addr(io->md, 0, 0), io->data_rd, io->num * 4) == 0)
		hm2_ioport_read(hm2);
}

static void hm2_write_gpio(void *arg, long period)
{
	struct hostmot2 *hm2 = arg;
	struct hm2_ioport *io = &hm2->ioport;

	if (hm2->io_error || hm2->closing)
		return;
	hm2_ioport_write(hm2);
	hm2_write_now(hm2, hm2_md_addr(io->md, 0, 0), io->data_wr, io->num * 4);
	hm2_watchdog_write(hm2, period);
	hm2_tram_flush_writes(hm2);
}

static int export_functions(struct hostmot2 *hm2)
{
	const char *b = hm2->llio->name;
	int id = hm2->llio->comp_id, rc = 0;
	char n[HAL_NAME_LEN + 1];

	if (hm2->llio->split_read) {
		rtapi_snprintf(n, sizeof(n), "%s.read-request", b);
		rc = hal_export_funct(n, hm2_read_request, hm2, 0, 0, id);
	}
	rtapi_snprintf(n, sizeof(n), "%s.read", b);
	if (!rc)
		rc = hal_export_funct(n, hm2_read, hm2, 1, 0, id);
	rtapi_snprintf(n, sizeof(n), "%s.write", b);
	if (!rc)
		rc = hal_export_funct(n, hm2_write, hm2, 1, 0, id);
	if (hm2->llio->threadsafe) {
		rtapi_snprintf(n, sizeof(n), "%s.read_gpio", b);
		if (!rc)
			rc = hal_export_funct(n, hm2_read_gpio, hm2, 0, 0, id);
		rtapi_snprintf(n, sizeof(n), "%s.write_gpio", b);
		if (!rc)
			rc = hal_export_funct(n, hm2_write_gpio, hm2, 0, 0, id);
	}
	return rc;
}

static int export_all(struct hostmot2 *hm2)
{
	int rc = hm2_ioport_export(hm2);

	if (!rc) rc = hm2_watchdog_export(hm2);
	if (!rc) rc = hm2_dpll_export(hm2);
	if (!rc) rc = hm2_encoder_export(hm2);
	if (!rc) rc = hm2_stepgen_export(hm2);
	if (!rc) rc = hm2_pwmgen_export(hm2);
	if (!rc) rc = hm2_tppwm_export(hm2);
	if (!rc) rc = hm2_bspi_export(hm2);
	if (!rc) rc = hm2_uart_export(hm2);
	if (!rc) rc = hm2_led_export(hm2);
	if (!rc) rc = hm2_raw_export(hm2);
	if (!rc) rc = hm2_alias_module_pins(hm2);
	if (rc)
		HM2_ERR(hm2, "cannot create the HAL objects (%d)", rc);
	return rc;
}

static int register_board(struct hm2_llio *llio, const char *config);

/* The serial modules put their names in lists sub-drivers search: a board that
 * fails half way takes them out again. */
int hm2_register(struct hm2_llio *llio, const char *config)
{
	int rc = register_board(llio, config);

	if (rc && llio && llio->hm2) {
		hm2_bspi_cleanup(llio->hm2);
		hm2_uart_cleanup(llio->hm2);
		llio->hm2 = 0;
	}
	return rc;
}
EXPORT_SYMBOL(hm2_register);

static int register_board(struct hm2_llio *llio, const char *config)
{
	struct hostmot2 *hm2;
	char err[HM2_ERRLEN];
	int rc;

	if (!llio || !llio->read || !llio->write || llio->num_ioport_connectors < 1 ||
	    llio->num_ioport_connectors > HM2_LLIO_MAX_CONNECTORS) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hostmot2: hm2_register: incomplete board description\n");
		return -EINVAL;
	}
	hm2 = hal_malloc(sizeof(*hm2));
	if (!hm2) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: out of HAL memory\n", llio->name);
		return -ENOMEM;
	}
	hm2->llio = llio;
	llio->hm2 = hm2;
	llio->needs_reset = 0;
	if (hm2_config_parse(config, &hm2->cfg, err, sizeof(err))) {
		HM2_ERR(hm2, "%s", err);
		return -EINVAL;
	}
	rc = hm2_firmware_load(hm2);	/* firmware=: before the board is read */
	if (rc)
		return rc;
	rc = hal_param_bit_newf(HAL_RW, &hm2->io_error, llio->comp_id, "%s.io_error", llio->name);
	if (rc)
		return rc;
	llio->io_error = &hm2->io_error;
	rc = read_idrom(hm2);
	if (!rc) rc = read_pin_descriptors(hm2);
	if (!rc) rc = read_module_descriptors(hm2);
	if (!rc) rc = parse_module_descriptors(hm2);
	if (!rc) rc = check_counts(hm2);
	if (!rc) rc = hm2_tram_allocate(hm2);
	if (!rc) rc = export_all(hm2);
	if (rc)
		return rc;
	rtapi_fpu_begin();
	hm2_encoder_init_fp(hm2);
	hm2_stepgen_init_fp(hm2);
	hm2_pwmgen_init_fp(hm2);
	hm2_tppwm_init_fp(hm2);
	hm2_dpll_init_fp(hm2);
	rtapi_fpu_end();
	hm2_ioport_print_pins(hm2);

	/* registers to a known state, then one read (counts start at 0) and one write
	 * (GPIO outputs 0, stepgen rates 0, PWM values 0) */
	force_write_all(hm2);
	rc = hm2_tram_request_reads(hm2);
	if (!rc)
		rc = hm2_tram_receive_reads(hm2);
	if (rc) {
		HM2_ERR(hm2, "the first read of the board failed (%d)", rc);
		return rc;
	}
	hm2_ioport_read(hm2);
	rtapi_fpu_begin();
	hm2_encoder_prepare_fp(hm2);
	rtapi_fpu_end();
	hm2_stepgen_prepare(hm2);
	rc = hm2_tram_write(hm2);
	if (!rc)
		rc = hm2_tram_flush_writes(hm2);
	if (!rc)
		rc = export_functions(hm2);
	if (rc)
		return rc;
	HM2_INFO(hm2, "registered: %s, %d IO pins, %d encoders, %d stepgens, %d pwmgens%s%s",
		 hm2->idrom.board_name, hm2->num_pins, hm2->encoder.num, hm2->stepgen.num,
		 hm2->pwmgen.num, hm2->watchdog.md ? ", watchdog" : "", hm2->dpll.md ? ", dpll" : "");
	return 0;
}

void hm2_unregister(struct hm2_llio *llio)
{
	struct hostmot2 *hm2 = llio ? llio->hm2 : 0;

	if (!hm2)
		return;
	/* the thread may still run read/write until the board's component goes away:
	 * from now on they return at once, and the bite is written directly */
	hm2->closing = 1;
	hm2_bspi_cleanup(hm2);
	hm2_uart_cleanup(hm2);
	if (!hm2->io_error)
		hm2_watchdog_bite_now(hm2);
	llio->hm2 = 0;
}
EXPORT_SYMBOL(hm2_unregister);

int rtapi_app_main(void)
{
	comp_id = hal_init("hostmot2");
	if (comp_id < 0)
		return comp_id;
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_alias.c - second names (hal_pin_alias/hal_param_alias, the project's way of
 * keeping two documents' names alive, RULINGS.md "motion names"):
 *  - names of the EMC2-era hostmot2 page that hostmot2.txt changed (encoder
 *    "rawcount" -> "rawcounts"), made by the modules with hm2_alias_pin();
 *  - hostmot2.txt's aliases for IO pins owned by a module's output: the pin's
 *    gpio.NNN.invert_output and .is_opendrain params are also reachable as
 *    <module>.<NN>.<pin>.invert_output (pwmgen.00.out0.invert_output); when one
 *    module pin is on several IO pins, a .<k>. is inserted (pwmgen.00.0.enable...).
 * Integer-only, load time only. */
#include "rtapi.h"
#include "rtapi_string.h"
#include "hal.h"
#include "hm2.h"

/* prefix.alias becomes a second name of prefix.name, through hal_pin_alias or
 * hal_param_alias */
static int make_alias(struct hostmot2 *hm2, int (*alias_fn)(const char *, const char *),
		      const char *prefix, const char *name, const char *alias)
{
	char n[HAL_NAME_LEN + 1], a[HAL_NAME_LEN + 1];
	int rc;

	rtapi_snprintf(n, sizeof(n), "%s.%s", prefix, name);
	rtapi_snprintf(a, sizeof(a), "%s.%s", prefix, alias);
	rc = alias_fn(n, a);
	if (rc)
		HM2_ERR(hm2, "cannot make %s an alias of %s (%d)", a, n, rc);
	return rc;
}

int hm2_alias_pin(struct hostmot2 *hm2, const char *prefix, const char *name, const char *alias)
{
	return make_alias(hm2, hal_pin_alias, prefix, name, alias);
}

int hm2_alias_param(struct hostmot2 *hm2, const char *prefix, const char *name, const char *alias)
{
	return make_alias(hm2, hal_param_alias, prefix, name, alias);
}

/* HAL name of a module's output pin code (SecPin with bit 7), or NULL: no alias */
static const char *out_pin_name(int gtag, int code, char *buf, int len)
{
	static const char *const pwm[] = { "out0", "out1", "enable" };
	static const char *const tp[] = { "pwm-a", "pwm-b", "pwm-c", "npwm-a", "npwm-b", "npwm-c",
					  "enable" };
	static const char *const bspi[] = { "frame", "out", "clk" };
	static const char *const uart[] = { "tx", "tx-enable" };

	code &= 0x7F;
	switch (gtag) {
	case HM2_GTAG_STEPGEN:
		if (code == 1)
			return "step";
		if (code == 2)
			return "direction";
		if (code >= 3 && code <= 8) {
			rtapi_snprintf(buf, len, "table%d", code - 1);
			return buf;
		}
		return 0;
	case HM2_GTAG_PWMGEN:
		return code >= 1 && code <= 3 ? pwm[code - 1] : 0;
	case HM2_GTAG_TPPWM:
		return code >= 1 && code <= 7 ? tp[code - 1] : 0;
	case HM2_GTAG_BSPI:
		if (code >= 1 && code <= 3)
			return bspi[code - 1];
		if (code >= 5 && code <= 12) {
			rtapi_snprintf(buf, len, "cs%d", code - 5);
			return buf;
		}
		return 0;
	case HM2_GTAG_UART_TX:
		return code >= 1 && code <= 2 ? uart[code - 1] : 0;
	default:
		return 0;
	}
}

static const char *module_name(int gtag, int unit, char *buf, int len)
{
	switch (gtag) {
	case HM2_GTAG_STEPGEN: rtapi_snprintf(buf, len, "stepgen.%02d", unit); break;
	case HM2_GTAG_PWMGEN: rtapi_snprintf(buf, len, "pwmgen.%02d", unit); break;
	case HM2_GTAG_TPPWM: rtapi_snprintf(buf, len, "3pwmgen.%02d", unit); break;
	case HM2_GTAG_BSPI: rtapi_snprintf(buf, len, "bspi.%d", unit); break;
	case HM2_GTAG_UART_TX: rtapi_snprintf(buf, len, "uart.%d", unit); break;
	default: return 0;
	}
	return buf;
}

/* <board>.<alias>.<param> names <board>.<io>.<param> */
static int alias_io_param(struct hostmot2 *hm2, const char *io, const char *alias, const char *param)
{
	char n[HAL_NAME_LEN + 1], a[HAL_NAME_LEN + 1];

	rtapi_snprintf(n, sizeof(n), "%s.%s", io, param);
	rtapi_snprintf(a, sizeof(a), "%s.%s", alias, param);
	return hm2_alias_param(hm2, hm2->llio->name, n, a);
}

static int same_function(const struct hm2_pin *a, const struct hm2_pin *b)
{
	return a->gtag == b->gtag && a->pd.sec_unit == b->pd.sec_unit && a->pd.sec_pin == b->pd.sec_pin;
}

int hm2_alias_module_pins(struct hostmot2 *hm2)
{
	int i, j, rc = 0;

	for (i = 0; i < hm2->num_pins && !rc; i++) {
		const struct hm2_pin *p = &hm2->pin[i];
		char mbuf[32], pbuf[16], io[HAL_NAME_LEN + 1], alias[HAL_NAME_LEN + 1];
		const char *mod, *pin;
		int k = 0, shared = 0;

		if (p->gtag == HM2_GTAG_IOPORT || p->dir != HM2_PIN_OUT || (p->pd.sec_unit & 0x80))
			continue;
		mod = module_name(p->gtag, p->pd.sec_unit, mbuf, sizeof(mbuf));
		pin = out_pin_name(p->gtag, p->pd.sec_pin, pbuf, sizeof(pbuf));
		if (!mod || !pin)
			continue;
		for (j = 0; j < hm2->num_pins; j++) {
			if (j != i && same_function(p, &hm2->pin[j]))
				shared = 1;
			if (j < i && same_function(p, &hm2->pin[j]))
				k++;
		}
		rtapi_snprintf(io, sizeof(io), "gpio.%03d", i);
		if (shared)
			rtapi_snprintf(alias, sizeof(alias), "%s.%d.%s", mod, k, pin);
		else
			rtapi_snprintf(alias, sizeof(alias), "%s.%s", mod, pin);
		rc = alias_io_param(hm2, io, alias, "invert_output");
		if (!rc)
			rc = alias_io_param(hm2, io, alias, "is_opendrain");
	}
	return rc;
}

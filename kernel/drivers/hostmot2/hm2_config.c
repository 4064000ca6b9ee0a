/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_config.c - the config string: whitespace-separated tokens, every keyword of
 * hostmot2(9). A token is a whole keyword (num_encoders=3), never a prefix, so a
 * misspelling is refused instead of silently matching something else. */
#include "rtapi.h"
#include "rtapi_string.h"
#include "hm2_config.h"

#define TOKEN_MAX 128

static const char *const count_names[HM2_NUM_KEYS] = {
	"num_encoders", "num_pwmgens", "num_stepgens", "num_3pwmgens", "num_rcpwmgens",
	"num_resolvers", "num_bspis", "num_uarts", "num_pktuarts", "num_inms", "num_inmuxs",
	"num_outms", "num_ssrs", "num_oneshots", "num_periodms", "num_xy2mods", "num_dplls",
	"num_leds",
};

const char *hm2_config_count_name(enum hm2_count_key key)
{
	return count_names[key];
}

static int is_space(char c)
{
	return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

/* "-1", "0", ... "1000": strtol base 0 with nothing left over */
static int parse_int(const char *tok, const char *val, int min, int max, int *out,
		     char *err, int errlen)
{
	char *end;
	long v;

	if (!*val) {
		rtapi_snprintf(err, errlen, "config: '%s' needs a number", tok);
		return -EINVAL;
	}
	v = rtapi_strtol(val, &end, 0);
	if (*end || v < min || v > max) {
		rtapi_snprintf(err, errlen, "config: '%s': expected an integer %d..%d", tok, min, max);
		return -EINVAL;
	}
	*out = (int)v;
	return 0;
}

/* ssi_chan_N=FORMAT and friends */
static int parse_abs(const char *tok, const char *key, char (*formats)[HM2_ABS_FORMAT_MAX + 1],
		     char *err, int errlen)
{
	const char *p = tok + strlen(key);
	const char *eq = strchr(p, '=');
	char *end;
	long n;

	n = rtapi_strtol(p, &end, 10);
	if (end == p || end != eq || n < 0 || n >= HM2_ABS_CHANNELS) {
		rtapi_snprintf(err, errlen, "config: '%s': expected %sN=FORMAT with N 0..%d", tok, key,
			       HM2_ABS_CHANNELS - 1);
		return -EINVAL;
	}
	if (!eq[1] || strlen(eq + 1) > HM2_ABS_FORMAT_MAX) {
		rtapi_snprintf(err, errlen, "config: '%s': the format must be 1..%d characters", tok,
			       HM2_ABS_FORMAT_MAX);
		return -EINVAL;
	}
	if (formats[n][0]) {
		rtapi_snprintf(err, errlen, "config: '%s': channel %ld is given twice", tok, n);
		return -EINVAL;
	}
	rtapi_strlcpy(formats[n], eq + 1, HM2_ABS_FORMAT_MAX + 1);
	return 0;
}

static int parse_sserial(const char *tok, struct hm2_config *cfg, char *err, int errlen)
{
	const char *p = tok + strlen("sserial_port_");
	const char *modes;
	int port, i;

	if (p[0] < '0' || p[0] >= '0' + HM2_SSERIAL_PORTS || p[1] != '=') {
		rtapi_snprintf(err, errlen, "config: '%s': expected sserial_port_N=MODES with N 0..%d",
			       tok, HM2_SSERIAL_PORTS - 1);
		return -EINVAL;
	}
	port = p[0] - '0';
	modes = p + 2;
	if (!*modes || strlen(modes) > HM2_SSERIAL_CHANNELS) {
		rtapi_snprintf(err, errlen, "config: '%s': 1..%d mode characters expected", tok,
			       HM2_SSERIAL_CHANNELS);
		return -EINVAL;
	}
	for (i = 0; modes[i]; i++) {
		if (!((modes[i] >= '0' && modes[i] <= '9') || modes[i] == 'x' || modes[i] == 'X')) {
			rtapi_snprintf(err, errlen, "config: '%s': mode '%c' is not 0-9 or x", tok,
				       modes[i]);
			return -EINVAL;
		}
	}
	rtapi_strlcpy(cfg->sserial_modes[port], modes, HM2_SSERIAL_CHANNELS + 1);
	if (port + 1 > cfg->num_sserials)
		cfg->num_sserials = port + 1;
	return 0;
}

static int parse_token(const char *tok, struct hm2_config *cfg, char *err, int errlen)
{
	int i;

	for (i = 0; i < HM2_NUM_KEYS; i++) {
		int n = strlen(count_names[i]);

		if (strncmp(tok, count_names[i], n) == 0 && tok[n] == '=')
			return parse_int(tok, tok + n + 1, -1, HM2_MAX_COUNT, &cfg->num[i], err, errlen);
	}
	if (strncmp(tok, "stepgen_width=", 14) == 0)
		return parse_int(tok, tok + 14, 0, 8, &cfg->stepgen_width, err, errlen);
	if (strcmp(tok, "enable_raw") == 0) {
		cfg->enable_raw = 1;
		return 0;
	}
	if (strncmp(tok, "firmware=", 9) == 0) {
		if (!tok[9] || strlen(tok + 9) > HM2_FIRMWARE_NAME_MAX) {
			rtapi_snprintf(err, errlen, "config: '%s': the firmware name must be 1..%d "
				       "characters", tok, HM2_FIRMWARE_NAME_MAX);
			return -EINVAL;
		}
		rtapi_strlcpy(cfg->firmware, tok + 9, sizeof(cfg->firmware));
		return 0;
	}
	if (strncmp(tok, "sserial_port_", 13) == 0)
		return parse_sserial(tok, cfg, err, errlen);
	if (strncmp(tok, "ssi_chan_", 9) == 0)
		return parse_abs(tok, "ssi_chan_", cfg->ssi_format, err, errlen);
	if (strncmp(tok, "biss_chan_", 10) == 0)
		return parse_abs(tok, "biss_chan_", cfg->biss_format, err, errlen);
	if (strncmp(tok, "fanuc_chan_", 11) == 0)
		return parse_abs(tok, "fanuc_chan_", cfg->fanuc_format, err, errlen);
	rtapi_snprintf(err, errlen, "config: unknown keyword '%s' (see hostmot2(9), config modparam)",
		       tok);
	return -EINVAL;
}

int hm2_config_parse(const char *s, struct hm2_config *cfg, char *err, int errlen)
{
	char tok[TOKEN_MAX + 1];
	int i, n, rc;

	memset(cfg, 0, sizeof(*cfg));
	for (i = 0; i < HM2_NUM_KEYS; i++)
		cfg->num[i] = -1;
	cfg->stepgen_width = 2;
	if (!s)
		return 0;
	while (*s) {
		while (is_space(*s))
			s++;
		if (!*s)
			break;
		for (n = 0; s[n] && !is_space(s[n]); n++)
			;
		if (n > TOKEN_MAX) {
			rtapi_snprintf(err, errlen, "config: token '%.20s...' is longer than %d characters",
				       s, TOKEN_MAX);
			return -EINVAL;
		}
		memcpy(tok, s, n);
		tok[n] = 0;
		s += n;
		rc = parse_token(tok, cfg, err, errlen);
		if (rc)
			return rc;
	}
	return 0;
}

int hm2_config_instances(const struct hm2_config *cfg, enum hm2_count_key key, int available,
			 char *err, int errlen)
{
	int want = cfg->num[key];

	if (want < 0)
		return available;
	if (want > available) {
		rtapi_snprintf(err, errlen, "config: %s=%d, but the firmware has only %d", count_names[key],
			       want, available);
		return -EINVAL;
	}
	return want;
}

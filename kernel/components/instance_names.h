/* SPDX-License-Identifier: GPL-2.0-or-later */
/* instance_names.h - the "count=N | names=name1[,name2...]" convention of the
 * component pages (and2(9) ... xor2(9); siggen(9) calls count "num_chan"):
 * how many instances to make, and the prefix of each one's pins and functions.
 * HAL-free apart from HAL_NAME_LEN, so unit tests call it directly. Init code only. */
#ifndef INSTANCE_NAMES_H
#define INSTANCE_NAMES_H

#include "rtapi.h"
#include "hal.h"

/* Number of instances asked for: 1..max, or -EINVAL after logging one line.
 * comp names the component in messages; count_param is the name of the count
 * parameter ("count", "num_chan"); count < 0 (not given) and count = 0 mean the
 * default, one instance (LinuxCNC; callers with another default substitute it).
 * An empty names= (names[0] == "") counts as not given. names[0..names_len-1] holds the names= entries,
 * NULL where none was given. */
static inline int instance_count(const char *comp, const char *count_param, int count,
				 char *const *names, int names_len, int max)
{
	int n, i, k, len;

	if (!names[0] || !names[0][0]) {
		if (count <= 0)		/* count=0 is the default, as in LinuxCNC */
			return 1;
		if (count < 1 || count > max) {
			rtapi_print_msg(RTAPI_MSG_ERR, "%s: %s=%d is out of range, must be 1..%d\n",
					comp, count_param, count, max);
			return -EINVAL;
		}
		return count;
	}
	if (count > 0) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"%s: %s= and names= are mutually exclusive; give only one of them\n",
				comp, count_param);
		return -EINVAL;
	}
	for (n = 0; n < names_len && names[n]; n++) {
		for (len = 0; names[n][len]; len++)
			;
		if (len == 0) {
			rtapi_print_msg(RTAPI_MSG_ERR, "%s: names= entry %d is empty\n", comp, n + 1);
			return -EINVAL;
		}
		if (len > HAL_NAME_LEN) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"%s: names= entry '%s' is longer than %d characters\n",
					comp, names[n], HAL_NAME_LEN);
			return -EINVAL;
		}
		for (i = 0; i < n; i++) {
			for (k = 0; names[i][k] && names[i][k] == names[n][k]; k++)
				;
			if (names[i][k] == names[n][k]) {
				rtapi_print_msg(RTAPI_MSG_ERR, "%s: names= gives '%s' twice\n",
						comp, names[n]);
				return -EINVAL;
			}
		}
	}
	if (n > max) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: names= gives %d names, at most %d are allowed\n",
				comp, n, max);
		return -EINVAL;
	}
	return n;
}

/* Prefix of instance i (valid after instance_count() accepted the parameters):
 * names[i] when names= was given, else "<comp>.<i>". */
static inline void instance_prefix(char *buf, unsigned long size, const char *comp,
				   char *const *names, int i)
{
	if (names[0] && names[0][0])
		rtapi_snprintf(buf, size, "%s", names[i]);
	else
		rtapi_snprintf(buf, size, "%s.%d", comp, i);
}

#endif /* INSTANCE_NAMES_H */

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_app_testmod.c - a realtime module with no HAL in it, for the rtapi_app
 * tests. fail=N makes rtapi_app_main() return -N after an ERR line showing every
 * parameter, so the test reads the applied values from the load error. */
#include "rtapi.h"
#include "rtapi_app.h"

MODULE_LICENSE("GPL");

static int count = 1;
RTAPI_MP_INT(count, "any number, reported");
static int fail;
RTAPI_MP_INT(fail, "errno to fail rtapi_app_main() with (0: succeed)");
static int values[4] = {0, 0, 0, 0};
RTAPI_MP_ARRAY_INT(values, 4, "up to four numbers, reported");
static char *label = "none";
RTAPI_MP_STRING(label, "a word, reported");

int rtapi_app_main(void)
{
	int level = fail ? RTAPI_MSG_ERR : RTAPI_MSG_INFO;

	rtapi_print_msg(level, "rtapi_app_testmod: count=%d values=%d,%d,%d,%d label=%s\n",
			count, values[0], values[1], values[2], values[3], label);
	return -fail;
}

void rtapi_app_exit(void)
{
}

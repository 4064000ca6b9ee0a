/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_app_badsym.c - a module needing a symbol nobody exports, so dlopen() fails. */
#include "rtapi.h"
#include "rtapi_app.h"

int rtapi_app_badsym_missing(void);	/* defined nowhere on purpose */

int rtapi_app_main(void)
{
	return rtapi_app_badsym_missing();
}

void rtapi_app_exit(void)
{
}

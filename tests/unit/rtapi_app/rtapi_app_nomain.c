/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_app_nomain.c - a module without rtapi_app_main(), which rtapi_app must refuse. */
#include "rtapi.h"
#include "rtapi_app.h"

void rtapi_app_exit(void)
{
}

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_param_fp.c - hal_param_float_set(3hal), the one hal_lib entry that receives a
 * double (in an SSE register on x86-64), so the one hal_lib file compiled with SSE in
 * the kernel flavor. Its callers are FP code, running inside an FPU section; the value
 * is passed on as its bits, and hal_param.c stores them without FP instructions. */
#include "hal_internal.h"

int hal_param_float_set(const char *name, double value)
{
	union { double d; rtapi_u64 bits; } v = { .d = value };

	return hal_param_set(name, HAL_FLOAT, &v.bits);
}

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* weighted_sum_core.h - weighted_sum(9): offset plus the weight of every TRUE
 * bit, HAL-free so unit tests call it. Sums wrap as two's complement s32 does. */
#ifndef WEIGHTED_SUM_CORE_H
#define WEIGHTED_SUM_CORE_H

#include "rtapi.h"

#define WSUM_MAX_BITS 16	/* "each may have up to 16 input bits" */

static inline rtapi_s32 wsum_compute(const bool *bits, const rtapi_s32 *weights, int n,
				     rtapi_s32 offset)
{
	rtapi_u32 sum = (rtapi_u32)offset;	/* unsigned: overflow wraps, no UB */
	int m;

	for (m = 0; m < n; m++)
		if (bits[m])
			sum += (rtapi_u32)weights[m];
	return (rtapi_s32)sum;
}

#endif /* WEIGHTED_SUM_CORE_H */

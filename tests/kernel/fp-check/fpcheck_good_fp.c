/* SPDX-License-Identifier: GPL-2.0-or-later */
/* fpcheck_good_fp.c - fpcheck_good's FP code, alone in its file (compiled with SSE). */
long fpcheck_scaled(int scale);

long fpcheck_scaled(int scale)
{
	double d = scale * 1.5;

	return (long)d;
}

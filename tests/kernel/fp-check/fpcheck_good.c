/* SPDX-License-Identifier: GPL-2.0-or-later */
/* fpcheck_good.c - the same computation as fpcheck_bad.c, done by the rule: init code
 * (this file, no SSE) calls the FP code in fpcheck_good_fp.c inside an FPU section.
 * kmod-fp-check.sh must pass it. Never loaded. */
#include <linux/module.h>
#include <asm/fpu/api.h>

MODULE_LICENSE("GPL");

long fpcheck_scaled(int scale);	/* fpcheck_good_fp.c */

static int scale = 3;
module_param(scale, int, 0444);
static volatile long result;

static int __init fpcheck_good_init(void)
{
	kernel_fpu_begin();
	result = fpcheck_scaled(scale);
	kernel_fpu_end();
	return 0;
}
module_init(fpcheck_good_init);

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* fpcheck_bad.c - a deliberately bad module for tests/kernel/fp-check-test.sh: compiled
 * with SSE (as a whole FP file used to be), and its init code uses a double outside
 * any FPU section. kmod-fp-check.sh must name it. Never loaded. */
#include <linux/module.h>

MODULE_LICENSE("GPL");

static int scale = 3;
module_param(scale, int, 0444);
static volatile long result;

static int __init fpcheck_bad_init(void)
{
	double d = scale * 1.5;

	result = (long)d;
	return 0;
}
module_init(fpcheck_bad_init);

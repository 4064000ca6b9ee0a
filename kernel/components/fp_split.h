/* SPDX-License-Identifier: GPL-2.0-or-later */
/* fp_split.h - a hand-written component with floating-point realtime functions is two
 * translation units: NAME.c (init, exit, HAL glue, integer-only functions; compiled
 * without SSE in the kernel flavor) and NAME_fp.c (the FP realtime functions and
 * nothing else; compiled with SSE, run only on a thread inside an FPU section), with
 * NAME_fp.h for what both need. kernel/kmod-fp-check.sh checks the machine code. */
#ifndef FP_SPLIT_H
#define FP_SPLIT_H

/* NAME_fp.c's functions are called from NAME.c only; hidden, because rtapi_app
 * dlopen()s modules with RTLD_GLOBAL and two modules may use the same names. */
#define COMP_FP_LOCAL __attribute__((visibility("hidden")))

#endif /* FP_SPLIT_H */

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Compiled, never run: the C compiler rejects any declaration in hal_test_internal.h
 * that conflicts with hal_internal.h. */
#include "hal_internal.h"
#include "hal_test_internal.h"

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* trivkins.h - what trivkins.c (init, type) and trivkins_fp.c (forward, inverse) share. */
#ifndef TRIVKINS_H
#define TRIVKINS_H

#include "kinematics.h"
#include "kins_coords.h"

/* Set by rtapi_app_main(), read-only afterwards. One per module: the kinematics
 * interface has no context argument. */
struct trivkins_state {
	struct kins_coords coords;
	KINEMATICS_TYPE type;
};
COMP_FP_LOCAL extern struct trivkins_state trivkins;

#endif /* TRIVKINS_H */

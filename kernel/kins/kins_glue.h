/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kins_glue.h - what every kinematics module's init and integer entry points share
 * (kins_glue.c): refusing a second kinematics module, and the run-time switch of the
 * switchable modules (genhexkins, genserkins, pumakins, scarakins) between their own
 * kinematics and the identity mapping of their coordinates= letters. No floating
 * point. */
#ifndef KINS_GLUE_H
#define KINS_GLUE_H

#include "kinematics.h"
#include "kins_coords.h"
#include "fp_split.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Called first in rtapi_app_main() with the module's kinematicsType as motion will
 * find it (seen: the address the name resolves to) and as the module defines it
 * (own: a local alias). They differ only when an earlier module already provides the
 * kinematics functions (the simulated flavor; the kernel refuses the duplicate
 * export before init). 0, or -EBUSY after logging. */
COMP_FP_LOCAL int kins_claim(const char *mod, KINEMATICS_TYPE (*seen)(void),
			     KINEMATICS_TYPE (*own)(void));

/* The switch state of a switchable module: written by kinematicsSwitch(), read by
 * the module's forward and inverse (one int: no tearing). */
struct kins_switch {
	volatile int type;		/* KINS_SWITCH_PRIMARY or KINS_SWITCH_IDENTITY */
	struct kins_coords coords;	/* the identity mapping (coordinates=) */
};

/* Reads coordinates= (NULL or empty: default_letters) for a switchable module. */
COMP_FP_LOCAL int kins_switch_init(const char *mod, const char *letters,
				   const char *default_letters, struct kins_switch *s);
/* kinematicsSwitch() of a switchable module: 0, or -EINVAL for another type. */
COMP_FP_LOCAL int kins_switch_to(struct kins_switch *s, int type);

#ifdef __cplusplus
}
#endif
#endif /* KINS_GLUE_H */

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kins_bind.h - how motion (motmod) and kinstest reach the loaded kinematics module:
 * its kinematics.h functions looked up by name when they load (rtapi_symbol_get), not
 * linked. Every kinematics module exports the same names, so a linked reference would
 * make the kernel flavor's build record one of them (the last one built) as a
 * dependency, and modprobe would load it. The lookup also holds the module: it cannot
 * be unloaded while motion uses it. No floating point here. */
#ifndef KINS_BIND_H
#define KINS_BIND_H

#include "rtapi_symbol.h"
#include "kinematics.h"

struct kins_ops {
	int (*forward)(const double *joints, EmcPose *world,
		       const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags);
	int (*inverse)(const EmcPose *world, double *joints,
		       const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags);
	KINEMATICS_TYPE (*type)(void);
	int (*switchable)(void);
	int (*switch_to)(int switchkins_type);
};

/* Releases what kins_bind() found (the module may be unloaded again). */
static inline void kins_unbind(struct kins_ops *k)
{
	if (k->forward)
		rtapi_symbol_put("kinematicsForward");
	if (k->inverse)
		rtapi_symbol_put("kinematicsInverse");
	if (k->type)
		rtapi_symbol_put("kinematicsType");
	if (k->switchable)
		rtapi_symbol_put("kinematicsSwitchable");
	if (k->switch_to)
		rtapi_symbol_put("kinematicsSwitch");
	k->forward = 0;
	k->inverse = 0;
	k->type = 0;
	k->switchable = 0;
	k->switch_to = 0;
}

/* 0 with every function found, or -ENOENT (none held) when no kinematics module is
 * loaded. Call from rtapi_app_main; kins_unbind() from rtapi_app_exit. (A symbol's
 * address converts to the function pointer it is, as with the kernel's symbol_get.) */
static inline int kins_bind(struct kins_ops *k)
{
	k->forward = (int (*)(const double *, EmcPose *, const KINEMATICS_FORWARD_FLAGS *,
			      KINEMATICS_INVERSE_FLAGS *))rtapi_symbol_get("kinematicsForward");
	k->inverse = (int (*)(const EmcPose *, double *, const KINEMATICS_INVERSE_FLAGS *,
			      KINEMATICS_FORWARD_FLAGS *))rtapi_symbol_get("kinematicsInverse");
	k->type = (KINEMATICS_TYPE (*)(void))rtapi_symbol_get("kinematicsType");
	k->switchable = (int (*)(void))rtapi_symbol_get("kinematicsSwitchable");
	k->switch_to = (int (*)(int))rtapi_symbol_get("kinematicsSwitch");
	if (!k->forward || !k->inverse || !k->type || !k->switchable || !k->switch_to) {
		kins_unbind(k);
		return -ENOENT;
	}
	return 0;
}

#endif /* KINS_BIND_H */

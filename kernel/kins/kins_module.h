/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kins_module.h - the entry points every kinematics module defines alike, written
 * once. A module's NAME.c says, after its state:
 *     KINS_TYPE_IS(KINEMATICS_BOTH)        kinematicsType(), and own_type for kins_claim()
 *     KINS_NOT_SWITCHABLE  or  KINS_SWITCHABLE(&state->sw)
 *     KINS_EXPORTS                         the six names motion resolves (GPL-only
 *                                          exports: the kernel's symbol_get, behind
 *                                          rtapi_symbol_get, finds no others since 6.1.53)
 * and defines kinematicsForward/Inverse/Home in NAME_fp.c. */
#ifndef KINS_MODULE_H
#define KINS_MODULE_H

#include "rtapi.h"
#include "kins_glue.h"

/* own_type: this module's kinematicsType whatever the global name resolves to. */
#define KINS_TYPE_IS(type_expr)                                                    \
	KINEMATICS_TYPE kinematicsType(void)                                       \
	{                                                                          \
		return (type_expr);                                                \
	}                                                                          \
	static KINEMATICS_TYPE own_type(void) __attribute__((alias("kinematicsType")));

/* Only the module's own kinematics: a switch to anything else is refused. */
#define KINS_NOT_SWITCHABLE                                                        \
	int kinematicsSwitchable(void)                                             \
	{                                                                          \
		return 0;                                                          \
	}                                                                          \
	int kinematicsSwitch(int switchkins_type)                                  \
	{                                                                          \
		return switchkins_type == KINS_SWITCH_PRIMARY ? 0 : -EINVAL;       \
	}

/* Switchable between its kinematics and the identity of coordinates= (kins_glue.h). */
#define KINS_SWITCHABLE(switch_state)                                              \
	int kinematicsSwitchable(void)                                             \
	{                                                                          \
		return 1;                                                          \
	}                                                                          \
	int kinematicsSwitch(int switchkins_type)                                  \
	{                                                                          \
		return kins_switch_to((switch_state), switchkins_type);            \
	}

#define KINS_EXPORTS                                                               \
	EXPORT_SYMBOL_GPL(kinematicsForward);	\
	EXPORT_SYMBOL_GPL(kinematicsInverse);	\
	EXPORT_SYMBOL_GPL(kinematicsHome);	\
	EXPORT_SYMBOL_GPL(kinematicsType);	\
	EXPORT_SYMBOL_GPL(kinematicsSwitchable);	\
	EXPORT_SYMBOL_GPL(kinematicsSwitch);

#endif /* KINS_MODULE_H */

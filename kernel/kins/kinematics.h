/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kinematics.h - the interface between motion (motmod, and the test component kinstest)
 * and a kinematics module (trivkins, gantrykins, rotatekins, tripodkins, genhexkins,
 * maxkins, genserkins, pumakins, scarakins): the contract of docs/kinematics.md.
 *
 * A kinematics module exports the six functions below under these names (the names
 * LinuxCNC's modules export, so a kinematics module written for it plugs in too).
 * Exactly one kinematics module is loaded at a time, before motmod: `loadrt trivkins`
 * then `loadrt motmod ...`. motmod (and kinstest) look the functions up by name when
 * they load (kins_bind.h: rtapi_symbol_get), which holds the kinematics module until
 * they unload; no module links against them, so none depends on a particular
 * kinematics module (kernel/kmod-deps-check.sh). The kernel refuses a second module
 * exporting the names, rtapi_app a second kinematics module (kins_claim).
 *
 * Units: joints in machine units or degrees, as the module documents; the world pose
 * X Y Z U V W in machine units, A B C in degrees. Joint arrays passed in are
 * KINS_MAX_JOINTS long; a module reads and writes only its own joints.
 *
 * Context: kinematicsForward, kinematicsInverse and kinematicsHome compute in floating
 * point: call them only from a realtime function exported with uses_fp = 1 (or from
 * init code between rtapi_fpu_begin() and rtapi_fpu_end()). kinematicsType,
 * kinematicsSwitchable and kinematicsSwitch use no floating point. None of them
 * sleeps, allocates or prints: all may run in a realtime thread. */
#ifndef KINEMATICS_H
#define KINEMATICS_H

#include "rtapi.h"

#ifdef __cplusplus
extern "C" {
#endif

#define KINS_MAX_JOINTS 16	/* EMCMOT_MAX_JOINTS of LinuxCNC 2.9 */
#define KINS_NUM_AXES 9		/* X Y Z A B C U V W, axis index 0..8 */

typedef struct {
	double x, y, z;
} PmCartesian;

/* A world position: tran.x/y/z, then a b c (degrees), u v w. */
typedef struct {
	PmCartesian tran;
	double a, b, c;
	double u, v, w;
} EmcPose;

/* Flag words, private to each module: what the forward learned about the
 * configuration (e.g. pumakins' elbow/shoulder/wrist) for a later inverse to choose
 * the same one (iflags), and the reverse (fflags: e.g. tripodkins below the plane). */
typedef unsigned long KINEMATICS_FORWARD_FLAGS;
typedef unsigned long KINEMATICS_INVERSE_FLAGS;

/* What motion may rely on (kinematics.md section 1, motion.md section 6). */
typedef enum {
	KINEMATICS_IDENTITY = 1,	/* joints are the axes: world feedback valid unhomed */
	KINEMATICS_FORWARD_ONLY = 2,
	KINEMATICS_INVERSE_ONLY = 3,
	KINEMATICS_BOTH = 4,
} KINEMATICS_TYPE;

/* Switch types of kinematicsSwitch(): the module's own kinematics, or the identity
 * mapping of its coordinates= letters (motion.switchkins-type 0 and 1). */
#define KINS_SWITCH_PRIMARY 0
#define KINS_SWITCH_IDENTITY 1

/* joints -> world. *world holds the initial guess on entry (iterative modules start
 * from it; motion passes the previous world position). *fflags chooses among
 * solutions; *iflags may be set for a later inverse. 0 on success, negative when the
 * joints have no world position (out of reach, no convergence); *world is then
 * unspecified. */
int kinematicsForward(const double *joints, EmcPose *world,
		      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags);

/* world -> joints. joints[] holds the current joints on entry (the start of an
 * iterative inverse; kept where the pose leaves a joint undetermined). 0 on success,
 * negative when the pose cannot be reached; a module may instead return 0 with a
 * non-finite joint, which motion treats as a failure too. */
int kinematicsInverse(const EmcPose *world, double *joints,
		      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags);

/* The world position of the given (home) joints: the forward kinematics with
 * *fflags cleared first, *iflags cleared or set by the forward (EMC2's contract;
 * LinuxCNC 2.9 motion no longer calls it). 0 or negative as kinematicsForward. */
int kinematicsHome(EmcPose *world, double *joints,
		   KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags);

KINEMATICS_TYPE kinematicsType(void);

/* 1 when kinematicsSwitch() can change the kinematics at run time, else 0. */
int kinematicsSwitchable(void);

/* Switch to KINS_SWITCH_PRIMARY or KINS_SWITCH_IDENTITY: 0, or -EINVAL for a type
 * the module does not have (every type but 0 for a module that is not switchable).
 * Motion recomputes the world position from the joints after a switch. */
int kinematicsSwitch(int switchkins_type);

#ifdef __cplusplus
}
#endif
#endif /* KINEMATICS_H */

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kins_coords.h - the joint <-> axis-letter mapping of `coordinates=` (trivkins,
 * gantrykins, and the identity type of the switchable modules) and `kinstype=`:
 * kinematics.md sections 2 and 3. Parsing (kins_coords.c) is init code without
 * floating point; the mapping itself (kins_coords_fp.c) is floating point. */
#ifndef KINS_COORDS_H
#define KINS_COORDS_H

#include "kinematics.h"
#include "fp_split.h"

#ifdef __cplusplus
extern "C" {
#endif

#define KINS_COORDS_MAX_LEN 32	/* characters of a coordinates= string */

struct kins_coords {
	int num_joints;				/* letters given: joints 0..num_joints-1 */
	signed char axis[KINS_MAX_JOINTS];	/* axis index 0..8 of each joint */
};

/* Reads LETTERS (X Y Z A B C U V W in either case, blanks and tabs skipped, letters
 * may repeat) for module MOD into *c, allowing at most max_joints joints. 0, or
 * -EINVAL after logging one line naming the module, the string and what is wrong. */
COMP_FP_LOCAL int kins_coords_parse(const char *mod, const char *letters, int max_joints,
				    struct kins_coords *c);

/* true when the joints are X Y Z A B C U V W in that order, each letter once (the
 * mapping the plain trivkins of EMC2 has, and nothing to print at load). */
COMP_FP_LOCAL bool kins_coords_is_trivial(const struct kins_coords *c);

/* Logs, at info level, which axis each joint drives ("trivkins: joint 2 = Y"). */
COMP_FP_LOCAL void kins_coords_print(const char *mod, const struct kins_coords *c);

/* The letter of axis index 0..8. */
COMP_FP_LOCAL char kins_axis_letter(int axis);

/* kinstype=: the first character 1 (identity), b/B (both), f/F (forward only) or
 * i/I (inverse only). 0 with *type set, or -EINVAL after logging. */
COMP_FP_LOCAL int kins_kinstype_parse(const char *mod, const char *text, KINEMATICS_TYPE *type);

/* Which joint a duplicated letter takes its forward value from. */
enum kins_coords_winner {
	KINS_FIRST_JOINT_WINS,	/* LinuxCNC 2.9 trivkins: the first listed joint */
	KINS_LAST_JOINT_WINS,	/* EMC2 gantrykins: the highest-numbered joint */
};

/* Forward: each axis letter takes its joint's value; axes with no joint keep what
 * *world holds. Inverse: every joint takes its letter's axis. (floating point) */
COMP_FP_LOCAL void kins_coords_forward(const struct kins_coords *c, enum kins_coords_winner w,
				       const double *joints, EmcPose *world);
COMP_FP_LOCAL void kins_coords_inverse(const struct kins_coords *c, const EmcPose *world,
				       double *joints);

#ifdef __cplusplus
}
#endif
#endif /* KINS_COORDS_H */

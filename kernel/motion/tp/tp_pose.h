/* tp_pose.h - the nine-axis world pose the trajectory planner works in.
 *
 * Same order and units as LinuxCNC's EmcPose (x y z linear, a b c in degrees,
 * u v w linear), but a plain record of nine doubles so the planner can treat it
 * as a vector.  motmod converts to/from kinematics.h's EmcPose field by field.
 * Pure C, no HAL, no FP code (only the type). */
#ifndef TP_POSE_H
#define TP_POSE_H

#ifdef __cplusplus
extern "C" {
#endif

#define TP_NUM_AXES 9		/* X Y Z A B C U V W: axis index 0..8 */

struct tp_pose {
	double x, y, z;		/* linear, machine units */
	double a, b, c;		/* rotary, degrees */
	double u, v, w;		/* linear, machine units */
};

/* A 3-vector (arc centre, plane normal). */
struct tp_cart {
	double x, y, z;
};

#ifdef __cplusplus
}
#endif
#endif

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kins_coords.c - reading `coordinates=` and `kinstype=` (kins_coords.h). Init code,
 * no floating point. */
#include "rtapi.h"
#include "rtapi_string.h"
#include "kins_coords.h"

static const char axis_letters[KINS_NUM_AXES + 1] = "XYZABCUVW";

char kins_axis_letter(int axis)
{
	return axis >= 0 && axis < KINS_NUM_AXES ? axis_letters[axis] : '?';
}

static int axis_of(char ch)
{
	int i;

	if (ch >= 'a' && ch <= 'z')
		ch = (char)(ch - 'a' + 'A');
	for (i = 0; i < KINS_NUM_AXES; i++)
		if (axis_letters[i] == ch)
			return i;
	return -1;
}

int kins_coords_parse(const char *mod, const char *letters, int max_joints, struct kins_coords *c)
{
	const char *s;
	int axis;

	c->num_joints = 0;
	if (!letters || strlen(letters) > KINS_COORDS_MAX_LEN) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: coordinates='%s' is longer than %d characters\n",
				mod, letters ? letters : "", KINS_COORDS_MAX_LEN);
		return -EINVAL;
	}
	for (s = letters; *s; s++) {
		if (*s == ' ' || *s == '\t')
			continue;
		axis = axis_of(*s);
		if (axis < 0) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"%s: invalid character '%c' in coordinates '%s' (letters XYZABCUVW)\n",
					mod, *s, letters);
			return -EINVAL;
		}
		if (c->num_joints == max_joints) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"%s: coordinates '%s' names more than %d joints\n",
					mod, letters, max_joints);
			return -EINVAL;
		}
		c->axis[c->num_joints++] = (signed char)axis;
	}
	if (c->num_joints == 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: coordinates='%s' names no joint\n", mod, letters);
		return -EINVAL;
	}
	return 0;
}

bool kins_coords_is_trivial(const struct kins_coords *c)
{
	int j;

	for (j = 0; j < c->num_joints; j++)
		if (c->axis[j] != j)
			return false;
	return true;
}

void kins_coords_print(const char *mod, const struct kins_coords *c)
{
	int j;

	for (j = 0; j < c->num_joints; j++)
		rtapi_print_msg(RTAPI_MSG_INFO, "%s: joint %d = %c\n", mod, j,
				kins_axis_letter(c->axis[j]));
}

int kins_kinstype_parse(const char *mod, const char *text, KINEMATICS_TYPE *type)
{
	switch (text ? text[0] : '1') {
	case '1':
		*type = KINEMATICS_IDENTITY;
		return 0;
	case 'b': case 'B':
		*type = KINEMATICS_BOTH;
		return 0;
	case 'f': case 'F':
		*type = KINEMATICS_FORWARD_ONLY;
		return 0;
	case 'i': case 'I':
		*type = KINEMATICS_INVERSE_ONLY;
		return 0;
	}
	rtapi_print_msg(RTAPI_MSG_ERR,
			"%s: kinstype='%s': use 1 (identity), b (both), f (forward only) or i (inverse only)\n",
			mod, text);
	return -EINVAL;
}

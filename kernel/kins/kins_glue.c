/* SPDX-License-Identifier: GPL-2.0-or-later */
/* kins_glue.c - the kinematics modules' shared init and switch code (kins_glue.h). */
#include "rtapi.h"
#include "kins_glue.h"

int kins_claim(const char *mod, KINEMATICS_TYPE (*seen)(void), KINEMATICS_TYPE (*own)(void))
{
	if (seen == own)
		return 0;
	rtapi_print_msg(RTAPI_MSG_ERR,
			"%s: another kinematics module is already loaded; load only one (unloadrt it first)\n",
			mod);
	return -EBUSY;
}

int kins_switch_init(const char *mod, const char *letters, const char *default_letters,
		     struct kins_switch *s)
{
	s->type = KINS_SWITCH_PRIMARY;
	return kins_coords_parse(mod, letters && letters[0] ? letters : default_letters,
				 KINS_MAX_JOINTS, &s->coords);
}

int kins_switch_to(struct kins_switch *s, int type)
{
	if (type != KINS_SWITCH_PRIMARY && type != KINS_SWITCH_IDENTITY)
		return -EINVAL;
	s->type = type;
	return 0;
}

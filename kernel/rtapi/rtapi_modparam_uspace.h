/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_modparam_uspace.h - the module parameter registry that rtapi_app uses to apply
 * "name=value" arguments of loadrt (rtapi_module_param(3rtapi)), simulated-realtime
 * flavor. The host loads one module at a time:
 *     rtapi_mp_collect_begin(); dlopen(...);   // constructors call rtapi_mp_register()
 *     n = rtapi_mp_collect_end(&descs);        // this module's parameters
 *     rtapi_mp_set(descs[i], "0,0,2", err, sizeof(err));  ... then rtapi_app_main() */
#ifndef RTAPI_MODPARAM_USPACE_H
#define RTAPI_MODPARAM_USPACE_H

#include "rtapi_app.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Forget what was registered so far and start collecting for the next module. */
void rtapi_mp_collect_begin(void);

/* The descriptors registered since rtapi_mp_collect_begin(), in registration order;
 * *out stays valid until the next rtapi_mp_collect_begin() or rtapi_mp_register().
 * Returns their number. */
int rtapi_mp_collect_end(const struct rtapi_mp_desc ***out);

/* Assign one parameter from its text: integers in C notation (strtol base 0: 10, 0x1f,
 * 017) within the type's range; strings as given (copied and kept for the life of the
 * process); arrays as a comma-separated list of at most d->num elements, elements not
 * given keep their values. All or nothing: on error nothing is assigned, err gets one
 * line such as "step_type: '9x' is not an integer", and the result is -EINVAL. */
int rtapi_mp_set(const struct rtapi_mp_desc *d, const char *value, char *err, unsigned long errlen);

#ifdef __cplusplus
}
#endif
#endif /* RTAPI_MODPARAM_USPACE_H */

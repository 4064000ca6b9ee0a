/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_app.h - module entry points and module parameters (rtapi_module_param(3rtapi)).
 * Include once, in the file that defines rtapi_app_main(). In the kernel flavor the
 * macros map onto module_param/module_param_array; in the simulated flavor each
 * parameter registers itself with rtapi_app while the shared object is dlopen()ed, so
 * rtapi_app can apply "name=value" arguments before calling rtapi_app_main(). */
#ifndef RTAPI_APP_H
#define RTAPI_APP_H

#include "rtapi.h"

#ifdef __cplusplus
extern "C" {
#endif

int rtapi_app_main(void);	/* provided by the component: 0 or -errno */
void rtapi_app_exit(void);	/* provided by the component */

#if defined(__KERNEL__)
#include "rtapi_app_kmod.h"
#else

enum rtapi_mp_type {
	RTAPI_MP_TYPE_INT,
	RTAPI_MP_TYPE_LONG,
	RTAPI_MP_TYPE_STRING,
};

/* One module parameter as rtapi_app sees it. 'num' is 0 for a scalar, else the
 * array capacity (elements beyond those given keep their initial values). */
struct rtapi_mp_desc {
	const char *name;
	enum rtapi_mp_type type;
	void *addr;		/* int *, long *, or char ** (array: first element) */
	int num;
	const char *description;
};

/* Called by the constructors below while rtapi_app dlopen()s the module. */
void rtapi_mp_register(const struct rtapi_mp_desc *desc);

/* Linux's module_param uses the same name-pasting to make one record per parameter. */
#define RTAPI_MP_DECLARE(var, kind, count, descr)					\
	static const struct rtapi_mp_desc rtapi_mp_desc_##var = {			\
		#var, kind, (void *)&(var), count, descr };				\
	__attribute__((constructor)) static void rtapi_mp_register_##var(void)	\
	{ rtapi_mp_register(&rtapi_mp_desc_##var); }

#define RTAPI_MP_INT(var, descr) RTAPI_MP_DECLARE(var, RTAPI_MP_TYPE_INT, 0, descr)
#define RTAPI_MP_LONG(var, descr) RTAPI_MP_DECLARE(var, RTAPI_MP_TYPE_LONG, 0, descr)
#define RTAPI_MP_STRING(var, descr) RTAPI_MP_DECLARE(var, RTAPI_MP_TYPE_STRING, 0, descr)
#define RTAPI_MP_ARRAY_INT(var, num, descr) RTAPI_MP_DECLARE(var, RTAPI_MP_TYPE_INT, num, descr)
#define RTAPI_MP_ARRAY_LONG(var, num, descr) RTAPI_MP_DECLARE(var, RTAPI_MP_TYPE_LONG, num, descr)
#define RTAPI_MP_ARRAY_STRING(var, num, descr) RTAPI_MP_DECLARE(var, RTAPI_MP_TYPE_STRING, num, descr)

#define MODULE_LICENSE(x)
#define MODULE_AUTHOR(x)
#define MODULE_DESCRIPTION(x)
#define MODULE_SUPPORTED_DEVICE(x)
#define MODULE_PARM_DESC(v, d)
#define EXPORT_FUNCTION(fn)	/* rtapi_app dlopen()s with RTLD_GLOBAL */
#include "rtapi_export.h"

#endif /* __KERNEL__ */

#ifdef __cplusplus
}
#endif
#endif /* RTAPI_APP_H */

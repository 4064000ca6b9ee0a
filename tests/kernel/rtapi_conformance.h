/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_conformance.h - one RTAPI conformance suite for both flavors: the cases in
 * rtapi_conformance.c, written once against rtapi.h, run as GoogleTest in the
 * simulated flavor (tests/unit/rtapi/rtapi_conformance_test.cpp) and as the kernel
 * module rtapi_conformance.ko inside the qemu VM (tests/kernel/cases/05-rtapi-conformance.sh). */
#ifndef RTAPI_CONFORMANCE_H
#define RTAPI_CONFORMANCE_H

#ifdef __cplusplus
extern "C" {
#endif

struct rtapi_conf_case {
	const char *name;
	/* 0 when the behaviour is the documented one, else -1 with 'why' filled in */
	int (*run)(char *why, int why_len);
};

extern const struct rtapi_conf_case rtapi_conf_cases[];
extern const int rtapi_conf_ncases;

#ifdef __cplusplus
}
#endif
#endif /* RTAPI_CONFORMANCE_H */

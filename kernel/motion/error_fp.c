/* SPDX-License-Identifier: GPL-2.0-or-later */
/* error_fp.c - motion's error messages: queued in the shared error ring (motion_if.h)
 * for the task / motcmd, and logged. FP file: messages format doubles. */
#include "motmod_priv.h"

static struct motmod *report_to;	/* for homing's report function (no context) */

void mot_error_attach(struct motmod *m)
{
	report_to = m;
}

static void queue(struct motmod *m, const char *text)
{
	struct motion_error_ring *r = &m->shm->error;
	rtapi_u32 head = r->head;
	/* tail is written by readers: read it once, and a value that makes no sense
	 * (more queued than the ring holds) counts as full */
	rtapi_u32 tail = __atomic_load_n(&r->tail, __ATOMIC_ACQUIRE);

	if (head - tail >= MOTION_ERR_NUM) {
		r->overflow++;
		return;
	}
	rtapi_strlcpy(r->msg[head % MOTION_ERR_NUM], text, MOTION_ERR_LEN);
	__atomic_store_n(&r->head, head + 1, __ATOMIC_RELEASE);
}

void mot_error(struct motmod *m, const char *fmt, ...)
{
	char text[MOTION_ERR_LEN];
	va_list ap;

	va_start(ap, fmt);
	rtapi_vsnprintf(text, sizeof(text), fmt, ap);
	va_end(ap);
	rtapi_print_msg(RTAPI_MSG_ERR, "motion: %s\n", text);
	queue(m, text);
}

void mot_homing_report(const char *msg)
{
	if (report_to)
		mot_error(report_to, "%s", msg);
	else
		rtapi_print_msg(RTAPI_MSG_ERR, "motion: %s\n", msg);
}

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* debounce.c - filter noisy digital inputs, debounce(9) and the Debounce section
 * of the realtime components chapter: loadrt debounce [cfg=size[,size...]]
 * (default one group of one filter, at most 8 groups). Group G has pins
 * debounce.G.F.in / .out, the s32 parameter debounce.G.delay (thread periods)
 * and the function debounce.G (no FP). Logic: debounce_core.h. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "debounce_core.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("filter noisy digital inputs");

#define DEBOUNCE_MAX_GROUPS 8
#define DEBOUNCE_MAX_FILTERS 1024	/* per group; the page only limits by memory */

static int cfg[DEBOUNCE_MAX_GROUPS] = { -1, -1, -1, -1, -1, -1, -1, -1 };
RTAPI_MP_ARRAY_INT(cfg, DEBOUNCE_MAX_GROUPS, "number of filters in each group");

struct debounce_pins {		/* in hal_malloc() memory, one per filter */
	hal_bit_t *in;		/* read by the group's function */
	hal_bit_t *out;		/* written by the group's function */
	struct debounce_filter f;
};

struct debounce_group {		/* in hal_malloc() memory */
	hal_s32_t delay;	/* RW param, thread periods */
	int num;
	struct debounce_pins *filters;
};

static int comp_id;

static void debounce_group_update(void *arg, long period_ns)
{
	struct debounce_group *g = arg;
	rtapi_s32 delay = g->delay;
	int n;

	for (n = 0; n < g->num; n++)
		*g->filters[n].out = debounce_step(&g->filters[n].f, *g->filters[n].in, delay);
}

static int export_group(int gi, int num)
{
	char fn[HAL_NAME_LEN + 1];
	struct debounce_group *g = hal_malloc(sizeof(*g));
	int n, err;

	if (g)
		g->filters = hal_malloc(num * (long)sizeof(*g->filters));
	if (!g || !g->filters) {
		rtapi_print_msg(RTAPI_MSG_ERR, "debounce: out of HAL memory for group %d\n", gi);
		return -ENOMEM;
	}
	g->num = num;
	err = hal_param_s32_newf(HAL_RW, &g->delay, comp_id, "debounce.%d.delay", gi);
	for (n = 0; !err && n < num; n++) {
		err = hal_pin_bit_newf(HAL_IN, &g->filters[n].in, comp_id, "debounce.%d.%d.in", gi, n);
		if (!err)
			err = hal_pin_bit_newf(HAL_OUT, &g->filters[n].out, comp_id,
					       "debounce.%d.%d.out", gi, n);
	}
	if (err)
		return err;
	g->delay = 5;
	rtapi_snprintf(fn, sizeof(fn), "debounce.%d", gi);
	return hal_export_funct(fn, debounce_group_update, g, 0, 0, comp_id);
}

int rtapi_app_main(void)
{
	int groups, n, err = 0;

	for (groups = 0; groups < DEBOUNCE_MAX_GROUPS && cfg[groups] != -1; groups++) {
		if (cfg[groups] < 1 || cfg[groups] > DEBOUNCE_MAX_FILTERS) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"debounce: cfg= entry %d is %d, must be 1..%d filters\n",
					groups + 1, cfg[groups], DEBOUNCE_MAX_FILTERS);
			return -EINVAL;
		}
	}
	comp_id = hal_init("debounce");
	if (comp_id < 0)
		return comp_id;
	if (groups == 0)	/* default cfg "1": one group of one filter */
		err = export_group(0, 1);
	for (n = 0; !err && n < groups; n++)
		err = export_group(n, cfg[n]);
	if (err) {
		hal_exit(comp_id);
		return err;
	}
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* fifo_module.h - init-time code shared by sampler(9) and streamer(9): checking
 * depth=/cfg=, creating and removing the shared-memory FIFO of streamer_fifo.h,
 * and exporting the typed PREFIX.N.pin.M pins. Realtime code lives in each .c. */
#ifndef FIFO_MODULE_H
#define FIFO_MODULE_H

#include "rtapi.h"
#include "hal.h"
#include "streamer_fifo.h"

union fifo_pin_ptr {		/* one PREFIX.N.pin.M; which member follows cfg[M] */
	hal_float_t *f;
	hal_bit_t *b;
	hal_s32_t *s;
	hal_u32_t *u;
	hal_s64_t *l;
	hal_u64_t *k;
};

struct fifo_shm {		/* one FIFO's two RTAPI segments, as mapped here */
	int hdr_id;		/* 0 when not created */
	int data_id;
	struct hal_fifo_hdr *hdr;
	union hal_fifo_value *data;
};

/* Number of FIFOs asked for by cfg=/depth= (1..HAL_FIFO_MAX_FIFOS), or -EINVAL
 * after logging one line naming the bad entry. */
static inline int fifo_module_count(const char *comp, char *const *cfg, const int *depth)
{
	int n, k, pins;

	for (n = 0; n < HAL_FIFO_MAX_FIFOS && cfg[n] && cfg[n][0]; n++) {
		pins = hal_fifo_cfg_pins(cfg[n]);
		if (pins == -(1 + HAL_FIFO_MAX_PINS)) {
			rtapi_print_msg(RTAPI_MSG_ERR, "%s: cfg= string %d '%s' has more than %d pins\n",
					comp, n + 1, cfg[n], HAL_FIFO_MAX_PINS);
			return -EINVAL;
		}
		if (pins < 0) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"%s: cfg= string %d '%s': bad character '%c', use f, b, s, u, l (s64) or k (u64)\n",
					comp, n + 1, cfg[n], cfg[n][-pins - 1]);
			return -EINVAL;
		}
		if (depth[n] < 1 || depth[n] > HAL_FIFO_MAX_DEPTH) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"%s: depth= entry %d is %d; FIFO %d (cfg=%s) needs a depth of 1..%d\n",
					comp, n + 1, depth[n], n, cfg[n], HAL_FIFO_MAX_DEPTH);
			return -EINVAL;
		}
	}
	if (n == 0) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"%s: cfg= is required, e.g. loadrt %s depth=100 cfg=ffb\n", comp, comp);
		return -EINVAL;
	}
	for (k = n; k < HAL_FIFO_MAX_FIFOS; k++) {
		if ((cfg[k] && cfg[k][0]) || depth[k] != 0) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"%s: cfg= has %d strings but depth= or cfg= has more entries; give one depth per cfg string\n",
					comp, n);
			return -EINVAL;
		}
	}
	return n;
}

static inline void fifo_shm_destroy(struct fifo_shm *f, int module_id)
{
	if (f->hdr)
		hal_fifo_withdraw(f->hdr);	/* attached tools see the FIFO go away */
	if (f->data_id > 0)
		rtapi_shmem_delete(f->data_id, module_id);
	if (f->hdr_id > 0)
		rtapi_shmem_delete(f->hdr_id, module_id);
	f->hdr_id = f->data_id = 0;
	f->hdr = 0;
	f->data = 0;
}

/* Create FIFO n (keys base_key + n and base_key + HAL_FIFO_DATA_KEY_OFFSET + n)
 * with an empty ring and publish it. 0 or -errno after logging; on failure
 * nothing is left. */
static inline int fifo_shm_create(struct fifo_shm *f, const char *comp, int module_id,
				  int base_key, int n, const char *cfg, int depth)
{
	int pins = hal_fifo_cfg_pins(cfg);
	void *p;
	int err;

	f->hdr_id = rtapi_shmem_new(base_key + n, module_id, sizeof(struct hal_fifo_hdr));
	if (f->hdr_id < 0) {
		err = f->hdr_id;
		f->hdr_id = 0;
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: FIFO %d: cannot create shared memory key 0x%08x (%d)\n",
				comp, n, base_key + n, err);
		return err;
	}
	err = rtapi_shmem_getptr(f->hdr_id, &p);
	if (err)
		goto fail_map;
	f->hdr = (struct hal_fifo_hdr *)p;
	hal_fifo_hdr_init(f->hdr, cfg, pins, depth);
	f->data_id = rtapi_shmem_new(base_key + HAL_FIFO_DATA_KEY_OFFSET + n, module_id,
				     f->hdr->data_size);
	if (f->data_id < 0) {
		err = f->data_id;
		f->data_id = 0;
		rtapi_print_msg(RTAPI_MSG_ERR,
				"%s: FIFO %d: cannot create %u bytes of shared memory for depth=%d (%d)\n",
				comp, n, f->hdr->data_size, depth, err);
		goto fail;
	}
	err = rtapi_shmem_getptr(f->data_id, &p);
	if (err)
		goto fail_map;
	f->data = (union hal_fifo_value *)p;
	hal_fifo_publish(f->hdr);
	return 0;

fail_map:
	rtapi_print_msg(RTAPI_MSG_ERR, "%s: FIFO %d: cannot map shared memory (%d)\n", comp, n, err);
fail:
	fifo_shm_destroy(f, module_id);
	return err;
}

/* Export PREFIX.N.pin.M for every character of cfg, in direction dir. */
static inline int fifo_pins_export(union fifo_pin_ptr *pins, int comp_id, const char *comp,
				   int n, const char *cfg, hal_pin_dir_t dir)
{
	int m, err = 0;

	for (m = 0; !err && cfg[m]; m++) {
		switch (hal_fifo_type_of(cfg[m])) {
		case HAL_FIFO_FLOAT:
			err = hal_pin_float_newf(dir, &pins[m].f, comp_id, "%s.%d.pin.%d", comp, n, m);
			break;
		case HAL_FIFO_BIT:
			err = hal_pin_bit_newf(dir, &pins[m].b, comp_id, "%s.%d.pin.%d", comp, n, m);
			break;
		case HAL_FIFO_S32:
			err = hal_pin_s32_newf(dir, &pins[m].s, comp_id, "%s.%d.pin.%d", comp, n, m);
			break;
		case HAL_FIFO_U32:
			err = hal_pin_u32_newf(dir, &pins[m].u, comp_id, "%s.%d.pin.%d", comp, n, m);
			break;
		case HAL_FIFO_S64:
			err = hal_pin_s64_newf(dir, &pins[m].l, comp_id, "%s.%d.pin.%d", comp, n, m);
			break;
		case HAL_FIFO_U64:
			err = hal_pin_u64_newf(dir, &pins[m].k, comp_id, "%s.%d.pin.%d", comp, n, m);
			break;
		default:
			err = -EINVAL;	/* fifo_module_count() accepted only good characters */
			break;
		}
	}
	return err;
}

/* What a FIFO module (sampler, streamer) holds from init to exit. */
struct fifo_module {
	const char *name;	/* "sampler" / "streamer": component, rtapi module, messages */
	int module_id;		/* the rtapi module that owns the shared memory */
	int comp_id;
	struct fifo_shm shm[HAL_FIFO_MAX_FIFOS];
};

/* Undo fifo_module_load(), also half-way: HAL first, so no thread still runs
 * the FIFO function when its shared memory goes. */
static inline void fifo_module_remove(struct fifo_module *m)
{
	int n;

	hal_exit(m->comp_id);
	for (n = 0; n < HAL_FIFO_MAX_FIFOS; n++)
		fifo_shm_destroy(&m->shm[n], m->module_id);
	rtapi_exit(m->module_id);
}

/* rtapi_app_main() of a FIFO module: check cfg=/depth=, register with RTAPI and
 * HAL, give every FIFO 'size' bytes of HAL memory and let export_fifo(m, mem, n) make
 * its shared memory, pins and function. 0, or -errno with nothing left behind. */
static inline int fifo_module_load(struct fifo_module *m, char *const *cfg, const int *depth,
				   long size, int (*export_fifo)(struct fifo_module *m, void *mem, int n))
{
	char *all;
	int num, n, err;

	num = fifo_module_count(m->name, cfg, depth);
	if (num < 0)
		return num;
	m->module_id = rtapi_init(m->name);
	if (m->module_id < 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: rtapi_init failed (%d)\n", m->name, m->module_id);
		return m->module_id;
	}
	m->comp_id = hal_init(m->name);
	if (m->comp_id < 0) {
		rtapi_exit(m->module_id);
		return m->comp_id;
	}
	all = (char *)hal_malloc(num * size);
	err = all ? 0 : -ENOMEM;
	if (!all)
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: out of HAL memory for %d FIFOs\n", m->name, num);
	for (n = 0; !err && n < num; n++)
		err = export_fifo(m, all + n * size, n);
	if (err) {
		fifo_module_remove(m);
		return err;
	}
	hal_ready(m->comp_id);
	return 0;
}

#endif /* FIFO_MODULE_H */

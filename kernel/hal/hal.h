/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal.h - the HAL API of hal(3hal) and its pages. Included by realtime components
 * (RTAPI defined) and userspace components and tools (ULAPI defined); a component
 * written for the documented API compiles unchanged against it. */
#ifndef HAL_H
#define HAL_H

#include "rtapi.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Longest pin/param/signal/funct/thread/comp name. RULINGS.md asks for at least 47;
 * 63 leaves room for the "<funct>.time" pin of a function with a 47-character name. */
#define HAL_NAME_LEN 63

/* Data types (hal_type_t(3hal)). hal_bit_t is an integer type: test it with if (b). */
typedef bool hal_bool;
typedef volatile bool hal_bit_t;
typedef volatile __u32 hal_u32_t;
typedef volatile __s32 hal_s32_t;
typedef volatile rtapi_u64 hal_u64_t;	/* s64/u64: LinuxCNC 2.9's 64-bit pins */
typedef volatile rtapi_s64 hal_s64_t;
typedef double real_t __attribute__((aligned(8)));
typedef real_t hal_real_t;
typedef __u64 ireal_t __attribute__((aligned(8)));
typedef volatile real_t hal_float_t;

typedef enum {
	HAL_TYPE_UNSPECIFIED = -1,
	HAL_BIT = 1,
	HAL_FLOAT = 2,
	HAL_S32 = 3,
	HAL_U32 = 4,
	HAL_S64 = 5,
	HAL_U64 = 6
} hal_type_t;

typedef enum {
	HAL_DIR_UNSPECIFIED = -1,
	HAL_IN = 16,
	HAL_OUT = 32,
	HAL_IO = (HAL_IN | HAL_OUT)
} hal_pin_dir_t;

typedef enum {
	HAL_RO = 64,
	HAL_RW = 192
} hal_param_dir_t;

typedef hal_pin_dir_t hal_in_dir_t;	/* name used by hal_pin_new(3hal) */

/* Lock levels (hal_set_lock(3hal), RULINGS.md). */
#define HAL_LOCK_NONE 0
#define HAL_LOCK_LOAD 1		/* loadrt, loadusr */
#define HAL_LOCK_CONFIG 2	/* newsig, delsig, link, unlink, addf, delf */
#define HAL_LOCK_PARAMS 4	/* setp, sets */
#define HAL_LOCK_RUN 8		/* start, stop */
#define HAL_LOCK_ALL 0xff

/* --- components: init/cleanup or userspace code --- */
int hal_init(const char *name);		/* > 0 component id, or -errno */
int hal_exit(int comp_id);
int hal_ready(int comp_id);
int hal_unready(int comp_id);		/* back to not ready: more pins may follow */
void *hal_malloc(long int size);		/* 8-byte aligned, zeroed; NULL on failure */
typedef int (*hal_constructor_t)(const char *prefix, const char *arg);
int hal_set_constructor(int comp_id, hal_constructor_t constructor);

/* --- pins (hal_pin_new(3hal)) --- */
int hal_pin_bit_new(const char *name, hal_pin_dir_t dir, hal_bit_t **data_ptr_addr, int comp_id);
int hal_pin_float_new(const char *name, hal_pin_dir_t dir, hal_float_t **data_ptr_addr, int comp_id);
int hal_pin_u32_new(const char *name, hal_pin_dir_t dir, hal_u32_t **data_ptr_addr, int comp_id);
int hal_pin_s32_new(const char *name, hal_pin_dir_t dir, hal_s32_t **data_ptr_addr, int comp_id);
int hal_pin_bit_newf(hal_pin_dir_t dir, hal_bit_t **data_ptr_addr, int comp_id, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
int hal_pin_float_newf(hal_pin_dir_t dir, hal_float_t **data_ptr_addr, int comp_id, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
int hal_pin_u32_newf(hal_pin_dir_t dir, hal_u32_t **data_ptr_addr, int comp_id, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
int hal_pin_s32_newf(hal_pin_dir_t dir, hal_s32_t **data_ptr_addr, int comp_id, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
int hal_pin_new(const char *name, hal_type_t type, hal_pin_dir_t dir, void **data_ptr_addr, int comp_id);
/* 64-bit integer pins and params (hal_pin64.c); realtime code reads and writes them
 * with rtapi_load_u64/rtapi_store_u64 where another thread may look at them. */
int hal_pin_s64_new(const char *name, hal_pin_dir_t dir, hal_s64_t **data_ptr_addr, int comp_id);
int hal_pin_u64_new(const char *name, hal_pin_dir_t dir, hal_u64_t **data_ptr_addr, int comp_id);
int hal_pin_s64_newf(hal_pin_dir_t dir, hal_s64_t **data_ptr_addr, int comp_id, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
int hal_pin_u64_newf(hal_pin_dir_t dir, hal_u64_t **data_ptr_addr, int comp_id, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
int hal_param_s64_new(const char *name, hal_param_dir_t dir, hal_s64_t *data_addr, int comp_id);
int hal_param_u64_new(const char *name, hal_param_dir_t dir, hal_u64_t *data_addr, int comp_id);
int hal_param_s64_newf(hal_param_dir_t dir, hal_s64_t *data_addr, int comp_id, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
int hal_param_u64_newf(hal_param_dir_t dir, hal_u64_t *data_addr, int comp_id, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));

/* --- parameters (hal_param_new(3hal)) --- */
int hal_param_bit_new(const char *name, hal_param_dir_t dir, hal_bit_t *data_addr, int comp_id);
int hal_param_float_new(const char *name, hal_param_dir_t dir, hal_float_t *data_addr, int comp_id);
int hal_param_u32_new(const char *name, hal_param_dir_t dir, hal_u32_t *data_addr, int comp_id);
int hal_param_s32_new(const char *name, hal_param_dir_t dir, hal_s32_t *data_addr, int comp_id);
int hal_param_bit_newf(hal_param_dir_t dir, hal_bit_t *data_addr, int comp_id, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
int hal_param_float_newf(hal_param_dir_t dir, hal_float_t *data_addr, int comp_id, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
int hal_param_u32_newf(hal_param_dir_t dir, hal_u32_t *data_addr, int comp_id, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
int hal_param_s32_newf(hal_param_dir_t dir, hal_s32_t *data_addr, int comp_id, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
int hal_param_new(const char *name, hal_type_t type, hal_param_dir_t dir, void *data_addr, int comp_id);
/* Set a parameter's value by name, as its owner would (also RO params). */
int hal_param_bit_set(const char *name, int value);
int hal_param_float_set(const char *name, double value);
int hal_param_u32_set(const char *name, unsigned long value);
int hal_param_s32_set(const char *name, signed long value);
int hal_param_set(const char *name, hal_type_t type, void *value_addr);

/* --- aliases: a second name for a pin or parameter (LinuxCNC's hal_pin_alias).
 * Both names then find the object. alias NULL or "" removes every alias of it. --- */
int hal_pin_alias(const char *pin_name, const char *alias);
int hal_param_alias(const char *param_name, const char *alias);

/* --- signals (hal_signal_new(3hal)) --- */
int hal_signal_new(const char *signal_name, hal_type_t type);
int hal_signal_delete(const char *signal_name);
int hal_link(const char *pin_name, const char *signal_name);
int hal_unlink(const char *pin_name);

/* --- functions and threads --- */
typedef void (*hal_funct_t)(void *arg, long period);
int hal_export_funct(const char *name, hal_funct_t funct, void *arg, int uses_fp, int reentrant, int comp_id);
int hal_create_thread(const char *name, unsigned long period, int uses_fp);
int hal_thread_delete(const char *name);
int hal_add_funct_to_thread(const char *funct_name, const char *thread_name, int position);
int hal_del_funct_from_thread(const char *funct_name, const char *thread_name);
int hal_start_threads(void);
int hal_stop_threads(void);

/* --- lock levels --- */
int hal_set_lock(unsigned char lock_type);
int hal_get_lock(void);

#ifdef __cplusplus
}
#endif
#endif /* HAL_H */

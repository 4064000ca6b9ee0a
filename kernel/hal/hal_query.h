/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_query.h - what tools (halcmd, halsampler, halmeter, emcrsh) need beyond hal.h:
 * attaching to the HAL segment without becoming a component, snapshots of every
 * object, and checked value access by name. Userspace (ULAPI) only; implemented in
 * kernel/hal/hal_query.c so that only kernel/hal/ knows the segment layout.
 *
 * Every function takes the HAL mutex itself. Iteration callbacks run with the mutex
 * held: they must copy what they need and must not call back into HAL. */
#ifndef HAL_QUERY_H
#define HAL_QUERY_H

#include "hal.h"

#ifdef __cplusplus
extern "C" {
#endif

#define HAL_ARGS_LEN 511	/* module arguments kept for "save comp" */

union hal_value {
	bool b;
	__s32 s;
	__u32 u;
	double f;
	long long ls;		/* HAL_S64 */
	unsigned long long lu;	/* HAL_U64 */
};

/* Map the HAL segment (creating it if no HAL runs yet). 0 or -errno. Idempotent. */
int hal_attach(void);
void hal_detach(void);
/* Force the HAL mutex free (halcmd -R, halrun -U): recovery after a crash. */
void hal_release_mutex(void);

struct hal_comp_info {
	int id;
	char name[HAL_NAME_LEN + 1];
	bool is_realtime;		/* RT (loadrt) or User (hal_init from a process) */
	bool is_ready;
	int pid;			/* userspace components only; 0 for RT */
	char module[HAL_NAME_LEN + 1];	/* module that created it (RT only) */
	char args[HAL_ARGS_LEN + 1];	/* module arguments it was loaded with */
};

struct hal_pin_info {
	char name[HAL_NAME_LEN + 1];
	char owner[HAL_NAME_LEN + 1];
	int owner_id;
	hal_type_t type;
	hal_pin_dir_t dir;
	union hal_value value;		/* the linked signal's value, or the pin's own */
	char signal[HAL_NAME_LEN + 1];	/* "" when unlinked */
};

struct hal_param_info {
	char name[HAL_NAME_LEN + 1];
	char owner[HAL_NAME_LEN + 1];
	int owner_id;
	hal_type_t type;
	hal_param_dir_t dir;
	union hal_value value;
};

struct hal_sig_info {
	char name[HAL_NAME_LEN + 1];
	hal_type_t type;
	union hal_value value;
	int readers;			/* HAL_IN pins linked */
	int writers;			/* HAL_OUT pins linked: 0 or 1 */
	int bidirs;			/* HAL_IO pins linked */
};

struct hal_funct_info {
	char name[HAL_NAME_LEN + 1];
	char owner[HAL_NAME_LEN + 1];
	int owner_id;
	__u64 code_addr;		/* in the owner's address space: for display only */
	__u64 arg;
	bool uses_fp;
	bool reentrant;
	int users;			/* threads it is on */
};

struct hal_thread_info {
	char name[HAL_NAME_LEN + 1];
	char owner[HAL_NAME_LEN + 1];
	long long period_ns;
	int priority;
	bool uses_fp;
	__s32 time;			/* CPU clocks of the last cycle */
	__s32 tmax;
	__u64 cycles;			/* completed cycles since creation */
	__u64 cpu_ns;			/* thread CPU time spent in functions (bench) */
	long long overruns;		/* periods missed since creation (pin <name>.overruns) */
};

/* Iterate all objects of a kind, in no particular order (sort for display).
 * The callback returns 0 to continue, nonzero to stop. Returns the number visited or -errno. */
int hal_query_comps(int (*cb)(const struct hal_comp_info *, void *), void *ctx);
int hal_query_pins(int (*cb)(const struct hal_pin_info *, void *), void *ctx);
int hal_query_params(int (*cb)(const struct hal_param_info *, void *), void *ctx);
int hal_query_sigs(int (*cb)(const struct hal_sig_info *, void *), void *ctx);
int hal_query_functs(int (*cb)(const struct hal_funct_info *, void *), void *ctx);
int hal_query_threads(int (*cb)(const struct hal_thread_info *, void *), void *ctx);
/* Functions of a thread in execution order. */
int hal_query_thread_functs(const char *thread_name, int (*cb)(const char *funct_name, void *), void *ctx);

/* Single lookups: 0, or -ENOENT (no message printed). */
int hal_find_comp(const char *name, struct hal_comp_info *out);
int hal_find_pin(const char *name, struct hal_pin_info *out);
int hal_find_param(const char *name, struct hal_param_info *out);
int hal_find_sig(const char *name, struct hal_sig_info *out);
int hal_find_funct(const char *name, struct hal_funct_info *out);
int hal_find_thread(const char *name, struct hal_thread_info *out);

/* Checked writes, as halcmd's setp/sets do them. The value must already be of the
 * object's type. Each failure prints one line naming the object:
 * -ENOENT no such object, -EPERM output pin / read-only param / signal with a writer,
 * -EBUSY pin linked to a signal, -EACCES HAL locked (HAL_LOCK_PARAMS). */
int hal_set_pin_value(const char *name, const union hal_value *v);
int hal_set_param_value(const char *name, const union hal_value *v);
int hal_set_sig_value(const char *name, const union hal_value *v);

/* Aliases (hal_alias.c). unalias: 'name' is an alias (removed) or a pin/param name
 * (all its aliases removed); -ENOENT with a message when it is neither. */
struct hal_alias_info {
	bool is_param;			/* else a pin alias */
	char alias[HAL_NAME_LEN + 1];
	char target[HAL_NAME_LEN + 1];	/* the pin's or param's own name */
};
int hal_query_aliases(int (*cb)(const struct hal_alias_info *, void *), void *ctx);
int hal_unalias_pin(const char *name);
int hal_unalias_param(const char *name);

/* halcmd setexact_for_test_suite_only: the first thread's period is taken as asked,
 * whatever the clock gives. -EBUSY (message) once a thread exists. */
int hal_set_exact_periods(void);

/* Number of objects of each kind (status mem). */
struct hal_counts {
	int comps, pins, params, aliases, sigs, functs, threads;
};
int hal_object_counts(struct hal_counts *out);

/* Crash clean-up: remove userspace component 'comp_id' if its process no longer
 * exists (it died without hal_exit): its pins are unlinked and deleted, its memory
 * returned. 0 removed, -ENOENT no such component, -EPERM realtime, -EBUSY the process
 * is alive. No message. The kernel flavor will route this through hal_lib.ko's ioctl. */
int hal_comp_remove_dead(int comp_id);
/* hal_comp_remove_dead() for every userspace component; returns how many were removed. */
int hal_comps_remove_dead(void);

/* Before unloading a kernel module: take the functions of its components off every
 * thread (its module reference is dropped once no thread runs them). module "" = every
 * module. Returns the number of its components, or -errno. */
int hal_release_module(const char *module);

bool hal_threads_running(void);
/* Base period set by the first thread, 0 if none. */
long long hal_base_period(void);

/* Bytes of the HAL segment in use and in total (status). */
int hal_memory_usage(unsigned long *used, unsigned long *total);

#ifdef __cplusplus
}
#endif
#endif /* HAL_QUERY_H */

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_shmem_ulapi_kmod.h - shared memory for userspace programs (ULAPI) when the
 * kernel flavor runs: segments are made by rtapi.ko and reached through /dev/rtapi.
 * rtapi_shmem_uspace.c calls these instead of its POSIX ones when
 * rtapi_shmem_kmod_active(). Private to kernel/rtapi. */
#ifndef RTAPI_SHMEM_ULAPI_KMOD_H
#define RTAPI_SHMEM_ULAPI_KMOD_H

/* 1 when this process uses the kernel flavor's segments, decided at the first call
 * and kept: env HAL_FLAVOR=kernel (or kmod) -> 1, HAL_FLAVOR=sim (or uspace) -> 0,
 * unset -> 1 when /dev/rtapi exists (rtapi.ko is loaded). */
int rtapi_shmem_kmod_active(void);

/* As rtapi_shmem_new/_delete/_getptr, module_id already checked. A process cannot
 * create a segment here: a key that rtapi.ko does not hold, or no rtapi.ko at all,
 * gives -ENOENT (no message: the caller knows which module should have made it). */
int rtapi_shmem_new_kmod(int key, int module_id, unsigned long size);
int rtapi_shmem_delete_kmod(int shmem_id, int module_id);
int rtapi_shmem_getptr_kmod(int shmem_id, void **ptr);
void rtapi_shmem_module_exit_kmod(int module_id);

#endif /* RTAPI_SHMEM_ULAPI_KMOD_H */

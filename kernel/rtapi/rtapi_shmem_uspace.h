/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_shmem_uspace.h - simulated-realtime shared memory extras for the tools.
 * Segments are POSIX shared memory objects named "/rtapi-<uid>-<instance>-<key %08x>"
 * (instance: env RTAPI_INSTANCE, default "0"); a hidden header page before the user's
 * area holds a magic number, the size and a reference count across processes, so
 * the last rtapi_shmem_delete() unlinks the object. */
#ifndef RTAPI_SHMEM_USPACE_H
#define RTAPI_SHMEM_USPACE_H

#ifdef __cplusplus
extern "C" {
#endif

/* For `halrun -U`: unlink every segment of this user and RTAPI_INSTANCE, whoever holds
 * it (mappings stay valid until unmapped). Returns how many were unlinked, or -errno
 * when /dev/shm cannot be read. With the kernel flavor (rtapi_shmem_ulapi_kmod.h)
 * there is nothing to unlink: returns 0. */
int rtapi_shmem_force_unlink_all(void);

#ifdef __cplusplus
}
#endif
#endif /* RTAPI_SHMEM_USPACE_H */

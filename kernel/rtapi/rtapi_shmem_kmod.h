/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_shmem_kmod.h - the /dev/rtapi interface through which userspace reaches
 * segments that rtapi.ko allocated (kernel flavor). Shared by rtapi.ko and the
 * userspace side, so only fixed-width types: a 32-bit tool and a 64-bit kernel agree.
 *
 * Use: open("/dev/rtapi", O_RDWR); ioctl(fd, RTAPI_IOC_SHMEM_LOOKUP, &q) with q.key
 * set; then mmap(NULL, q.size, PROT_READ|PROT_WRITE, MAP_SHARED, fd, q.id * page size).
 * A mapping keeps its segment alive after the last module released it. */
#ifndef RTAPI_SHMEM_KMOD_H
#define RTAPI_SHMEM_KMOD_H

#ifdef __KERNEL__
#include <linux/types.h>
#include <linux/ioctl.h>
#else
#include <linux/types.h>
#include <sys/ioctl.h>
#endif

#define RTAPI_DEVICE_NAME "rtapi"	/* /dev/rtapi */

struct rtapi_shmem_query {
	__s32 key;	/* in: the key given to rtapi_shmem_new */
	__u32 id;	/* out: segment id (mmap offset = id * page size) */
	__u64 size;	/* out: size in bytes as requested by its creator */
};

#define RTAPI_IOC_MAGIC 0xb7
#define RTAPI_IOC_SHMEM_LOOKUP _IOWR(RTAPI_IOC_MAGIC, 1, struct rtapi_shmem_query)

#endif /* RTAPI_SHMEM_KMOD_H */

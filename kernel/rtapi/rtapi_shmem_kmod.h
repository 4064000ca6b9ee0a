/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_shmem_kmod.h - the /dev/rtapi interface through which userspace reaches
 * segments that rtapi.ko allocated (kernel flavor). Shared by rtapi.ko and the
 * userspace side, so only fixed-width types: a 32-bit tool and a 64-bit kernel agree.
 * The device is 0660, group 'hal' (firmware/udev/): docs/kernel-security.md.
 *
 * Use: open("/dev/rtapi", O_RDWR); ioctl(fd, RTAPI_IOC_SHMEM_LOOKUP, &q) with q.key
 * set; then mmap(NULL, q.size, PROT_READ|PROT_WRITE, MAP_SHARED, fd, RTAPI_SHMEM_PGOFF(q.id, 0)
 * * page size). A mapping keeps its segment alive after the last module released it.
 * A protected segment (the HAL's) maps read-only below its protected length and only
 * in separate pieces: RTAPI_SHMEM_PGOFF(id, first page) selects a piece. Other ioctls
 * go to the module that registered itself (hal_lib.ko: hal_request.h). */
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

/* mmap offset (in pages) of page 'page' of segment 'id' */
#define RTAPI_SHMEM_ID_BITS 8
#define RTAPI_SHMEM_PGOFF(id, page) ((unsigned long)(id) | ((unsigned long)(page) << RTAPI_SHMEM_ID_BITS))

#define RTAPI_IOC_MAGIC 0xb7
#define RTAPI_IOC_SHMEM_LOOKUP _IOWR(RTAPI_IOC_MAGIC, 1, struct rtapi_shmem_query)

#ifdef __KERNEL__
/* For hal_lib.ko: the segment made with 'key' maps read-only below 'ro_len' bytes
 * (call before creating it). 0 or -ENOMEM when the table is full. */
int rtapi_shmem_kmod_protect_key(int key, unsigned long ro_len);

/* For hal_lib.ko: ioctls of /dev/rtapi that are not RTAPI's go to 'ioctl', and
 * 'release' runs when a file that has a nonzero *state is closed. Calls hold a
 * reference on 'owner'. Pass NULL to unregister. */
struct file;
struct rtapi_dev_hook {
	struct module *owner;
	long (*ioctl)(unsigned long *state, unsigned int cmd, unsigned long arg);
	void (*release)(unsigned long *state);
};
void rtapi_kmod_set_dev_hook(const struct rtapi_dev_hook *hook);
#endif

#endif /* RTAPI_SHMEM_KMOD_H */

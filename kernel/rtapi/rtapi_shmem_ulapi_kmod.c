/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_shmem_ulapi_kmod.c - rtapi_shmem(3rtapi) for userspace programs in the kernel
 * flavor (see rtapi_shmem_ulapi_kmod.h): look the key up with the /dev/rtapi ioctl
 * and mmap the segment. Each key is mapped once per process and shared by the
 * modules (rtapi_init callers) that asked for it; the last one unmaps it. The
 * mapping keeps the kernel's segment alive even if its modules go away. */
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>
#include "rtapi.h"
#include "rtapi_shmem_kmod.h"
#include "rtapi_shmem_ulapi_kmod.h"
#include "rtapi_uspace.h"

#define MAX_MAPS 32

struct kmap {				/* guarded by map_lock */
	int in_use;
	int key;
	unsigned long size;		/* as its creator asked */
	void *base;
	size_t map_len;
	int nattached;
	unsigned char attached[RTAPI_MAX_MODULES + 1];	/* by module id */
};

static pthread_mutex_t map_lock = PTHREAD_MUTEX_INITIALIZER;
static struct kmap maps[MAX_MAPS + 1];	/* [0] unused: ids are 1.. */

int rtapi_shmem_kmod_active(void)
{
	static int active = -1;		/* -1: not decided yet */
	const char *f;

	if (__atomic_load_n(&active, __ATOMIC_ACQUIRE) >= 0)
		return active;
	f = getenv("HAL_FLAVOR");
	if (f && (strcmp(f, "kernel") == 0 || strcmp(f, "kmod") == 0))
		__atomic_store_n(&active, 1, __ATOMIC_RELEASE);
	else if (f && f[0])
		__atomic_store_n(&active, 0, __ATOMIC_RELEASE);
	else
		__atomic_store_n(&active, access("/dev/" RTAPI_DEVICE_NAME, F_OK) == 0,
				 __ATOMIC_RELEASE);
	return active;
}

/* Map the kernel's segment 'key' into m. */
static int map_segment(struct kmap *m, int key, unsigned long size)
{
	struct rtapi_shmem_query q = { .key = key };
	long page = sysconf(_SC_PAGESIZE);
	int fd, err;

	fd = open("/dev/" RTAPI_DEVICE_NAME, O_RDWR | O_CLOEXEC);
	if (fd < 0) {
		err = errno;
		if (err != ENOENT)	/* no rtapi.ko: no segment either, said as such */
			rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: cannot open /dev/%s: %s\n",
					RTAPI_DEVICE_NAME, strerror(err));
		return -err;
	}
	if (ioctl(fd, RTAPI_IOC_SHMEM_LOOKUP, &q) < 0) {
		err = errno;
		close(fd);
		if (err != ENOENT)
			rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: shared memory key 0x%08x: lookup "
					"failed: %s\n", (unsigned)key, strerror(err));
		return -err;
	}
	if (q.size < size) {
		close(fd);
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: shared memory key 0x%08x has %llu bytes, %lu "
				"requested\n", (unsigned)key, (unsigned long long)q.size, size);
		return -EINVAL;
	}
	m->map_len = (size_t)((q.size + page - 1) / page * page);
	m->base = mmap(NULL, m->map_len, PROT_READ | PROT_WRITE, MAP_SHARED, fd,
		       (off_t)q.id * page);
	err = errno;
	close(fd);			/* the mapping holds the device open */
	if (m->base == MAP_FAILED) {
		m->base = NULL;
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: shared memory key 0x%08x: mmap failed: %s\n",
				(unsigned)key, strerror(err));
		return -err;
	}
	m->size = (unsigned long)q.size;
	return 0;
}

static int new_locked(int key, int module_id, unsigned long size)
{
	struct kmap *m = NULL;
	int id, err;

	for (id = 1; id <= MAX_MAPS; id++)
		if (maps[id].in_use && maps[id].key == key) {
			m = &maps[id];
			break;
		}
	if (m) {			/* mapped here already: one more module on it */
		if (size > m->size) {
			rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: shared memory key 0x%08x has %lu bytes, "
					"%lu requested\n", (unsigned)key, m->size, size);
			return -EINVAL;
		}
		if (!m->attached[module_id]) {
			m->attached[module_id] = 1;
			m->nattached++;
		}
		return id;
	}
	for (id = 1; id <= MAX_MAPS && maps[id].in_use; id++)
		;
	if (id > MAX_MAPS) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: shared memory key 0x%08x: all %d blocks in "
				"use\n", (unsigned)key, MAX_MAPS);
		return -ENOMEM;
	}
	m = &maps[id];
	err = map_segment(m, key, size);
	if (err)
		return err;
	m->in_use = 1;
	m->key = key;
	memset(m->attached, 0, sizeof(m->attached));
	m->attached[module_id] = 1;
	m->nattached = 1;
	return id;
}

int rtapi_shmem_new_kmod(int key, int module_id, unsigned long size)
{
	int ret;

	pthread_mutex_lock(&map_lock);
	ret = new_locked(key, module_id, size);
	pthread_mutex_unlock(&map_lock);
	return ret;
}

static void detach_locked(struct kmap *m, int module_id)
{
	m->attached[module_id] = 0;
	if (--m->nattached == 0) {
		munmap(m->base, m->map_len);
		m->base = NULL;
		m->in_use = 0;
	}
}

int rtapi_shmem_delete_kmod(int shmem_id, int module_id)
{
	int ret = -EINVAL;

	pthread_mutex_lock(&map_lock);
	if (shmem_id >= 1 && shmem_id <= MAX_MAPS && maps[shmem_id].in_use &&
	    module_id >= 1 && module_id <= RTAPI_MAX_MODULES && maps[shmem_id].attached[module_id]) {
		detach_locked(&maps[shmem_id], module_id);
		ret = 0;
	}
	pthread_mutex_unlock(&map_lock);
	if (ret)
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_shmem_delete(%d, module %d): the module "
				"does not hold that block\n", shmem_id, module_id);
	return ret;
}

void rtapi_shmem_module_exit_kmod(int module_id)
{
	int id;

	pthread_mutex_lock(&map_lock);
	for (id = 1; id <= MAX_MAPS; id++)
		if (maps[id].in_use && maps[id].attached[module_id])
			detach_locked(&maps[id], module_id);
	pthread_mutex_unlock(&map_lock);
}

int rtapi_shmem_getptr_kmod(int shmem_id, void **ptr)
{
	if (shmem_id < 1 || shmem_id > MAX_MAPS || !ptr)
		return -EINVAL;
	if (!__atomic_load_n(&maps[shmem_id].in_use, __ATOMIC_ACQUIRE) || !maps[shmem_id].base)
		return -EINVAL;
	*ptr = maps[shmem_id].base;
	return 0;
}

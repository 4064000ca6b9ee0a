/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_shmem_uspace.c - shared memory blocks (rtapi_shmem(3rtapi)) for the
 * simulated-realtime flavor, both builds, on POSIX shared memory; naming and the
 * header page are described in rtapi_shmem_uspace.h. Within one process each key is
 * mapped once and shared by all modules that asked for it; every module attachment,
 * in any process, holds one reference in the header. A userspace program (ULAPI)
 * running with the kernel flavor uses rtapi.ko's segments instead: each entry point
 * hands over to rtapi_shmem_ulapi_kmod.c then. */
#include <dirent.h>
#include <fcntl.h>
#include <pthread.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include "rtapi.h"
#include "rtapi_shmem_uspace.h"
#include "rtapi_uspace.h"
#include "rtapi_shmem_ulapi_kmod.h"
#ifdef ULAPI
#define KERNEL_FLAVOR() rtapi_shmem_kmod_active()
#else
#define KERNEL_FLAVOR() 0	/* rtapi_app is the simulated flavor's module host */
#endif

#define RTAPI_MAX_SHMEMS 32
#define SHM_HDR_SIZE 4096		/* keeps the user's area page aligned */
#define SHM_MAGIC 0x52534d31u		/* "RSM1": written last, once the header is valid */
#define SHM_OPEN_TRIES 1000		/* ~1 s of 1 ms retries while another process races us */
#define SHM_PREFIX_LEN 64		/* "rtapi-<uid>-<instance>-", instance <= 32 chars */
#define SHM_NAME_LEN 96

struct shm_header {
	rtapi_u32 magic;
	rtapi_u32 refs;			/* module attachments in all processes; atomic */
	rtapi_u64 size;			/* the user's area, in bytes */
	rtapi_s32 key;
};

struct shm_rec {			/* process-local; guarded by shm_lock */
	int in_use;
	int key;
	char name[SHM_NAME_LEN];	/* kept: RTAPI_INSTANCE may change later */
	unsigned long size;		/* the segment's user size (may exceed what we asked) */
	char *base;			/* the mapping: header page, then the user's area */
	unsigned long map_len;
	int nattached;
	unsigned char attached[RTAPI_MAX_MODULES + 1];	/* by module id */
};

static pthread_mutex_t shm_lock = PTHREAD_MUTEX_INITIALIZER;
static struct shm_rec shms[RTAPI_MAX_SHMEMS + 1];	/* [0] unused: ids are 1.. */

static const char *instance_name(void)
{
	const char *inst = getenv("RTAPI_INSTANCE");

	return (inst && inst[0]) ? inst : "0";
}

static int shm_prefix(char *buf, size_t len)
{
	const char *inst = instance_name();

	if (strchr(inst, '/') || strlen(inst) > 32) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: RTAPI_INSTANCE='%s' is not usable: at most 32 "
				"characters, no '/'\n", inst);
		return -EINVAL;
	}
	snprintf(buf, len, "rtapi-%u-%s-", (unsigned)getuid(), inst);
	return 0;
}

static void short_wait(void)
{
	struct timespec ts = { 0, 1000000 };

	nanosleep(&ts, NULL);
}

/* Take one reference unless the count already fell to 0 (its last user is unlinking
 * it: the caller must retry and will create a fresh one). */
static int ref_get(struct shm_header *h)
{
	rtapi_u32 r = __atomic_load_n(&h->refs, __ATOMIC_ACQUIRE);

	while (r != 0)
		if (__atomic_compare_exchange_n(&h->refs, &r, r + 1, 0, __ATOMIC_ACQ_REL, __ATOMIC_ACQUIRE))
			return 1;
	return 0;
}

static int create_segment(int fd, struct shm_rec *s, int key, unsigned long size)
{
	struct shm_header *h;

	if (ftruncate(fd, (off_t)(SHM_HDR_SIZE + size)) != 0) {
		int err = errno;

		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: shared memory %s: cannot allocate %lu bytes: %s\n",
				s->name, size, strerror(err));
		shm_unlink(s->name);
		return -err;
	}
	s->map_len = SHM_HDR_SIZE + size;
	s->base = mmap(NULL, s->map_len, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
	if (s->base == MAP_FAILED) {
		int err = errno;

		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: shared memory %s: mmap failed: %s\n",
				s->name, strerror(err));
		shm_unlink(s->name);
		return -err;
	}
	h = (struct shm_header *)s->base;
	h->size = size;
	h->key = key;
	h->refs = 1;
	__atomic_store_n(&h->magic, SHM_MAGIC, __ATOMIC_RELEASE);	/* now others may use it */
	s->size = size;
	return 0;
}

/* Map an existing segment. Returns 0, 1 to retry (not ready, or being deleted), or -errno. */
static int open_segment(int fd, struct shm_rec *s, unsigned long size)
{
	struct shm_header *h;
	struct stat st;

	if (fstat(fd, &st) != 0)
		return -errno;
	if (st.st_size < SHM_HDR_SIZE)
		return 1;		/* its creator has not sized it yet */
	s->map_len = (unsigned long)st.st_size;
	s->base = mmap(NULL, s->map_len, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
	if (s->base == MAP_FAILED)
		return -errno;
	h = (struct shm_header *)s->base;
	if (__atomic_load_n(&h->magic, __ATOMIC_ACQUIRE) != SHM_MAGIC) {
		munmap(s->base, s->map_len);
		return 1;
	}
	if (h->size < size) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: shared memory key 0x%08x has %lu bytes, %lu "
				"requested\n", (unsigned)h->key, (unsigned long)h->size, size);
		munmap(s->base, s->map_len);
		return -EINVAL;
	}
	if (!ref_get(h)) {
		munmap(s->base, s->map_len);
		return 1;
	}
	s->size = (unsigned long)h->size;
	return 0;
}

/* Create the segment or attach to the existing one, racing safely with others. */
static int attach_segment(struct shm_rec *s, int key, unsigned long size)
{
	int tries, fd, err;

	for (tries = 0; tries < SHM_OPEN_TRIES; tries++) {
		fd = shm_open(s->name, O_RDWR | O_CREAT | O_EXCL, 0600);
		if (fd >= 0) {
			err = create_segment(fd, s, key, size);
			close(fd);
			return err;
		}
		if (errno != EEXIST)
			break;
		fd = shm_open(s->name, O_RDWR, 0);
		if (fd < 0) {
			if (errno == ENOENT)
				continue;	/* unlinked between our two opens */
			break;
		}
		err = open_segment(fd, s, size);
		close(fd);
		if (err <= 0)
			return err;
		short_wait();
	}
	if (tries == SHM_OPEN_TRIES) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: shared memory %s never became ready (its creator "
				"died?): run 'halrun -U'\n", s->name);
		return -EBUSY;
	}
	err = errno;
	rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: shared memory %s: %s\n", s->name, strerror(err));
	return -err;
}

static struct shm_rec *find_key(int key)
{
	int id;

	for (id = 1; id <= RTAPI_MAX_SHMEMS; id++)
		if (shms[id].in_use && shms[id].key == key)
			return &shms[id];
	return NULL;
}

static struct shm_rec *free_slot(void)
{
	int id;

	for (id = 1; id <= RTAPI_MAX_SHMEMS; id++)
		if (!shms[id].in_use)
			return &shms[id];
	return NULL;
}

/* caller holds shm_lock */
static int shmem_new_locked(int key, int module_id, unsigned long size)
{
	struct shm_rec *s = find_key(key);
	char prefix[SHM_PREFIX_LEN];
	int err;

	if (s) {		/* mapped here already: one more module on it */
		if (size > s->size) {
			rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: shared memory key 0x%08x has %lu bytes, "
					"%lu requested\n", (unsigned)key, s->size, size);
			return -EINVAL;
		}
		if (!s->attached[module_id]) {
			if (!ref_get((struct shm_header *)s->base))
				return -EIDRM;	/* cannot happen while we hold a reference */
			s->attached[module_id] = 1;
			s->nattached++;
		}
		return (int)(s - shms);
	}
	s = free_slot();
	if (!s) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: shared memory key 0x%08x: all %d blocks in "
				"use\n", (unsigned)key, RTAPI_MAX_SHMEMS);
		return -ENOMEM;
	}
	err = shm_prefix(prefix, sizeof(prefix));
	if (err)
		return err;
	snprintf(s->name, sizeof(s->name), "/%.63s%08x", prefix, (unsigned)key);
	err = attach_segment(s, key, size);
	if (err)
		return err;
	s->in_use = 1;
	s->key = key;
	memset(s->attached, 0, sizeof(s->attached));
	s->attached[module_id] = 1;
	s->nattached = 1;
	return (int)(s - shms);
}

int rtapi_shmem_new(int key, int module_id, unsigned long int size)
{
	int ret;

	if (key == 0 || size == 0 || size > (1UL << 40)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_shmem_new(key 0x%08x, %lu bytes): the key "
				"must be nonzero and the size 1..2^40\n", (unsigned)key, size);
		return -EINVAL;
	}
	if (!rtapi_module_is_valid(module_id)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_shmem_new(key 0x%08x): module %d did not "
				"come from rtapi_init\n", (unsigned)key, module_id);
		return -EINVAL;
	}
	if (KERNEL_FLAVOR())
		return rtapi_shmem_new_kmod(key, module_id, size);
	pthread_mutex_lock(&shm_lock);
	ret = shmem_new_locked(key, module_id, size);
	pthread_mutex_unlock(&shm_lock);
	return ret;
}

/* caller holds shm_lock */
static void detach_locked(struct shm_rec *s, int module_id)
{
	struct shm_header *h = (struct shm_header *)s->base;

	s->attached[module_id] = 0;
	s->nattached--;
	if (__atomic_sub_fetch(&h->refs, 1, __ATOMIC_ACQ_REL) == 0)
		shm_unlink(s->name);	/* the last user anywhere */
	if (s->nattached == 0) {
		munmap(s->base, s->map_len);
		s->base = NULL;
		s->in_use = 0;
	}
}

int rtapi_shmem_delete(int shmem_id, int module_id)
{
	struct shm_rec *s;
	int ret = -EINVAL;

	if (KERNEL_FLAVOR())
		return rtapi_shmem_delete_kmod(shmem_id, module_id);
	pthread_mutex_lock(&shm_lock);
	s = (shmem_id >= 1 && shmem_id <= RTAPI_MAX_SHMEMS) ? &shms[shmem_id] : NULL;
	if (s && s->in_use && module_id >= 1 && module_id <= RTAPI_MAX_MODULES &&
	    s->attached[module_id]) {
		detach_locked(s, module_id);
		ret = 0;
	}
	pthread_mutex_unlock(&shm_lock);
	if (ret)
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: rtapi_shmem_delete(%d, module %d): the module "
				"does not hold that block\n", shmem_id, module_id);
	return ret;
}

void rtapi_shmem_module_exit(int module_id)
{
	int id;

	if (KERNEL_FLAVOR()) {
		rtapi_shmem_module_exit_kmod(module_id);
		return;
	}
	pthread_mutex_lock(&shm_lock);
	for (id = 1; id <= RTAPI_MAX_SHMEMS; id++)
		if (shms[id].in_use && shms[id].attached[module_id])
			detach_locked(&shms[id], module_id);
	pthread_mutex_unlock(&shm_lock);
}

/* No lock: realtime code may call this; a block stays mapped while its caller holds it. */
int rtapi_shmem_getptr(int shmem_id, void **ptr)
{
	struct shm_rec *s;

	if (KERNEL_FLAVOR())
		return rtapi_shmem_getptr_kmod(shmem_id, ptr);
	if (shmem_id < 1 || shmem_id > RTAPI_MAX_SHMEMS || !ptr)
		return -EINVAL;
	s = &shms[shmem_id];
	if (!__atomic_load_n(&s->in_use, __ATOMIC_ACQUIRE) || !s->base)
		return -EINVAL;
	*ptr = s->base + SHM_HDR_SIZE;
	return 0;
}

int rtapi_shmem_force_unlink_all(void)
{
	char prefix[SHM_PREFIX_LEN], path[SHM_NAME_LEN + 256];
	struct dirent *de;
	DIR *dir;
	int n = 0, err = shm_prefix(prefix, sizeof(prefix));

	if (err)
		return err;
	if (KERNEL_FLAVOR())
		return 0;	/* rtapi.ko frees its segments when their modules go */
	dir = opendir("/dev/shm");
	if (!dir) {
		err = errno;
		rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: cannot read /dev/shm: %s\n", strerror(err));
		return -err;
	}
	while ((de = readdir(dir)) != NULL) {
		if (strncmp(de->d_name, prefix, strlen(prefix)) != 0)
			continue;
		snprintf(path, sizeof(path), "/%s", de->d_name);
		if (shm_unlink(path) == 0)
			n++;
	}
	closedir(dir);
	return n;
}

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_segcheck.c - kernel-flavor test tool, run inside the test VM: finds the HAL
 * segment through /dev/rtapi (ioctl lookup by key, mmap), checks its header and
 * prints the object counts, one "name=value" per word:
 *   magic=ok version=1 comps=2 pins=6 params=4 sigs=0 functs=1 threads=1 running=0
 * Exit status: 0 found and sane, 1 no segment, 2 bad header or device error. */
#define ULAPI
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>
#include "rtapi.h"
#include "hal_layout.h"
#include "rtapi_shmem_kmod.h"

int main(void)
{
	struct rtapi_shmem_query q = { .key = HAL_KEY };
	const struct hal_seg_hdr *seg;
	int fd = open("/dev/" RTAPI_DEVICE_NAME, O_RDWR);

	if (fd < 0) {
		perror("/dev/" RTAPI_DEVICE_NAME);
		return 2;
	}
	if (ioctl(fd, RTAPI_IOC_SHMEM_LOOKUP, &q) < 0) {
		perror("HAL segment lookup");
		return errno == ENOENT ? 1 : 2;
	}
	/* the records only, read-only: nobody maps them writable (docs/kernel-security.md) */
	seg = mmap(NULL, HAL_VAL_START(q.size), PROT_READ, MAP_SHARED, fd,
		   (off_t)q.id * sysconf(_SC_PAGESIZE));
	if (seg == MAP_FAILED) {
		perror("mmap of the HAL segment");
		return 2;
	}
	if (seg->magic != HAL_SEG_MAGIC || seg->init_state != 2) {
		printf("magic=bad (0x%08x, init_state %u)\n", seg->magic, seg->init_state);
		return 2;
	}
	printf("magic=ok version=%u comps=%u pins=%u params=%u sigs=%u functs=%u threads=%u "
	       "running=%u\n", seg->version, seg->count[HAL_KIND_COMP], seg->count[HAL_KIND_PIN],
	       seg->count[HAL_KIND_PARAM], seg->count[HAL_KIND_SIG], seg->count[HAL_KIND_FUNCT],
	       seg->count[HAL_KIND_THREAD], seg->threads_running);
	return 0;
}

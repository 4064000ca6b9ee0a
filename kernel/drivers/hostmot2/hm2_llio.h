/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_llio.h - the narrow interface between hostmot2 and a board driver ("low-level
 * I/O"). A board driver (hm2_pci, hm2_eth, hm2_7i43, hm2_sim) fills one struct
 * hm2_llio per board and calls hm2_register(); the hostmot2 core is its only user.
 * The core knows no board, the board knows no function module.
 *
 * Addresses are byte addresses in the 64 KiB HostMot2 space; sizes are bytes and
 * always a multiple of 4 (whole little-endian 32-bit words). Every op returns 0 or
 * a negative errno; a transport failure also sets *io_error (the core's
 * <board>.io_error parameter) and needs_reset, and the core then stops touching
 * the board until the user clears io_error. */
#ifndef HM2_LLIO_H
#define HM2_LLIO_H

#include "rtapi.h"
#include "hal.h"

#define HM2_LLIO_MAX_CONNECTORS 8

struct hm2_llio {
	/* set by the board driver before hm2_register() */
	char name[HAL_NAME_LEN + 1];	/* HAL prefix of the board, "hm2_5i25.0" */
	int comp_id;			/* the board driver's component: owns every HAL object */
	int num_ioport_connectors;	/* must equal the IDROM's IOPorts */
	int pins_per_connector;		/* must equal the IDROM's PortWidth */
	const char *ioport_connector_name[HM2_LLIO_MAX_CONNECTORS];	/* "P3", in IOPort order */
	int num_leds;			/* LEDs on the board (led.CR01...) */
	const char *fpga_part_number;	/* "6slx9tqg144"; NULL when it cannot be programmed */
	int threadsafe;			/* read_gpio/write_gpio may run in another thread */
	int split_read;			/* long turnaround: export read-request */

	/* immediate transfers */
	int (*read)(struct hm2_llio *llio, rtapi_u32 addr, void *buf, int size);
	int (*write)(struct hm2_llio *llio, rtapi_u32 addr, const void *buf, int size);
	/* batched transfers (optional, all four or none): reads are queued, sent as one
	 * request and received into their buffers; writes are queued and sent at once */
	int (*queue_read)(struct hm2_llio *llio, rtapi_u32 addr, void *buf, int size);
	int (*send_queued_reads)(struct hm2_llio *llio);
	int (*receive_queued_reads)(struct hm2_llio *llio);	/* -EAGAIN: not yet, skip a cycle */
	int (*queue_write)(struct hm2_llio *llio, rtapi_u32 addr, const void *buf, int size);
	int (*send_queued_writes)(struct hm2_llio *llio);
	/* FPGA configuration (optional: NULL on boards that boot from flash). The core
	 * calls reset, then program_fpga with the .BIT file's bitstream as stored in the
	 * file; the board bit-reverses each byte if its configuration port needs it
	 * (hm2_bitfile_reverse) and returns 0 once the FPGA says DONE. */
	int (*program_fpga)(struct hm2_llio *llio, const void *bitstream, rtapi_u32 size);
	int (*reset)(struct hm2_llio *llio);

	void *priv;			/* the board driver's own state */

	/* set by the core */
	hal_bit_t *io_error;		/* <board>.io_error; the board sets it on a failure */
	int needs_reset;		/* set with io_error: force-write everything on recovery */
	void *hm2;			/* the core's state for this board */
};

/* Parse config (the hostmot2 config string, may be NULL), check the IDROM, build the
 * function modules' HAL objects and functions, and initialise the board. 0 or -errno
 * with one message naming the board and the reason. Call from rtapi_app_main() after
 * hal_init() (the HAL objects belong to llio->comp_id). */
int hm2_register(struct hm2_llio *llio, const char *config);

/* Make the board safe (the watchdog bites at once) and forget it; call before
 * hal_exit() of the board driver's component. */
void hm2_unregister(struct hm2_llio *llio);

/* The start of the rtapi_app_main() of a board driver with a board per module-parameter
 * entry (hm2_7i43, hm2_eth), once it counted n boards: a config= entry past them (of
 * max) names no board and is refused, naming `key` (the parameter that makes a board);
 * then the component `name` joins HAL and *boards gets n zeroed structs of `size` bytes
 * in HAL memory. The component id, or -errno (nothing left behind). */
static inline int hm2_llio_init_boards(const char *name, const char *key, char **config, int max,
				       int n, unsigned long size, void **boards)
{
	int k, comp_id;

	for (k = n; k < max; k++) {
		if (config[k] && *config[k]) {
			rtapi_print_msg(RTAPI_MSG_ERR, "%s: config= entry %d has no %s= entry\n", name, k, key);
			return -EINVAL;
		}
	}
	comp_id = hal_init(name);
	if (comp_id < 0)
		return comp_id;
	*boards = hal_malloc((long)(n * size));	/* zeroed */
	if (!*boards) {
		hal_exit(comp_id);
		return -ENOMEM;
	}
	return comp_id;
}

/* The end of the rtapi_app_main() of a board driver with a board per module-parameter
 * entry (hm2_7i43, hm2_eth, hm2_sim): set up boards 0..n-1 in order; on the first
 * failure undo() releases every board set up so far and the component leaves HAL.
 * 0 (the component is ready) or that failure's -errno. */
static inline int hm2_llio_setup_boards(int comp_id, int n, int (*setup)(int k), void (*undo)(void))
{
	int k, rc = 0;

	for (k = 0; k < n && !rc; k++)
		rc = setup(k);
	if (rc) {
		undo();
		hal_exit(comp_id);
		return rc;
	}
	hal_ready(comp_id);
	return 0;
}

#endif /* HM2_LLIO_H */

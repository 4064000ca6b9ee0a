/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_bspi.c - Buffered SPI (GTag 14, hostmot2.md 7.9) and its sub-driver API
 * (hm2_serial.h). No HAL objects: each instance is a name, hm2_<board>.<N>.bspi.<i>,
 * printed at load, that a sub-driver (mesa_7i65) uses to describe its chips and
 * register frames. Registers of instance i (stride from the MD, 0x40):
 *   reg 0: FIFO window, word ch = push data with descriptor ch; reading pops a reply
 *   reg 1: descriptor setup, written 16 times from #15 down to #0
 *   reg 2: FIFO counts; any write empties both FIFOs
 * Every cycle read() pops one reply per registered frame whose channel echoes (with
 * the other per-cycle reads; a channel is set up before its frames are added), if
 * the previous write() sent the frames, and calls the read function when they all
 * arrived (the FIFO count is read first); write() empties the FIFOs, calls the write
 * function and pushes the frames. Integer-only; the callbacks may use FP (they run in read/write). */
#include "rtapi.h"
#include "rtapi_string.h"
#include "hal.h"
#include "hm2.h"

#define REG_FIFO 0
#define REG_CD 1
#define REG_COUNT 2
#define MAX_NAMED 16		/* BSPI instances on all boards together */

/* the names sub-drivers look up; changed only while modules load or unload */
static struct hm2_bspi_inst *named[MAX_NAMED];

static struct hm2_bspi_inst *find(const char *name, const char *caller)
{
	int i;

	for (i = 0; i < MAX_NAMED; i++)
		if (named[i] && strcmp(named[i]->name, name) == 0)
			return named[i];
	rtapi_print_msg(RTAPI_MSG_ERR, "hostmot2: %s: no BSPI instance named '%s' (the names are "
			"printed when the board loads)\n", caller, name ? name : "(null)");
	return 0;
}

int hm2_bspi_parse(struct hostmot2 *hm2, const struct hm2_md *md)
{
	struct hm2_bspi *s = &hm2->bspi;
	char err[HM2_ERRLEN];
	int n;

	if (hm2_md_is_consistent(md, err, sizeof(err))) {
		HM2_ERR(hm2, "%s", err);
		return -EINVAL;
	}
	n = hm2_config_instances(&hm2->cfg, HM2_NUM_BSPIS, md->instances, err, sizeof(err));
	if (n < 0) {
		HM2_ERR(hm2, "%s", err);
		return n;
	}
	s->md = md;
	s->num = n;
	if (!n)
		return 0;
	s->inst = hal_malloc(n * sizeof(*s->inst));
	if (!s->inst)
		return -ENOMEM;
	memset(s->inst, 0, n * sizeof(*s->inst));
	hm2_pins_allocate(hm2, HM2_GTAG_BSPI, n);
	return 0;
}

int hm2_bspi_export(struct hostmot2 *hm2)
{
	struct hm2_bspi *s = &hm2->bspi;
	int i, j;

	for (i = 0; i < s->num; i++) {
		struct hm2_bspi_inst *b = &s->inst[i];

		b->hm2 = hm2;
		rtapi_snprintf(b->name, sizeof(b->name), "%s.bspi.%d", hm2->llio->name, i);
		for (j = 0; j < MAX_NAMED && named[j]; j++)
			;
		if (j == MAX_NAMED) {
			HM2_ERR(hm2, "bspi: more than %d BSPI instances on all boards", MAX_NAMED);
			return -ENOMEM;
		}
		named[j] = b;
		HM2_INFO(hm2, "BSPI channel %s", b->name);
	}
	return 0;
}

void hm2_bspi_cleanup(struct hostmot2 *hm2)
{
	int i, j;

	for (i = 0; i < hm2->bspi.num; i++)
		for (j = 0; j < MAX_NAMED; j++)
			if (named[j] == &hm2->bspi.inst[i])
				named[j] = 0;
}

static void write_descriptors(struct hostmot2 *hm2, int i)
{
	struct hm2_bspi_inst *b = &hm2->bspi.inst[i];
	int j;

	for (j = 15; j >= 0; j--)
		hm2_write_now(hm2, hm2_md_addr(hm2->bspi.md, REG_CD, i), &b->cd[j], 4);
	b->cd_dirty = 0;
}

void hm2_bspi_force_write(struct hostmot2 *hm2)
{
	rtapi_u32 clear = 0;
	int i;

	for (i = 0; i < hm2->bspi.num; i++) {
		write_descriptors(hm2, i);
		hm2_write_now(hm2, hm2_md_addr(hm2->bspi.md, REG_COUNT, i), &clear, 4);
	}
}

int hm2_bspi_request_reads(struct hostmot2 *hm2)
{
	int i, k, rc = 0;

	for (i = 0; i < hm2->bspi.num && rc >= 0; i++) {
		struct hm2_bspi_inst *b = &hm2->bspi.inst[i];

		if (!b->active || !b->sent)
			continue;	/* nothing in flight: an empty FIFO must not be popped */
		rc = hm2_tram_extra_read(hm2, hm2_md_addr(hm2->bspi.md, REG_COUNT, i), &b->count_rd, 4);
		for (k = 0; k < b->num_frames && rc >= 0; k++)
			if (b->frame_echo[k])
				rc = hm2_tram_extra_read(hm2, hm2_md_addr(hm2->bspi.md, REG_FIFO, i),
							 &b->frame_rd[k], 4);
	}
	return rc < 0 ? rc : 0;
}

/* a callback, marked as running so that hm2_bspi_release() can wait for it */
static void call(struct hm2_bspi_inst *b, int (*volatile *fn)(void *), void *volatile *data)
{
	int (*f)(void *);

	b->in_callback = 1;
	hm2_mb();
	f = *fn;
	if (f)
		f(*data);
	hm2_mb();
	b->in_callback = 0;
}

void hm2_bspi_read(struct hostmot2 *hm2)
{
	int i;

	for (i = 0; i < hm2->bspi.num; i++) {
		struct hm2_bspi_inst *b = &hm2->bspi.inst[i];

		/* a cycle shorter than the frames: not all replies are in, and the reads
		 * above took what there was; skip it (write() empties the FIFOs) */
		if (b->active && b->sent && (int)(b->count_rd & 0x1F) >= b->num_echo)
			call(b, &b->read_fn, &b->read_data);
		b->sent = 0;
	}
}

void hm2_bspi_write(struct hostmot2 *hm2)
{
	rtapi_u32 zero = 0;
	int i, k;

	for (i = 0; i < hm2->bspi.num; i++) {
		struct hm2_bspi_inst *b = &hm2->bspi.inst[i];
		rtapi_u32 fifo = hm2_md_addr(hm2->bspi.md, REG_FIFO, i);

		if (b->cd_dirty)
			write_descriptors(hm2, i);
		if (b->active)		/* late replies of a short cycle would misalign the next */
			hm2_write_now(hm2, hm2_md_addr(hm2->bspi.md, REG_COUNT, i), &zero, 4);
		for (k = 0; k < b->num_pending; k++)
			hm2_write_now(hm2, fifo + 4 * b->pending_chan[k], &b->pending[k], 4);
		b->num_pending = 0;
		if (!b->active)
			continue;
		call(b, &b->write_fn, &b->write_data);
		for (k = 0; k < b->num_frames; k++)
			hm2_write_now(hm2, fifo + 4 * b->frame_chan[k], &b->frame_wr[k], 4);
		b->sent = 1;
	}
}

/* ---- the sub-driver API ---- */

int hm2_bspi_setup_chan(const char *name, int chan, int cs, int bits, rtapi_u32 khz, int delay_ns,
			int cpol, int cpha, int noclear, int noecho)
{
	struct hm2_bspi_inst *b = find(name, "hm2_bspi_setup_chan");
	rtapi_u32 clk, div, delay, cd;

	if (!b)
		return -ENODEV;
	if (chan < 0 || chan > 15 || cs < 0 || cs > 15 || bits < 1 || bits > 64 || !khz ||
	    delay_ns < 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hostmot2: %s: channel %d: needs channel 0..15, chip select "
				"0..15, 1..64 bits, a bit rate above 0 and a delay >= 0\n", name, chan);
		return -EINVAL;
	}
	clk = b->hm2->bspi.md->clock_freq;
	div = clk / (2u * khz * 1000u);		/* rate = clk / 2(N + 1), no faster than asked */
	if (div * 2u * khz * 1000u < clk)
		div++;
	div = div ? div - 1 : 0;
	if (div > 255)
		div = 255;
	delay = (rtapi_u32)rtapi_div_u64((rtapi_u64)delay_ns * clk, 1000000000u);
	delay = delay ? (delay - 1 > 15 ? 15 : delay - 1) : 0x10;	/* 0x10: no delay */
	cd = (rtapi_u32)(bits - 1) | (cpol ? 1u << 6 : 0) | (cpha ? 1u << 7 : 0) | div << 8 |
	     (rtapi_u32)cs << 16 | delay << 24 | (noclear ? 1u << 30 : 0) | (noecho ? 1u << 31 : 0);
	b->cd[chan] = cd;
	b->cd_dirty = 1;
	HM2_INFO(b->hm2, "%s: channel %d: chip select %d, %d bits, %u kHz", name, chan, cs, bits,
		 clk / (2u * (div + 1)) / 1000u);
	return 0;
}
EXPORT_SYMBOL(hm2_bspi_setup_chan);

int hm2_bspi_write_chan(const char *name, int chan, rtapi_u32 val)
{
	struct hm2_bspi_inst *b = find(name, "hm2_bspi_write_chan");

	if (!b)
		return -ENODEV;
	if (chan < 0 || chan > 15 || b->num_pending >= 16) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hostmot2: %s: write to channel %d refused (channels "
				"0..15, at most 16 words per cycle)\n", name, chan);
		return -EINVAL;
	}
	b->pending[b->num_pending] = val;
	b->pending_chan[b->num_pending] = chan;
	hm2_mb();
	b->num_pending++;
	return 0;
}
EXPORT_SYMBOL(hm2_bspi_write_chan);

int hm2_tram_add_bspi_frame(const char *name, int chan, rtapi_u32 **wbuf, rtapi_u32 **rbuf)
{
	struct hm2_bspi_inst *b = find(name, "hm2_tram_add_bspi_frame");

	if (!b)
		return -ENODEV;
	if (b->active) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hostmot2: %s: frames are already running; "
				"hm2_bspi_release() first\n", name);
		return -EBUSY;
	}
	if (chan < 0 || chan > 15 || b->num_frames >= HM2_BSPI_FRAMES || !wbuf || !rbuf) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hostmot2: %s: frame on channel %d refused (channels "
				"0..15, at most %d frames)\n", name, chan, HM2_BSPI_FRAMES);
		return -EINVAL;
	}
	b->frame_chan[b->num_frames] = chan;
	b->frame_echo[b->num_frames] = !(b->cd[chan] & 0x80000000u);	/* set up the channel first */
	b->num_echo += b->frame_echo[b->num_frames];
	b->frame_wr[b->num_frames] = 0;
	b->frame_rd[b->num_frames] = 0;
	*wbuf = &b->frame_wr[b->num_frames];
	*rbuf = &b->frame_rd[b->num_frames];
	b->num_frames++;
	return 0;
}
EXPORT_SYMBOL(hm2_tram_add_bspi_frame);

int hm2_allocate_bspi_tram(const char *name)
{
	struct hm2_bspi_inst *b = find(name, "hm2_allocate_bspi_tram");

	if (!b)
		return -ENODEV;
	hm2_mb();
	b->active = 1;		/* the frames' words exist already: start sending them */
	return 0;
}
EXPORT_SYMBOL(hm2_allocate_bspi_tram);

int hm2_bspi_set_read_function(const char *name, int (*func)(void *subdata), void *subdata)
{
	struct hm2_bspi_inst *b = find(name, "hm2_bspi_set_read_function");

	if (!b)
		return -ENODEV;
	b->read_fn = 0;
	hm2_mb();
	b->read_data = subdata;
	hm2_mb();
	b->read_fn = func;
	return 0;
}
EXPORT_SYMBOL(hm2_bspi_set_read_function);

int hm2_bspi_set_write_function(const char *name, int (*func)(void *subdata), void *subdata)
{
	struct hm2_bspi_inst *b = find(name, "hm2_bspi_set_write_function");

	if (!b)
		return -ENODEV;
	b->write_fn = 0;
	hm2_mb();
	b->write_data = subdata;
	hm2_mb();
	b->write_fn = func;
	return 0;
}
EXPORT_SYMBOL(hm2_bspi_set_write_function);

/* Silent when the board is gone already (it may unload before its sub-driver). */
int hm2_bspi_release(const char *name)
{
	struct hm2_bspi_inst *b = 0;
	int i, waits;

	for (i = 0; i < MAX_NAMED; i++)
		if (named[i] && name && strcmp(named[i]->name, name) == 0)
			b = named[i];
	if (!b)
		return 0;
	b->active = 0;
	b->read_fn = 0;
	b->write_fn = 0;
	hm2_mb();
	for (waits = 0; b->in_callback && waits < 100000; waits++)
		rtapi_delay(10000);	/* a callback in progress finishes within a cycle */
	b->num_frames = b->num_echo = 0;
	b->read_data = b->write_data = 0;
	return 0;
}
EXPORT_SYMBOL(hm2_bspi_release);

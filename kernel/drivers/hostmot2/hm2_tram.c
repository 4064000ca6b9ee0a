/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_tram.c - the per-cycle register list ("TRAM", a software list; the firmware's
 * translation RAM is never used) and the core's own transfers. Modules register
 * (address, size, pointer) at parse time; one contiguous read buffer and one write
 * buffer are then allocated and every module's pointer aimed at its slice. Each
 * cycle the whole read list is queued as one batch, and likewise the write list.
 * A transport failure sets io_error and needs_reset once, with one message. */
#include "rtapi.h"
#include "rtapi_string.h"
#include "hal.h"
#include "hm2.h"

void hm2_msg(const struct hm2_llio *llio, int level, const char *fmt, ...)
{
	char buf[200];
	va_list ap;

	va_start(ap, fmt);
	rtapi_vsnprintf(buf, sizeof(buf), fmt, ap);
	va_end(ap);
	rtapi_print_msg(level, "%s: %s\n", llio->name, buf);
}

static int add(struct hostmot2 *hm2, struct hm2_tram_entry *list, int *num, int *bytes,
	       rtapi_u32 addr, int size, rtapi_u32 **buf)
{
	if (*num >= HM2_TRAM_MAX) {
		HM2_ERR(hm2, "too many per-cycle register blocks (at most %d)", HM2_TRAM_MAX);
		return -ENOMEM;
	}
	list[*num].addr = addr;
	list[*num].size = size;
	list[*num].buf = buf;
	(*num)++;
	*bytes += size;
	return 0;
}

int hm2_tram_add_read(struct hostmot2 *hm2, rtapi_u32 addr, int size, rtapi_u32 **buf)
{
	return add(hm2, hm2->tram.rd, &hm2->tram.num_rd, &hm2->tram.rd_bytes, addr, size, buf);
}

int hm2_tram_add_write(struct hostmot2 *hm2, rtapi_u32 addr, int size, rtapi_u32 **buf)
{
	return add(hm2, hm2->tram.wr, &hm2->tram.num_wr, &hm2->tram.wr_bytes, addr, size, buf);
}

/* Called once after every module has registered. */
int hm2_tram_allocate(struct hostmot2 *hm2)
{
	struct hm2_tram *t = &hm2->tram;
	int i, off;

	t->rd_buf = hal_malloc(t->rd_bytes + 8);
	t->wr_buf = hal_malloc(t->wr_bytes + 8);
	if (!t->rd_buf || !t->wr_buf) {
		HM2_ERR(hm2, "out of HAL memory for the register buffers");
		return -ENOMEM;
	}
	for (i = 0, off = 0; i < t->num_rd; off += t->rd[i].size / 4, i++)
		*t->rd[i].buf = t->rd_buf + off;
	for (i = 0, off = 0; i < t->num_wr; off += t->wr[i].size / 4, i++)
		*t->wr[i].buf = t->wr_buf + off;
	return 0;
}

/* addr is meaningless for a batch (queued != 0) */
static void io_failed(struct hostmot2 *hm2, const char *what, rtapi_u32 addr, int rc)
{
	int queued = what[0] == 'q';

	if (!hm2->io_error && !queued)
		HM2_ERR(hm2, "%s at 0x%04X failed (%d): stopping; clear %s.io_error to resume",
			what, addr, rc, hm2->llio->name);
	else if (!hm2->io_error)
		HM2_ERR(hm2, "%s failed (%d): stopping; clear %s.io_error to resume", what, rc,
			hm2->llio->name);
	hm2->io_error = 1;
	hm2->llio->needs_reset = 1;
}

int hm2_read_now(struct hostmot2 *hm2, rtapi_u32 addr, void *buf, int size)
{
	int rc = hm2->llio->read(hm2->llio, addr, buf, size);

	if (rc < 0)
		io_failed(hm2, "read", addr, rc);
	return rc;
}

/* Batched when the board batches: flushed by hm2_tram_flush_writes(). */
int hm2_write_now(struct hostmot2 *hm2, rtapi_u32 addr, const void *buf, int size)
{
	struct hm2_llio *llio = hm2->llio;
	int rc = llio->queue_write ? llio->queue_write(llio, addr, buf, size)
				   : llio->write(llio, addr, buf, size);

	if (rc < 0)
		io_failed(hm2, "write", addr, rc);
	return rc;
}

int hm2_tram_flush_writes(struct hostmot2 *hm2)
{
	struct hm2_llio *llio = hm2->llio;
	int rc;

	if (!llio->send_queued_writes)
		return 0;
	rc = llio->send_queued_writes(llio);
	if (rc < 0)
		io_failed(hm2, "queued write", 0, rc);
	return rc;
}

/* A read that goes with the per-cycle ones (BSPI replies): queued when batching. */
int hm2_tram_extra_read(struct hostmot2 *hm2, rtapi_u32 addr, void *buf, int size)
{
	struct hm2_llio *llio = hm2->llio;

	return llio->queue_read ? llio->queue_read(llio, addr, buf, size)
				: hm2_read_now(hm2, addr, buf, size);
}

/* Queue (or do) every per-cycle read, the raw-mode read and the BSPI replies, and
 * send them. */
int hm2_tram_request_reads(struct hostmot2 *hm2)
{
	struct hm2_llio *llio = hm2->llio;
	struct hm2_tram *t = &hm2->tram;
	int i, rc = 0;

	if (!llio->queue_read) {
		for (i = 0; i < t->num_rd && rc >= 0; i++)
			rc = hm2_read_now(hm2, t->rd[i].addr, *t->rd[i].buf, t->rd[i].size);
		if (rc >= 0 && hm2->raw.on)
			rc = hm2_read_now(hm2, *hm2->raw.read_address & 0xFFFF, &hm2->raw.rd_word, 4);
		if (rc >= 0)
			rc = hm2_bspi_request_reads(hm2);
		return rc < 0 ? rc : 0;
	}
	for (i = 0; i < t->num_rd && rc >= 0; i++)
		rc = llio->queue_read(llio, t->rd[i].addr, *t->rd[i].buf, t->rd[i].size);
	if (rc >= 0 && hm2->raw.on)
		rc = llio->queue_read(llio, *hm2->raw.read_address & 0xFFFF, &hm2->raw.rd_word, 4);
	if (rc >= 0)
		rc = hm2_bspi_request_reads(hm2);
	if (rc >= 0)
		rc = llio->send_queued_reads(llio);
	if (rc < 0) {
		io_failed(hm2, "queued read", 0, rc);
		return rc;
	}
	return 0;
}

/* 0 when the data is in the buffers, -EAGAIN to skip this cycle, else an error. */
int hm2_tram_receive_reads(struct hostmot2 *hm2)
{
	struct hm2_llio *llio = hm2->llio;
	int rc;

	if (!llio->receive_queued_reads)
		return 0;
	rc = llio->receive_queued_reads(llio);
	if (rc == -EAGAIN)
		return rc;
	if (rc < 0)
		io_failed(hm2, "queued read", 0, rc);
	return rc < 0 ? rc : 0;
}

int hm2_tram_write(struct hostmot2 *hm2)
{
	struct hm2_tram *t = &hm2->tram;
	int i, rc = 0;

	for (i = 0; i < t->num_wr && rc >= 0; i++)
		rc = hm2_write_now(hm2, t->wr[i].addr, *t->wr[i].buf, t->wr[i].size);
	return rc < 0 ? rc : 0;
}

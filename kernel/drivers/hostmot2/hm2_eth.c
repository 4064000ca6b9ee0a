/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_eth.c - board driver for Mesa's Ethernet cards (7i76E, 7i92, 7i96, ...): the
 * HostMot2 registers over LBP16 in UDP datagrams (hm2_lbp16.h). Simulated flavor
 * only; in the kernel flavor it refuses to load (hm2_eth_net.c says why).
 *   loadrt hostmot2
 *   loadrt hm2_eth board_ip=192.168.1.121 config="num_encoders=1"
 * board_ip= and config= are comma-separated arrays, one entry per board (up to 4).
 * board_ip may carry a port (a.b.c.d:port) for a simulator (hm2-eth-sim); cards
 * listen on 27181. The HAL prefix is hm2_<card>.N, the card's name as it reports it
 * (space 7), lower-cased: hm2_7i92.0.
 *
 * Per servo cycle (hm2-transports notes 3.5): read-request sends one datagram with
 * every per-cycle read plus a sequence number written to and read back from the
 * card's scratch registers; read waits for the reply until packet-read-timeout;
 * write sends one datagram with every write plus its own sequence number. A lost,
 * late, short or out-of-sequence reply is a packet error: that cycle's read is
 * skipped, packet-error-level rises by packet-error-increment (falls by
 * packet-error-decrement per good cycle) and at packet-error-limit io_error is set.
 * Before the thread runs (registration) every transfer is synchronous with a 200 ms
 * timeout, and any failure refuses the load. On unload hostmot2 makes the card's
 * watchdog bite at once. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "hal.h"
#include "hm2_llio.h"
#include "hm2_lbp16.h"
#include "hm2_boards.h"
#include "hm2_eth_net.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("Mesa HostMot2 Ethernet cards (LBP16 over UDP) for hostmot2");

#define MAX_BOARDS 4
#define MAX_QUEUED_READS 64
#define SYNC_TIMEOUT_NS 200000000LL	/* transfers outside the realtime thread */
#define MIN_READ_TIMEOUT_NS 100000LL
#define REPLY_TRAILER 10		/* rx count (2) + read_cnt and write_cnt echo (8) */
#define REQUEST_TRAILER 16		/* the three bookkeeping commands */
#define WRITE_TRAILER 8			/* write_cnt */

/* fixed HostMot2 locations (hostmot2 notes 1, 2) */
#define ADDR_COOKIE 0x0100
#define ADDR_IDROM_OFFSET 0x010C
#define HM2_COOKIE 0x55AACAFEu

static char *board_ip[MAX_BOARDS];
RTAPI_MP_ARRAY_STRING(board_ip, MAX_BOARDS, "IP address of each card (a.b.c.d[:port])");
static char *config[MAX_BOARDS];
RTAPI_MP_ARRAY_STRING(config, MAX_BOARDS, "hostmot2 config string of each card");
static int debug;
RTAPI_MP_INT(debug, "log every packet error");

struct queued_read {
	void *buf;
	int size;
};

struct eth_board {
	struct hm2_llio llio;
	int sock;
	char where[24];			/* "192.168.1.121" or "127.0.0.1:40000", for messages */
	char card[17];			/* the name the card reports */
	char hal_name[17];		/* "7i92": HAL prefix hm2_7i92.N */
	char connector_names[HM2_LLIO_MAX_CONNECTORS][4];
	int registered;			/* 0: synchronous transfers, failures refuse the load */

	/* the read request being built or awaiting its reply */
	struct queued_read rq[MAX_QUEUED_READS];
	int num_rq, rq_len, reply_len, pending;
	rtapi_u8 rq_pkt[LBP16_MAX_PACKET];
	rtapi_u8 reply[LBP16_MAX_PACKET];
	rtapi_u32 read_cnt, write_cnt;
	long long request_ns, period_ns;	/* period: measured between requests */
	/* synchronous transfers */
	rtapi_u8 sync_pkt[LBP16_MAX_PACKET], sync_data[1024];
	/* the write datagram being built */
	rtapi_u8 wq_pkt[LBP16_MAX_PACKET];
	int wq_len;

	/* HAL: <board>.packet-* */
	hal_s32_t read_timeout, error_limit, error_increment, error_decrement;
	hal_bit_t *packet_error, *error_exceeded;
	hal_u32_t *error_total;
	hal_s32_t *error_level;
};

static int comp_id;
static struct eth_board *boards;
static int num_boards;

/* ---- packet errors ---- */

static void packet_error(struct eth_board *b, const char *what, int v1, int v2)
{
	*b->packet_error = 1;
	(*b->error_total)++;
	*b->error_level += b->error_increment;
	if (debug)
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: packet error: %s (%d, %d)\n", b->llio.name, what, v1, v2);
	if (*b->error_level >= b->error_limit && !*b->error_exceeded) {
		*b->error_exceeded = 1;
		*b->llio.io_error = 1;
		b->llio.needs_reset = 1;
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: packet-error-level %d reached packet-error-limit %d "
				"(last: %s): stopping; clear %s.io_error to resume\n", b->llio.name,
				*b->error_level, b->error_limit, what, b->llio.name);
	}
}

static void packet_good(struct eth_board *b)
{
	*b->packet_error = 0;
	*b->error_level -= b->error_decrement;
	if (*b->error_level < 0)
		*b->error_level = 0;
}

/* packet-read-timeout: below 100 a percentage of the thread period, else ns */
static long long read_timeout_ns(struct eth_board *b)
{
	long long t;

	if (!b->registered)
		return SYNC_TIMEOUT_NS;
	if (b->read_timeout >= 100)
		t = b->read_timeout;
	else
		t = (b->period_ns ? b->period_ns : 1000000) * (b->read_timeout > 0 ? b->read_timeout : 80) / 100;
	return t < MIN_READ_TIMEOUT_NS ? MIN_READ_TIMEOUT_NS : t;
}

/* ---- synchronous transfers (registration, unload) ---- */

static void drain(struct eth_board *b)
{
	while (hm2_eth_net_recv(b->sock, b->reply, sizeof(b->reply), 0) >= 0)
		;
}

/* Sends pkt and waits for a reply of exactly expect bytes (none if 0). */
static int transact(struct eth_board *b, const rtapi_u8 *pkt, int len, void *reply, int expect)
{
	int rc, n;

	drain(b);
	rc = hm2_eth_net_send(b->sock, pkt, len);
	if (rc < 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: board %s: cannot send (%d)\n", b->where, rc);
		return rc;
	}
	if (!expect)
		return 0;
	n = hm2_eth_net_recv(b->sock, b->reply, sizeof(b->reply), rtapi_get_time() + SYNC_TIMEOUT_NS);
	if (n == -ETIMEDOUT || n == -ECONNREFUSED) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: board %s: no answer within %lld ms (UDP timeout%s): "
				"is the card powered, connected, and at this address?\n", b->where,
				SYNC_TIMEOUT_NS / 1000000, n == -ECONNREFUSED ? ", port unreachable" : "");
		return -ETIMEDOUT;
	}
	if (n < 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: board %s: receive failed (%d)\n", b->where, n);
		return n;
	}
	if (n != expect) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: board %s: wrong LBP16 reply: %d bytes, expected %d "
				"(not an LBP16 card, or another program talks to it)\n", b->where, n, expect);
		return -EPROTO;
	}
	memcpy(reply, b->reply, n);
	return 0;
}

/* Appends the read commands of [addr, addr + size) (size in bytes, whole words). */
static int append_reads(rtapi_u8 *pkt, int len, int cap, rtapi_u32 addr, int size)
{
	while (size > 0 && len >= 0) {
		int n = size / 4 > LBP16_MAX_COUNT ? LBP16_MAX_COUNT : size / 4;

		len = lbp16_append(pkt, len, cap, LBP16_CMD_READ_HM2(n), (rtapi_u16)addr, 0, 0);
		addr += 4 * n;
		size -= 4 * n;
	}
	return len;
}

static int append_writes(rtapi_u8 *pkt, int len, int cap, rtapi_u32 addr, const rtapi_u8 *data,
			 int size)
{
	while (size > 0 && len >= 0) {
		int n = size / 4 > LBP16_MAX_COUNT ? LBP16_MAX_COUNT : size / 4;

		len = lbp16_append(pkt, len, cap, LBP16_CMD_WRITE_HM2(n), (rtapi_u16)addr, data, 4 * n);
		addr += 4 * n;
		data += 4 * n;
		size -= 4 * n;
	}
	return len;
}

static int check(rtapi_u32 addr, int size)
{
	return (size <= 0 || (size & 3) || (addr & 3) || addr + size > 0x10000) ? -EINVAL : 0;
}

/* little-endian on the wire, host order in buf */
static void words_from_wire(void *buf, const rtapi_u8 *wire, int size)
{
	rtapi_u32 *w = buf;
	int i;

	for (i = 0; i < size / 4; i++)
		w[i] = lbp16_get32(wire + 4 * i);
}

static int eth_read(struct hm2_llio *llio, rtapi_u32 addr, void *buf, int size)
{
	struct eth_board *b = llio->priv;
	rtapi_u8 pkt[64];
	int rc = check(addr, size);

	while (!rc && size > 0) {
		int chunk = size > 1024 ? 1024 : size, len;

		len = append_reads(pkt, 0, sizeof(pkt), addr, chunk);
		rc = len < 0 ? len : transact(b, pkt, len, b->sync_data, chunk);
		if (!rc)
			words_from_wire(buf, b->sync_data, chunk);
		buf = (rtapi_u8 *)buf + chunk;
		addr += chunk;
		size -= chunk;
	}
	if (rc && b->registered && llio->io_error) {
		*llio->io_error = 1;
		llio->needs_reset = 1;
	}
	return rc;
}

static int eth_write(struct hm2_llio *llio, rtapi_u32 addr, const void *buf, int size)
{
	struct eth_board *b = llio->priv;
	const rtapi_u32 *w = buf;
	int rc = check(addr, size);

	while (!rc && size > 0) {
		int chunk = size > 1024 ? 1024 : size, i, len;

		for (i = 0; i < chunk / 4; i++)
			lbp16_put32(b->sync_data + 4 * i, w[i]);
		len = append_writes(b->sync_pkt, 0, LBP16_MAX_PACKET, addr, b->sync_data, chunk);
		rc = len < 0 ? len : transact(b, b->sync_pkt, len, 0, 0);
		w += chunk / 4;
		addr += chunk;
		size -= chunk;
	}
	return rc;
}

/* ---- queued reads: read-request and read ---- */

static int eth_queue_read(struct hm2_llio *llio, rtapi_u32 addr, void *buf, int size)
{
	struct eth_board *b = llio->priv;
	int len;

	if (b->pending) {		/* a request whose reply nobody waited for */
		b->pending = 0;
		b->num_rq = b->rq_len = b->reply_len = 0;
	}
	if (check(addr, size) || b->num_rq >= MAX_QUEUED_READS ||
	    b->reply_len + size + REPLY_TRAILER > LBP16_MAX_PACKET)
		return -ENOSPC;
	len = append_reads(b->rq_pkt, b->rq_len, LBP16_MAX_PACKET - REQUEST_TRAILER, addr, size);
	if (len < 0)
		return len;
	b->rq_len = len;
	b->rq[b->num_rq].buf = buf;
	b->rq[b->num_rq].size = size;
	b->num_rq++;
	b->reply_len += size;
	return 0;
}

static int eth_send_queued_reads(struct hm2_llio *llio)
{
	struct eth_board *b = llio->priv;
	rtapi_u8 cnt[4];
	long long now = rtapi_get_time();
	int len = b->rq_len, rc;

	if (*b->error_exceeded && !*llio->io_error) {	/* the user cleared io_error */
		*b->error_exceeded = 0;
		*b->error_level = 0;
	}
	lbp16_put32(cnt, ++b->read_cnt);
	len = lbp16_append(b->rq_pkt, len, LBP16_MAX_PACKET, LBP16_CMD_READ_RXCOUNT,
			   LBP16_STATUS_RXCOUNT, 0, 0);
	len = lbp16_append(b->rq_pkt, len, LBP16_MAX_PACKET, LBP16_CMD_WRITE_SCRATCH,
			   LBP16_SCRATCH_READ_CNT, cnt, 4);
	len = lbp16_append(b->rq_pkt, len, LBP16_MAX_PACKET, LBP16_CMD_READ_SCRATCH,
			   LBP16_SCRATCH_READ_CNT, 0, 0);
	if (len < 0)
		return len;	/* cannot happen: REQUEST_TRAILER bytes were kept free */
	if (b->request_ns && now - b->request_ns < 1000000000LL)
		b->period_ns = now - b->request_ns;
	b->request_ns = now;
	if (!b->registered)
		drain(b);
	rc = hm2_eth_net_send(b->sock, b->rq_pkt, len);
	b->rq_len = 0;
	if (rc < 0) {
		b->num_rq = b->reply_len = 0;
		if (!b->registered) {
			rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: board %s: cannot send (%d)\n", b->where, rc);
			return rc;
		}
		packet_error(b, "send failed", rc, 0);
		b->pending = 0;
		return 0;	/* read() will find nothing pending and skip the cycle */
	}
	b->pending = 1;
	return 0;
}

static int eth_receive_queued_reads(struct hm2_llio *llio)
{
	struct eth_board *b = llio->priv;
	int expect = b->reply_len + REPLY_TRAILER, n, i, off;
	long long deadline = b->request_ns + read_timeout_ns(b);
	rtapi_u32 echo_read, echo_write = 0;

	if (!b->pending)
		return -EAGAIN;
	b->pending = 0;
	for (;;) {
		n = hm2_eth_net_recv(b->sock, b->reply, sizeof(b->reply), deadline);
		if (n < 0)
			break;
		if (n != expect)
			break;
		echo_read = lbp16_get32(b->reply + expect - 8);
		if (echo_read == b->read_cnt)
			break;
		if ((rtapi_s32)(echo_read - b->read_cnt) > 0) {
			n = -EPROTO;	/* an answer to a request never sent */
			break;
		}
		/* a late answer to an earlier request: wait on for ours */
	}
	if (n == expect) {	/* ours: every queued read gets its words */
		for (i = 0, off = 0; i < b->num_rq; off += b->rq[i].size, i++)
			words_from_wire(b->rq[i].buf, b->reply + off, b->rq[i].size);
		echo_write = lbp16_get32(b->reply + expect - 4);
	}
	b->num_rq = b->reply_len = 0;
	if (!b->registered) {
		if (n == -ETIMEDOUT || n == -ECONNREFUSED)
			rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: board %s: no answer to the first read "
					"within %lld ms (UDP timeout)\n", b->where, SYNC_TIMEOUT_NS / 1000000);
		else if (n < 0)
			rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: board %s: wrong LBP16 reply to the first "
					"read (%d)\n", b->where, n);
		else if (n != expect)
			rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: board %s: wrong LBP16 reply: %d bytes, "
					"expected %d\n", b->where, n, expect);
		return n < 0 ? -EIO : n != expect ? -EPROTO : 0;
	}
	if (n != expect) {
		packet_error(b, n == -ETIMEDOUT ? "no reply within packet-read-timeout" :
			     n < 0 ? "receive failed or out-of-sequence reply" : "reply of the wrong length",
			     n, expect);
		return -EAGAIN;
	}
	if (echo_write != b->write_cnt)
		packet_error(b, "the card missed a write datagram", (int)echo_write, (int)b->write_cnt);
	else
		packet_good(b);
	return 0;
}

/* ---- queued writes: one datagram per write() ---- */

static int eth_send_queued_writes(struct hm2_llio *llio)
{
	struct eth_board *b = llio->priv;
	rtapi_u8 cnt[4];
	int len, rc;

	if (!b->wq_len)
		return 0;
	lbp16_put32(cnt, ++b->write_cnt);
	len = lbp16_append(b->wq_pkt, b->wq_len, LBP16_MAX_PACKET, LBP16_CMD_WRITE_SCRATCH,
			   LBP16_SCRATCH_WRITE_CNT, cnt, 4);
	b->wq_len = 0;
	if (len < 0)
		return len;	/* cannot happen: WRITE_TRAILER bytes were kept free */
	rc = hm2_eth_net_send(b->sock, b->wq_pkt, len);
	if (rc < 0) {
		if (!b->registered) {
			rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: board %s: cannot send (%d)\n", b->where, rc);
			return rc;
		}
		packet_error(b, "send failed", rc, 0);
	}
	return 0;
}

static int eth_queue_write(struct hm2_llio *llio, rtapi_u32 addr, const void *buf, int size)
{
	struct eth_board *b = llio->priv;
	const rtapi_u32 *w = buf;
	rtapi_u8 data[4 * LBP16_MAX_COUNT];
	int rc = check(addr, size);

	while (!rc && size > 0) {
		int n = size / 4 > LBP16_MAX_COUNT ? LBP16_MAX_COUNT : size / 4, i, len;

		for (i = 0; i < n; i++)
			lbp16_put32(data + 4 * i, w[i]);
		len = lbp16_append(b->wq_pkt, b->wq_len, LBP16_MAX_PACKET - WRITE_TRAILER,
				   LBP16_CMD_WRITE_HM2(n), (rtapi_u16)addr, data, 4 * n);
		if (len < 0) {		/* full: this datagram goes out now */
			if (!b->wq_len)
				return -ENOSPC;
			rc = eth_send_queued_writes(llio);
			continue;
		}
		b->wq_len = len;
		w += n;
		addr += 4 * n;
		size -= 4 * n;
	}
	return rc;
}

/* ---- setup ---- */

/* "a.b.c.d" or "a.b.c.d:port" */
static int parse_where(const char *s, char *ip, int iplen, int *port)
{
	const char *colon = strchr(s, ':');
	char *end;
	long p;

	*port = LBP16_UDP_PORT;
	if (!colon) {
		rtapi_strlcpy(ip, s, iplen);
		return 0;
	}
	if (colon - s >= iplen)
		return -EINVAL;
	memcpy(ip, s, colon - s);
	ip[colon - s] = 0;
	p = rtapi_strtol(colon + 1, &end, 10);
	if (*end || end == colon + 1 || p < 1 || p > 65535)
		return -EINVAL;
	*port = (int)p;
	return 0;
}

/* The HAL name of a card: its reported name up to '-', lower-cased, with the card
 * families' suffixes dropped ("7I80DB-16" -> 7i80, "7I76EU" -> 7i76e, "7I92T" -> 7i92). */
static void hal_board_name(const char *card, char *out, int outlen)
{
	static const char *const families[] = { "7I76E", "7I80", "7I92", "7I93", "7I94", "7I95",
						"7I96", "7I97", "7I98", "MC04" };
	unsigned k;
	int i;

	for (k = 0; k < sizeof(families) / sizeof(families[0]); k++) {
		if (strncmp(card, families[k], strlen(families[k])) == 0) {
			card = families[k];
			break;
		}
	}
	for (i = 0; i < outlen - 1 && card[i] && card[i] != '-' && card[i] != ' '; i++)
		out[i] = (card[i] >= 'A' && card[i] <= 'Z') ? card[i] - 'A' + 'a' : card[i];
	out[i] = 0;
}

static int identify(struct eth_board *b, char *hal_name, int hal_len)
{
	rtapi_u8 pkt[8], name[16], w[4];
	rtapi_u32 idrom, ports, width;
	const struct hm2_board_info *info;
	int i, len, rc;

	len = lbp16_append(pkt, 0, sizeof(pkt), LBP16_CMD_READ_NAME, 0, 0, 0);
	rc = transact(b, pkt, len, name, 16);
	if (rc)
		return rc;
	for (i = 0; i < 16 && name[i] >= ' ' && name[i] < 127; i++)
		b->card[i] = (char)name[i];
	b->card[i] = 0;
	if (!b->card[0]) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: board %s: the card reports no name (space 7)\n",
				b->where);
		return -EPROTO;
	}
	hal_board_name(b->card, hal_name, hal_len);
	rc = eth_read(&b->llio, ADDR_COOKIE, w, 4);
	if (rc)
		return rc;
	if (*(rtapi_u32 *)w != HM2_COOKIE) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: board %s: card '%s' answers, but its HostMot2 "
				"cookie at 0x%04X is 0x%08X, expected 0x%08X (no HostMot2 firmware?)\n",
				b->where, b->card, ADDR_COOKIE, *(rtapi_u32 *)w, HM2_COOKIE);
		return -EINVAL;
	}
	rc = eth_read(&b->llio, ADDR_IDROM_OFFSET, &idrom, 4);
	if (!rc)
		rc = eth_read(&b->llio, (idrom & 0xFFFC) + 0x1C, &ports, 4);
	if (!rc)
		rc = eth_read(&b->llio, (idrom & 0xFFFC) + 0x24, &width, 4);
	if (rc)
		return rc;
	if (ports < 1 || ports > HM2_LLIO_MAX_CONNECTORS) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: board %s: IDROM IOPorts is %u, expected 1..%d\n",
				b->where, ports, HM2_LLIO_MAX_CONNECTORS);
		return -EINVAL;
	}
	/* connectors: this driver's table for a known name, else the IDROM's numbers */
	info = hm2_board_find(hal_name);
	b->llio.num_ioport_connectors = (int)ports;
	b->llio.pins_per_connector = (int)width;
	b->llio.num_leds = info ? info->leds : 0;
	for (i = 0; i < (int)ports; i++) {
		if (info && i < info->connectors)
			b->llio.ioport_connector_name[i] = info->connector[i];
		else {
			rtapi_snprintf(b->connector_names[i], sizeof(b->connector_names[i]), "P%d", i + 1);
			b->llio.ioport_connector_name[i] = b->connector_names[i];
		}
	}
	return 0;
}

static int export_board(struct eth_board *b)
{
	const char *n = b->llio.name;
	int rc;

	b->read_timeout = 80;
	b->error_limit = 10;
	b->error_increment = 2;
	b->error_decrement = 1;
	rc = hal_param_s32_newf(HAL_RW, &b->read_timeout, comp_id, "%s.packet-read-timeout", n);
	if (!rc)
		rc = hal_param_s32_newf(HAL_RW, &b->error_limit, comp_id, "%s.packet-error-limit", n);
	if (!rc)
		rc = hal_param_s32_newf(HAL_RW, &b->error_increment, comp_id, "%s.packet-error-increment", n);
	if (!rc)
		rc = hal_param_s32_newf(HAL_RW, &b->error_decrement, comp_id, "%s.packet-error-decrement", n);
	if (!rc)
		rc = hal_pin_bit_newf(HAL_OUT, &b->packet_error, comp_id, "%s.packet-error", n);
	if (!rc)
		rc = hal_pin_u32_newf(HAL_OUT, &b->error_total, comp_id, "%s.packet-error-total", n);
	if (!rc)
		rc = hal_pin_s32_newf(HAL_OUT, &b->error_level, comp_id, "%s.packet-error-level", n);
	if (!rc)
		rc = hal_pin_bit_newf(HAL_OUT, &b->error_exceeded, comp_id, "%s.packet-error-exceeded", n);
	return rc;
}

/* board k: board_ip[k], config[k] */
static int setup_board(int k)
{
	struct eth_board *b = &boards[k];
	const char *where = board_ip[k], *cfg = config[k];
	char ip[20], hal_name[17];
	int port, same = 0, i, rc;

	b->sock = -1;
	rtapi_strlcpy(b->where, where, sizeof(b->where));
	if (strlen(where) >= sizeof(b->where) || parse_where(where, ip, sizeof(ip), &port)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: board_ip=%s: expected a.b.c.d or a.b.c.d:port\n",
				where);
		return -EINVAL;
	}
	rc = hm2_eth_net_open(ip, port);
	if (rc < 0)
		return rc;
	b->sock = rc;
	b->llio.priv = b;
	rc = identify(b, hal_name, sizeof(hal_name));
	if (rc)
		return rc;
	for (i = 0; i < k; i++)
		if (strcmp(boards[i].hal_name, hal_name) == 0)
			same++;
	rtapi_strlcpy(b->hal_name, hal_name, sizeof(b->hal_name));
	rtapi_snprintf(b->llio.name, sizeof(b->llio.name), "hm2_%s.%d", hal_name, same);
	b->llio.comp_id = comp_id;
	b->llio.threadsafe = 0;
	b->llio.split_read = 1;
	b->llio.read = eth_read;
	b->llio.write = eth_write;
	b->llio.queue_read = eth_queue_read;
	b->llio.send_queued_reads = eth_send_queued_reads;
	b->llio.receive_queued_reads = eth_receive_queued_reads;
	b->llio.queue_write = eth_queue_write;
	b->llio.send_queued_writes = eth_send_queued_writes;
	rc = export_board(b);
	if (rc)
		return rc;
	rtapi_print_msg(RTAPI_MSG_INFO, "hm2_eth: board %s is a %s, registered as %s\n", where, b->card,
			b->llio.name);
	rc = hm2_register(&b->llio, cfg);
	if (rc)
		return rc;
	b->registered = 1;
	b->request_ns = b->period_ns = 0;	/* the thread's period is measured afresh */
	return 0;
}

static void close_boards(void)
{
	int k;

	for (k = 0; k < num_boards; k++) {
		struct eth_board *b = &boards[k];

		if (b->registered) {
			b->registered = 0;	/* synchronous again: the bite goes out now */
			hm2_unregister(&b->llio);
		}
		if (b->sock >= 0)
			hm2_eth_net_close(b->sock);
		b->sock = -1;
	}
}

int rtapi_app_main(void)
{
	void *mem;
	int k;

	for (num_boards = 0; num_boards < MAX_BOARDS && board_ip[num_boards] && *board_ip[num_boards];)
		num_boards++;
	if (!num_boards) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: board_ip= is required (the card's address, "
				"e.g. board_ip=192.168.1.121)\n");
		return -EINVAL;
	}
	comp_id = hm2_llio_init_boards("hm2_eth", "board_ip", config, MAX_BOARDS, num_boards,
				       sizeof(*boards), &mem);
	if (comp_id < 0)
		return comp_id;
	boards = mem;
	for (k = 0; k < num_boards; k++)
		boards[k].sock = -1;
	return hm2_llio_setup_boards(comp_id, num_boards, setup_board, close_boards);
}

void rtapi_app_exit(void)
{
	close_boards();
	hal_exit(comp_id);
}

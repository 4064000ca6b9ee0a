/* SPDX-License-Identifier: GPL-2.0-or-later */
/* streamer_fifo.h - the shared-memory FIFO between sampler(9)/streamer(9) and
 * halsampler(1)/halstreamer(1). Pure layout plus index math: included by the
 * realtime components (C) and by the tools (C++), so no libc and no HAL here.
 *
 * One FIFO uses two RTAPI segments of fixed, known sizes, so that both sides
 * always call rtapi_shmem_new() with the same size for the same key:
 *   - the header segment (key = base + N, sizeof(struct hal_fifo_hdr)),
 *   - the record segment (key = base + HAL_FIFO_DATA_KEY_OFFSET + N,
 *     hal_fifo_data_size() bytes, read from the header).
 * The ring is single-producer single-consumer and lock-free: the producer
 * (sampler, halstreamer) alone writes 'in', the consumer (halsampler,
 * streamer) alone writes 'out'. A slot is written only while it is outside
 * [out, in), so its 64-bit values are never read while being written. */
#ifndef STREAMER_FIFO_H
#define STREAMER_FIFO_H

#include "rtapi.h"

#ifdef __cplusplus
extern "C" {
#define HAL_FIFO_STATIC_ASSERT(c, m) static_assert(c, m)
#else
#define HAL_FIFO_STATIC_ASSERT(c, m) _Static_assert(c, m)
#endif

#define HAL_FIFO_MAGIC 0x48464931u		/* "HFI1"; 0 = no FIFO (yet, or any more) */
#define HAL_FIFO_MAX_PINS 20			/* characters in one cfg string */
#define HAL_FIFO_MAX_FIFOS 8			/* cfg=/depth= entries per module */
#define HAL_FIFO_MAX_DEPTH 1000000
#define SAMPLER_SHMEM_KEY 0x48534d00		/* + N: header of sampler FIFO N */
#define STREAMER_SHMEM_KEY 0x48535400		/* + N: header of streamer FIFO N */
#define HAL_FIFO_DATA_KEY_OFFSET 0x80		/* + base + N: records of FIFO N */

/* Words at the start of every record, before the pin values. */
#define HAL_FIFO_REC_SAMPLE 0			/* sampler: sample number (s32) */
#define HAL_FIFO_REC_FLAGS 1			/* sampler: HAL_FIFO_GAP */
#define HAL_FIFO_REC_HDR_WORDS 2
#define HAL_FIFO_GAP 1u				/* samples were dropped before this one */

enum hal_fifo_type {
	HAL_FIFO_BAD = -1,
	HAL_FIFO_FLOAT = 0,
	HAL_FIFO_BIT,
	HAL_FIFO_S32,
	HAL_FIFO_U32,
	HAL_FIFO_S64,
	HAL_FIFO_U64
};

/* One value as stored: floats as doubles, bits as 0/1, s32 sign-extended, s64/u64 as they are. */
union hal_fifo_value {
	rtapi_u64 u;
	rtapi_s64 s;
	double f;
};
HAL_FIFO_STATIC_ASSERT(sizeof(union hal_fifo_value) == 8, "FIFO record layout changed");

/* The header segment. Geometry is written once by the realtime side at init,
 * before 'magic' is published; 'magic' is cleared again when it unloads. */
struct hal_fifo_hdr {
	rtapi_u32 magic;	/* HAL_FIFO_MAGIC while the FIFO is usable */
	rtapi_u32 depth;	/* records the FIFO holds */
	rtapi_u32 slots;	/* depth + 1: one slot stays free to tell full from empty */
	rtapi_u32 num_pins;	/* values per record, = length of cfg */
	rtapi_u32 data_size;	/* bytes of the record segment */
	rtapi_u32 in;		/* next slot to write: written by the producer only */
	rtapi_u32 out;		/* next slot to read: written by the consumer only */
	rtapi_u32 reserved;
	char cfg[HAL_FIFO_MAX_PINS + 4];	/* type characters, NUL-terminated */
	rtapi_u32 pad[2];
};
HAL_FIFO_STATIC_ASSERT(sizeof(struct hal_fifo_hdr) == 64, "FIFO header layout changed");

/* Type of one cfg character (sampler(9): F f B b S s U u; L l for s64 and K k for
 * u64, as LinuxCNC's sampler and streamer take them). */
static inline enum hal_fifo_type hal_fifo_type_of(char c)
{
	switch (c) {
	case 'f': case 'F': return HAL_FIFO_FLOAT;
	case 'b': case 'B': return HAL_FIFO_BIT;
	case 's': case 'S': return HAL_FIFO_S32;
	case 'u': case 'U': return HAL_FIFO_U32;
	case 'l': case 'L': return HAL_FIFO_S64;
	case 'k': case 'K': return HAL_FIFO_U64;
	default: return HAL_FIFO_BAD;
	}
}

/* Number of pins of a cfg string (1..HAL_FIFO_MAX_PINS), or -(1 + index) of
 * the first bad character, or 0 for an empty string, or -(1 + MAX_PINS) when
 * it is too long. */
static inline int hal_fifo_cfg_pins(const char *cfg)
{
	int n;

	for (n = 0; cfg[n]; n++) {
		if (n == HAL_FIFO_MAX_PINS)
			return -(1 + HAL_FIFO_MAX_PINS);
		if (hal_fifo_type_of(cfg[n]) == HAL_FIFO_BAD)
			return -(1 + n);
	}
	return n;
}

static inline rtapi_u32 hal_fifo_rec_words(rtapi_u32 num_pins)
{
	return HAL_FIFO_REC_HDR_WORDS + num_pins;
}

/* Bytes of the record segment; depth <= HAL_FIFO_MAX_DEPTH keeps it below 4 GiB. */
static inline rtapi_u32 hal_fifo_data_size(rtapi_u32 depth, rtapi_u32 num_pins)
{
	return (depth + 1) * hal_fifo_rec_words(num_pins) * (rtapi_u32)sizeof(union hal_fifo_value);
}

static inline rtapi_u32 hal_fifo_next(rtapi_u32 pos, rtapi_u32 slots)
{
	return pos + 1 >= slots ? 0 : pos + 1;
}

/* Records between out and in. */
static inline rtapi_u32 hal_fifo_count(rtapi_u32 in, rtapi_u32 out, rtapi_u32 slots)
{
	return in >= out ? in - out : in + slots - out;
}

/* Fill in the geometry of a new FIFO (realtime init code; magic stays 0). */
static inline void hal_fifo_hdr_init(struct hal_fifo_hdr *h, const char *cfg,
				     rtapi_u32 num_pins, rtapi_u32 depth)
{
	rtapi_u32 i;

	__atomic_store_n(&h->magic, 0, __ATOMIC_RELEASE);
	h->depth = depth;
	h->slots = depth + 1;
	h->num_pins = num_pins;
	h->data_size = hal_fifo_data_size(depth, num_pins);
	h->in = 0;
	h->out = 0;
	h->reserved = 0;
	for (i = 0; i < sizeof(h->cfg); i++)
		h->cfg[i] = i < num_pins ? cfg[i] : 0;
	h->pad[0] = h->pad[1] = 0;
}

static inline void hal_fifo_publish(struct hal_fifo_hdr *h)
{
	__atomic_store_n(&h->magic, HAL_FIFO_MAGIC, __ATOMIC_RELEASE);
}

static inline void hal_fifo_withdraw(struct hal_fifo_hdr *h)
{
	__atomic_store_n(&h->magic, 0, __ATOMIC_RELEASE);
}

static inline int hal_fifo_is_published(const struct hal_fifo_hdr *h)
{
	return __atomic_load_n(&h->magic, __ATOMIC_ACQUIRE) == HAL_FIFO_MAGIC;
}

/* Geometry sanity check for a consumer or producer that did not create the FIFO. */
static inline int hal_fifo_geometry_ok(const struct hal_fifo_hdr *h)
{
	int pins = hal_fifo_cfg_pins(h->cfg);

	return pins > 0 && (rtapi_u32)pins == h->num_pins && h->depth >= 1 &&
	       h->depth <= HAL_FIFO_MAX_DEPTH && h->slots == h->depth + 1 &&
	       h->data_size == hal_fifo_data_size(h->depth, h->num_pins);
}

static inline union hal_fifo_value *hal_fifo_record(const struct hal_fifo_hdr *h,
						    union hal_fifo_value *data, rtapi_u32 pos)
{
	return data + (unsigned long)pos * hal_fifo_rec_words(h->num_pins);
}

/* Current number of records, as either side sees it. */
static inline rtapi_u32 hal_fifo_used(const struct hal_fifo_hdr *h)
{
	rtapi_u32 in = __atomic_load_n(&h->in, __ATOMIC_ACQUIRE);
	rtapi_u32 out = __atomic_load_n(&h->out, __ATOMIC_ACQUIRE);

	if (in >= h->slots || out >= h->slots)
		return 0;
	return hal_fifo_count(in, out, h->slots);
}

/* Producer: the record to fill next, or NULL when the FIFO is full. */
static inline union hal_fifo_value *hal_fifo_write_slot(const struct hal_fifo_hdr *h,
							union hal_fifo_value *data)
{
	rtapi_u32 in = h->in;	/* ours: no other writer */
	rtapi_u32 out = __atomic_load_n(&h->out, __ATOMIC_ACQUIRE);

	if (in >= h->slots || hal_fifo_next(in, h->slots) == out)
		return NULL;
	return hal_fifo_record(h, data, in);
}

/* Producer: make the record filled after hal_fifo_write_slot() visible. */
static inline void hal_fifo_write_done(struct hal_fifo_hdr *h)
{
	__atomic_store_n(&h->in, hal_fifo_next(h->in, h->slots), __ATOMIC_RELEASE);
}

/* Consumer: the oldest record, or NULL when the FIFO is empty. */
static inline const union hal_fifo_value *hal_fifo_read_slot(const struct hal_fifo_hdr *h,
							     union hal_fifo_value *data)
{
	rtapi_u32 out = h->out;	/* ours: no other writer */
	rtapi_u32 in = __atomic_load_n(&h->in, __ATOMIC_ACQUIRE);

	if (out >= h->slots || in >= h->slots || in == out)
		return NULL;
	return hal_fifo_record(h, data, out);
}

/* Consumer: release the record returned by hal_fifo_read_slot(). */
static inline void hal_fifo_read_done(struct hal_fifo_hdr *h)
{
	__atomic_store_n(&h->out, hal_fifo_next(h->out, h->slots), __ATOMIC_RELEASE);
}

/* The realtime side (sampler, streamer) keeps its own copy of the geometry and of its
 * own index, in its hal_malloc() memory, which users cannot write. The header is in
 * shared memory that users may write (halsampler moves 'out'; docs/kernel-security.md),
 * so realtime code takes no size, stride or own index from it, and checks the other
 * side's index against its own copy before using it. */
struct hal_fifo_rt {
	rtapi_u32 slots;	/* depth + 1 */
	rtapi_u32 rec_words;	/* values per record, header words included */
	rtapi_u32 pos;		/* the producer's 'in' or the consumer's 'out' */
};

static inline void hal_fifo_rt_init(struct hal_fifo_rt *r, rtapi_u32 depth, rtapi_u32 num_pins)
{
	r->slots = depth + 1;
	r->rec_words = hal_fifo_rec_words(num_pins);
	r->pos = 0;
}

/* Records in the FIFO as the realtime side sees them (0 if the other index is bad). */
static inline rtapi_u32 hal_fifo_rt_used(const struct hal_fifo_hdr *h, const struct hal_fifo_rt *r,
					 int producer)
{
	rtapi_u32 other = __atomic_load_n(producer ? &h->out : &h->in, __ATOMIC_ACQUIRE);

	if (other >= r->slots)
		return 0;
	return producer ? hal_fifo_count(r->pos, other, r->slots) : hal_fifo_count(other, r->pos, r->slots);
}

/* Producer: the record to fill next, or NULL when the FIFO is full (or 'out' is bad). */
static inline union hal_fifo_value *hal_fifo_rt_write_slot(const struct hal_fifo_hdr *h,
							   const struct hal_fifo_rt *r,
							   union hal_fifo_value *data)
{
	rtapi_u32 out = __atomic_load_n(&h->out, __ATOMIC_ACQUIRE);

	if (out >= r->slots || hal_fifo_next(r->pos, r->slots) == out)
		return NULL;
	return data + (unsigned long)r->pos * r->rec_words;
}

static inline void hal_fifo_rt_write_done(struct hal_fifo_hdr *h, struct hal_fifo_rt *r)
{
	r->pos = hal_fifo_next(r->pos, r->slots);
	__atomic_store_n(&h->in, r->pos, __ATOMIC_RELEASE);
}

/* Consumer: the oldest record, or NULL when the FIFO is empty (or 'in' is bad). */
static inline const union hal_fifo_value *hal_fifo_rt_read_slot(const struct hal_fifo_hdr *h,
								const struct hal_fifo_rt *r,
								union hal_fifo_value *data)
{
	rtapi_u32 in = __atomic_load_n(&h->in, __ATOMIC_ACQUIRE);

	if (in >= r->slots || in == r->pos)
		return NULL;
	return data + (unsigned long)r->pos * r->rec_words;
}

static inline void hal_fifo_rt_read_done(struct hal_fifo_hdr *h, struct hal_fifo_rt *r)
{
	r->pos = hal_fifo_next(r->pos, r->slots);
	__atomic_store_n(&h->out, r->pos, __ATOMIC_RELEASE);
}

#ifdef __cplusplus
}
#endif
#endif /* STREAMER_FIFO_H */

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_sim_model.c - the simulated FPGA: IDROM image, register reads/writes with the
 * side effects of the real modules, and time (see hm2_sim_model.h). Module register
 * layouts follow hostmot2.md section 7; registers without side effects are plain
 * memory that reads back what was written. */
#include "rtapi.h"
#include "rtapi_string.h"
#include "hm2_sim_model.h"

#define IDROM_AT 0x400u
#define MD_AT 0x40u
#define PD_AT 0x1C0u
#define WD_BIT 0x80000000u

static void put(struct hm2_sim_model *m, rtapi_u32 addr, rtapi_u32 v)
{
	m->mem[(addr & 0xFFFF) / 4] = v;
}

static rtapi_u32 ascii4(const char *s)
{
	return (rtapi_u32)(rtapi_u8)s[0] | (rtapi_u32)(rtapi_u8)s[1] << 8 |
	       (rtapi_u32)(rtapi_u8)s[2] << 16 | (rtapi_u32)(rtapi_u8)s[3] << 24;
}

static const struct sim_md *find_md(const struct sim_layout *l, int gtag)
{
	int i;

	for (i = 0; i < SIM_MAX_MODULES && l->md[i].gtag; i++)
		if (l->md[i].gtag == gtag)
			return &l->md[i];
	return 0;
}

static void build_idrom(struct hm2_sim_model *m, const struct sim_layout *l, int fault)
{
	rtapi_u32 io_width = l->ports * l->port_width, w[16];
	int i, j;

	put(m, 0x100, fault == SIM_FAULT_NO_COOKIE ? 0 : 0x55AACAFEu);
	put(m, 0x104, ascii4(fault == SIM_FAULT_BAD_NAME ? "HOST" : "HOST"));
	put(m, 0x108, ascii4(fault == SIM_FAULT_BAD_NAME ? "MOT3" : "MOT2"));
	put(m, 0x10C, fault == SIM_FAULT_IDROM_OFFSET_0 ? 0 : IDROM_AT);
	w[0] = fault == SIM_FAULT_IDROM_TYPE ? 0x1234 : 3;
	w[1] = MD_AT;
	w[2] = PD_AT;
	w[3] = ascii4(l->idrom_name);
	w[4] = ascii4(l->idrom_name + 4);
	w[5] = l->fpga_size;
	w[6] = l->fpga_pins;
	w[7] = l->ports;
	w[8] = io_width;
	w[9] = l->port_width;
	w[10] = l->clock_low;
	w[11] = l->clock_high;
	w[12] = 4;
	w[13] = 0x40;
	w[14] = w[15] = 0x100;
	if (fault == SIM_FAULT_PORT_WIDTH)
		w[9] = 29;
	if (fault == SIM_FAULT_IO_WIDTH)
		w[8] = 99;
	if (fault == SIM_FAULT_IO_PORTS) {
		w[7] = l->ports + 1;
		w[8] = w[7] * l->port_width;
	}
	if (fault == SIM_FAULT_CLOCK_LOW)
		w[10] = 12345;
	if (fault == SIM_FAULT_CLOCK_HIGH)
		w[11] = 0;
	for (i = 0; i < 16; i++)
		put(m, IDROM_AT + 4 * i, w[i]);
	for (i = 0, j = 0; i < SIM_MAX_MODULES && l->md[i].gtag; i++) {
		const struct sim_md *d = &l->md[i];
		rtapi_u32 w0, w1;
		int clock_tag = d->clock_tag, nregs = d->num_registers;

		if (fault == SIM_FAULT_NO_IOPORT && d->gtag == 3)
			continue;
		if (fault == SIM_FAULT_MD_INCONSISTENT && d->gtag == 4)
			nregs = 4;
		if (fault == SIM_FAULT_CLOCK_TAG && d->gtag == 4)
			clock_tag = 7;
		w0 = d->gtag | (rtapi_u32)d->version << 8 | (rtapi_u32)clock_tag << 16 |
		     (rtapi_u32)d->instances << 24;
		w1 = d->base | (rtapi_u32)nregs << 16 | (rtapi_u32)d->instance_stride_sel << 28;
		put(m, IDROM_AT + MD_AT + 12 * j, w0);
		put(m, IDROM_AT + MD_AT + 12 * j + 4, w1);
		put(m, IDROM_AT + MD_AT + 12 * j + 8, d->multiple_registers);
		j++;
		if (fault == SIM_FAULT_DUPLICATE_MD && d->gtag == 2) {
			put(m, IDROM_AT + MD_AT + 12 * j, w0);
			put(m, IDROM_AT + MD_AT + 12 * j + 4, w1);
			put(m, IDROM_AT + MD_AT + 12 * j + 8, d->multiple_registers);
			j++;
		}
	}
	put(m, IDROM_AT + MD_AT + 12 * j, 0);	/* end of list */
	for (i = 0; i < (int)io_width && i < SIM_MAX_PINS; i++)
		put(m, IDROM_AT + PD_AT + 4 * i, fault == SIM_FAULT_PD_SENTINEL && i >= 3 ? 0 : l->pd[i]);
}

/* which IO pins carry each encoder's A/B/index and each stepgen's step/dir; a muxed
 * unit's data pins serve encoders 2u and 2u + 1 */
static void find_pins(struct hm2_sim_model *m)
{
	const struct sim_layout *l = m->layout;
	int i, k;

	m->pin_mux_sel = -1;
	for (i = 0; i < SIM_MAX_INST; i++) {
		for (k = 0; k < 2; k++)
			m->qc[k].enc[i].pin_a = m->qc[k].enc[i].pin_b = m->qc[k].enc[i].pin_idx = -1;
		m->sg[i].pin_step = m->sg[i].pin_dir = -1;
		m->tp[i].pin_fault = -1;
	}
	for (i = 0; i < m->num_pins; i++) {
		rtapi_u32 pd = l->pd[i];
		int tag = (pd >> 8) & 0xFF, unit = (pd >> 16) & 0x7F, pin = pd & 0xFF;

		if (unit >= SIM_MAX_INST)
			continue;
		if ((tag == 4 || tag == 12) && pin >= 1 && pin <= 3) {
			struct sim_qcount *q = &m->qc[tag == 12];
			int e = tag == 12 ? 2 * unit : unit;

			for (k = 0; k <= (tag == 12) && e + k < SIM_MAX_INST; k++) {
				int *slot = pin == 1 ? &q->enc[e + k].pin_a : pin == 2 ? &q->enc[e + k].pin_b
						     : &q->enc[e + k].pin_idx;

				*slot = i;
			}
		}
		if (tag == 13 && pin == 0x81)
			m->pin_mux_sel = i;
		if (tag == 5 && pin == 0x81)
			m->sg[unit].pin_step = i;
		if (tag == 5 && pin == 0x82)
			m->sg[unit].pin_dir = i;
		if (tag == 19 && pin == 0x08)
			m->tp[unit].pin_fault = i;
	}
}

void hm2_sim_model_init(struct hm2_sim_model *m, const struct sim_layout *l, int fault,
			long long now_ns)
{
	const struct sim_md *d;

	memset(m, 0, sizeof(*m));
	m->layout = l;
	m->num_pins = l->ports * l->port_width;
	build_idrom(m, l, fault);
	d = find_md(l, 3);
	m->base_ioport = d ? d->base : 0;
	d = find_md(l, 2);
	m->base_watchdog = d ? d->base : 0;
	d = find_md(l, 4);
	m->qc[0].base = d ? d->base : 0;
	m->qc[0].num = d ? d->instances : 0;
	d = find_md(l, 12);
	m->qc[1].base = d ? d->base : 0;
	m->qc[1].num = d ? d->instances : 0;
	m->qc[1].muxed = 1;
	d = find_md(l, 19);
	m->base_tppwm = d ? d->base : 0;
	m->num_tppwm = d ? d->instances : 0;
	d = find_md(l, 14);
	m->base_bspi = d ? d->base : 0;
	m->num_bspi = d ? d->instances : 0;
	d = find_md(l, 9);
	m->base_uart_tx = d ? d->base : 0;
	m->num_uart = d ? d->instances : 0;
	d = find_md(l, 10);
	m->base_uart_rx = d ? d->base : 0;
	if (m->num_bspi > 2)
		m->num_bspi = 2;
	if (m->num_uart > 2)
		m->num_uart = 2;
	if (m->num_tppwm > SIM_MAX_INST)
		m->num_tppwm = SIM_MAX_INST;
	d = find_md(l, 5);
	m->base_stepgen = d ? d->base : 0;
	m->num_stepgens = d ? d->instances : 0;
	m->wd_timer = m->wd_reload = WD_BIT;
	m->last_ns = now_ns;
	find_pins(m);
}

/* what the module behind an alt-source pin drives */
static int module_out(struct hm2_sim_model *m, int pin)
{
	int i;

	if (pin >= 0 && pin == m->pin_mux_sel)
		return m->mux_sel;
	for (i = 0; i < m->num_stepgens; i++) {
		struct sim_stepgen *s = &m->sg[i];
		int swap = (s->mode >> 2) & 1;
		int step = (s->acc >> 31) & 1, dir = (rtapi_s32)s->rate < 0;

		if ((s->mode & 3) != 0)
			continue;	/* only step/dir output is modelled on the pins */
		if (pin == s->pin_step)
			return swap ? dir : step;
		if (pin == s->pin_dir)
			return swap ? step : dir;
	}
	return 0;
}

static void update_levels(struct hm2_sim_model *m)
{
	int i, w = m->layout->port_width;

	for (i = 0; i < m->num_pins; i++) {
		int p = i / w;
		rtapi_u32 bit = 1u << (i % w);
		int data = (m->alt[p] & bit) ? module_out(m, i) : !!(m->data[p] & bit);

		if (m->inv[p] & bit)
			data = !data;
		if (m->od[p] & bit)
			m->level[i] = data ? m->ext_in[i] : 0;
		else if (m->ddr[p] & bit)
			m->level[i] = data;
		else
			m->level[i] = m->ext_in[i];
	}
}

static int level(struct hm2_sim_model *m, int pin)
{
	return pin >= 0 ? m->level[pin] : 0;
}

/* quadrature (or up/down) counting from the sampled levels; index latch */
static void sample_encoder(struct sim_encoder *e, int a, int b, int z, rtapi_u16 ts)
{
	static const rtapi_s8 quad[4][4] = {	/* [prev AB][now AB]: A leads B = up */
		{ 0, -1, 1, 2 }, { 1, 0, 2, -1 }, { -1, 2, 0, 1 }, { 2, 1, -1, 0 },
	};
	int d = 0, pol = (e->control >> 3) & 1;

	if (e->control & (1u << 10)) {		/* up/down: count A rising, B = down */
		if (a && !e->a)
			d = b ? -1 : 1;
	} else {
		d = quad[(e->a << 1) | e->b][(a << 1) | b];
		if (d == 2) {		/* both changed: illegal sequence */
			e->control |= 0x8000u;
			d = 0;
		}
	}
	if (d) {
		e->count += d;
		e->ts = ts;
	}
	if ((e->control & (1u << 4)) && z != e->idx && z == pol) {
		e->latched = e->count;
		if (e->control & (1u << 6))
			e->control &= ~(1u << 4);	/* JustOnce */
	}
	e->a = a;
	e->b = b;
	e->idx = z;
}

/* The muxed encoders see, through the outside multiplexer, the channel their select
 * phase picks; the select toggles far faster than HAL runs, so within one step both
 * channels of a unit are sampled. The data pins show the channel selected now. */
static void sample_encoders(struct hm2_sim_model *m)
{
	int i, k;

	for (k = 0; k < 2; k++) {
		struct sim_qcount *q = &m->qc[k];
		rtapi_u16 ts = (rtapi_u16)rtapi_div_u64(m->ticks, q->tsdiv + 2);

		for (i = 0; i < q->num && i < SIM_MAX_INST; i++) {
			struct sim_encoder *e = &q->enc[i];

			if (q->muxed)
				sample_encoder(e, m->mux_in[i][0], m->mux_in[i][1], m->mux_in[i][2], ts);
			else
				sample_encoder(e, level(m, e->pin_a), level(m, e->pin_b), level(m, e->pin_idx), ts);
		}
	}
}

/* the outside multiplexer: data pins carry the selected channel */
static void drive_mux(struct hm2_sim_model *m)
{
	struct sim_qcount *q = &m->qc[1];
	int i;

	if (!q->base)
		return;
	m->mux_sel = !m->mux_sel;
	for (i = m->mux_sel; i < q->num && i < SIM_MAX_INST; i += 2) {
		struct sim_encoder *e = &q->enc[i];

		if (e->pin_a >= 0)
			m->ext_in[e->pin_a] = m->mux_in[i][0];
		if (e->pin_b >= 0)
			m->ext_in[e->pin_b] = m->mux_in[i][1];
		if (e->pin_idx >= 0)
			m->ext_in[e->pin_idx] = m->mux_in[i][2];
	}
}

/* 3pwmgen: an active fault input latches the fault and clears enable */
static void tppwm_faults(struct hm2_sim_model *m)
{
	int i;

	for (i = 0; i < m->num_tppwm && i < SIM_MAX_INST; i++) {
		struct sim_tppwm *t = &m->tp[i];
		int active_high = (t->setup >> 15) & 1;

		if (t->pin_fault >= 0 && level(m, t->pin_fault) == active_high) {
			t->fault = 1;
			t->enable = 0;
		}
	}
}

void hm2_sim_model_advance(struct hm2_sim_model *m, long long now_ns)
{
	long long dt = now_ns - m->last_ns;
	rtapi_u64 total;
	rtapi_u32 rem, t;
	int i;

	if (dt < 0)
		dt = 0;
	if (dt > 1000000000LL)
		dt = 1000000000LL;	/* a paused session does not age the board by hours */
	m->last_ns = now_ns;
	total = (rtapi_u64)dt * m->layout->clock_low + m->frac_ns;
	t = (rtapi_u32)rtapi_div_u64_rem(total, 1000000000u, &rem);
	m->frac_ns = rem;
	m->ticks += t;
	if (m->base_watchdog && !(m->wd_timer & WD_BIT)) {
		m->wd_timer -= t;
		if (m->wd_timer & WD_BIT) {	/* bite: every pin released */
			m->wd_status |= 1;
			for (i = 0; i < m->layout->ports; i++)
				m->ddr[i] = m->od[i] = 0;
		}
	}
	for (i = 0; i < m->num_stepgens; i++) {
		struct sim_stepgen *s = &m->sg[i];

		s->acc = (s->acc + (rtapi_u64)((rtapi_s64)(rtapi_s32)s->rate * (rtapi_s64)t)) &
			 0xFFFFFFFFFFFFull;
	}
	drive_mux(m);
	update_levels(m);
	sample_encoders(m);
	tppwm_faults(m);
	hm2_sim_serial_advance(m);
}

/* register r and instance i of the module whose base is base, or -1 */
static int decode(rtapi_u32 addr, rtapi_u32 base, int nregs, int ninst, int *inst)
{
	int r;

	if (!base || addr < base || addr >= base + nregs * 0x100u)
		return -1;
	r = (addr - base) >> 8;
	*inst = (addr & 0xFF) / 4;
	return *inst < ninst || ninst == 0 ? r : -1;
}

rtapi_u32 hm2_sim_model_read(struct hm2_sim_model *m, rtapi_u32 addr)
{
	int r, i, w = m->layout->port_width, b;
	rtapi_u32 v;

	addr &= 0xFFFC;
	m->words_read++;
	if ((r = decode(addr, m->base_watchdog, 3, 1, &i)) >= 0)
		return r == 0 ? m->wd_timer : r == 1 ? m->wd_status : 0;
	if ((r = decode(addr, m->base_ioport, 5, m->layout->ports, &i)) >= 0) {
		rtapi_u32 v = 0;

		switch (r) {
		case 0:
			for (b = 0; b < w; b++)
				v |= (rtapi_u32)m->level[i * w + b] << b;
			return v;
		case 1: return m->ddr[i];
		case 2: return m->alt[i];
		case 3: return m->od[i];
		default: return m->inv[i];
		}
	}
	for (b = 0; b < 2; b++) {
		struct sim_qcount *q = &m->qc[b];

		if ((r = decode(addr, q->base, 5, 0, &i)) < 0)
			continue;
		if (r == 0 && i < q->num)
			return (rtapi_u32)q->enc[i].ts << 16 | q->enc[i].count;
		if (r == 1 && i < q->num)
			return (rtapi_u32)q->enc[i].latched << 16 | (q->enc[i].control & 0xFFF8u) |
			       q->enc[i].idx << 2 | q->enc[i].b << 1 | q->enc[i].a;
		if (r == 3)
			return (rtapi_u32)rtapi_div_u64(m->ticks, q->tsdiv + 2) & 0xFFFF;
	}
	if ((r = decode(addr, m->base_tppwm, 4, 0, &i)) >= 0 && r == 1 && i < m->num_tppwm)
		return m->tp[i].enable | (rtapi_u32)m->tp[i].fault << 1;
	if (hm2_sim_serial_read(m, addr, &v))
		return v;
	if ((r = decode(addr, m->base_stepgen, 10, 0, &i)) >= 0 && r == 1 && i < m->num_stepgens)
		return (rtapi_u32)(m->sg[i].acc >> 16);
	if (addr == 0x7000 + 3 * 0x100)		/* DPLL control 1: DDS size 32 reads back */
		return (m->mem[addr / 4] & ~0xFFu) | 32;
	return m->mem[addr / 4];
}

void hm2_sim_model_write(struct hm2_sim_model *m, rtapi_u32 addr, rtapi_u32 v)
{
	int r, i, k;

	addr &= 0xFFFC;
	m->words_written++;
	if (addr < 0x800 && addr >= 0x100)
		return;			/* the IDROM and the fixed words are read-only */
	if ((r = decode(addr, m->base_watchdog, 3, 1, &i)) >= 0) {
		if (r == 0)
			m->wd_timer = m->wd_reload = v;
		else if (r == 1)
			m->wd_status = v & 1;
		else if ((v >> 24) == 0x5A)
			m->wd_timer = m->wd_reload;
		return;
	}
	if ((r = decode(addr, m->base_ioport, 5, m->layout->ports, &i)) >= 0) {
		rtapi_u32 *regs[5] = { m->data, m->ddr, m->alt, m->od, m->inv };

		regs[r][i] = v;
		update_levels(m);
		return;
	}
	for (k = 0; k < 2; k++) {
		struct sim_qcount *q = &m->qc[k];

		if ((r = decode(addr, q->base, 5, 0, &i)) < 0)
			continue;
		if (r == 0 && i < q->num) {
			q->enc[i].count = 0;	/* any write clears the count */
			return;
		}
		if (r == 1 && i < q->num) {
			q->enc[i].control = v & 0xFFF8u;	/* bit 15 loads the quad-error flag */
			return;
		}
		if (r == 2)
			q->tsdiv = v & 0xFFFF;
		if (r == 4)
			q->filter = v;
	}
	if ((r = decode(addr, m->base_tppwm, 4, 0, &i)) >= 0 && i < m->num_tppwm) {
		struct sim_tppwm *t = &m->tp[i];

		if (r == 0)
			t->value = v;
		else if (r == 1) {
			t->enable = v & 1;	/* enabling clears a latched fault */
			if (t->enable)
				t->fault = 0;
		} else if (r == 2)
			t->setup = v;
	}
	if (hm2_sim_serial_write(m, addr, v))
		return;
	if ((r = decode(addr, m->base_stepgen, 10, 0, &i)) >= 0 && i < m->num_stepgens) {
		if (r == 0)
			m->sg[i].rate = v;
		else if (r == 1)
			m->sg[i].acc = (rtapi_u64)v << 16;
		else if (r == 2)
			m->sg[i].mode = v;
	}
	m->mem[addr / 4] = v;
}

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_parport.c - the PC parallel port driver (module hal_parport), small-boards.md
 * §3: loadrt hal_parport cfg="addr [type] ..." (default "0x0278"; types in, out,
 * epp, x). Per port P: pins parport.P.pin-NN-out / -in / -in-not, params
 * -out-invert / -out-reset, reset-time, debug1, debug2; functions parport.P.read,
 * parport.P.write, parport.P.reset and parport.read-all / parport.write-all (no FP).
 * HAL TRUE always means the DB25 pin is electrically high: the port's own inversions
 * (status bit 7, control bits 0, 1, 3) are undone here. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "hal_parport.h"
#include "parport_cfg.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("PC parallel port driver");

static char *cfg = "0x0278";
RTAPI_MP_STRING(cfg, "ports: \"addr [in|out|epp|x] ...\"");

#define STATUS_INV 0x80		/* Busy (pin 11) is inverted by the port */
#define CONTROL_INV 0x0b	/* nStrobe, nAutoFd, nSelectIn are inverted */
#define CONTROL_DIR_IN 0x20	/* data port reads the pins */
#define SHADOW_NONE 0x100	/* no byte equals it: the first write always writes */

/* DB25 pins of the status bits 3..7 and of the control bits 0..3. */
static const int status_pin[5] = { 15, 13, 12, 10, 11 };
static const int control_pin[4] = { 1, 14, 16, 17 };

struct out_pin {		/* one output; HAL memory */
	hal_bit_t *out;		/* read by write() */
	hal_bit_t invert;	/* param */
	hal_bit_t reset;	/* param: reset() returns the pin to its FALSE level */
};

struct in_pin {			/* one input; HAL memory */
	hal_bit_t *in, *in_not;	/* written by read() */
};

struct pp_port {		/* one port; HAL memory, owned by its functions */
	hal_parport_t pp;
	enum parport_type type;
	struct out_pin data_out[8];	/* used when the data port is an output */
	struct in_pin data_in[8];	/* used for type in */
	struct in_pin status_in[5];
	struct out_pin control_out[4];	/* used unless type x */
	struct in_pin control_in[4];	/* used for type x */
	hal_u32_t reset_time;		/* ns, clamped to period/4 by reset() */
	hal_u32_t debug1, debug2;
	unsigned int data_shadow, control_shadow;	/* last written, or SHADOW_NONE */
	unsigned char data_reset_mask, data_reset_val;	/* from write() for reset() */
	unsigned char control_reset_mask, control_reset_val;
	long long data_time, control_time;	/* rtapi_get_time() of the last writes */
};

struct pp_all {
	int num;
	struct pp_port *port;
};

static int comp_id;
static struct pp_all *all;	/* HAL memory; set once in rtapi_app_main */

static int data_is_output(const struct pp_port *p)
{
	return p->type != PARPORT_IN;
}

static void pp_read(void *arg, long period)
{
	struct pp_port *p = arg;
	unsigned char b = rtapi_inb(p->pp.base + 1) ^ STATUS_INV;
	int i;

	for (i = 0; i < 5; i++) {
		*p->status_in[i].in = (b >> (i + 3)) & 1;
		*p->status_in[i].in_not = !*p->status_in[i].in;
	}
	if (p->type == PARPORT_IN) {
		b = rtapi_inb(p->pp.base);
		for (i = 0; i < 8; i++) {
			*p->data_in[i].in = (b >> i) & 1;
			*p->data_in[i].in_not = !*p->data_in[i].in;
		}
	} else if (p->type == PARPORT_X) {
		b = rtapi_inb(p->pp.base + 2) ^ CONTROL_INV;
		for (i = 0; i < 4; i++) {
			*p->control_in[i].in = (b >> i) & 1;
			*p->control_in[i].in_not = !*p->control_in[i].in;
		}
	}
}

/* The byte of 'n' outputs, its reset mask and the reset pins' FALSE levels. */
static unsigned char out_byte(const struct out_pin *o, int n, unsigned char *mask,
			      unsigned char *val)
{
	unsigned char b = 0;
	int i;

	*mask = *val = 0;
	for (i = 0; i < n; i++) {
		b |= (unsigned char)((*o[i].out ^ o[i].invert) & 1) << i;
		if (o[i].reset) {
			*mask |= 1u << i;
			*val |= (unsigned char)(o[i].invert & 1) << i;
		}
	}
	return b;
}

static void pp_write(void *arg, long period)
{
	struct pp_port *p = arg;
	unsigned char b, mask, val;

	if (data_is_output(p)) {
		b = out_byte(p->data_out, 8, &p->data_reset_mask, &p->data_reset_val);
		if (b != p->data_shadow) {
			rtapi_outb(b, p->pp.base);
			p->data_shadow = b;
			p->data_time = rtapi_get_time();
		}
	}
	if (p->type == PARPORT_X) {
		b = 0x0f;	/* open collector: every control pin floats high */
		p->control_reset_mask = 0;
	} else {
		b = out_byte(p->control_out, 4, &mask, &val);
		p->control_reset_mask = mask;
		p->control_reset_val = val;
	}
	if (p->type == PARPORT_IN)
		b |= CONTROL_DIR_IN;
	if (b != p->control_shadow) {
		rtapi_outb(b ^ CONTROL_INV, p->pp.base + 2);
		p->control_shadow = b;
		p->control_time = rtapi_get_time();
	}
}

static void wait_until(long long t)
{
	while (rtapi_get_time() < t)
		;
}

static void pp_reset(void *arg, long period)
{
	struct pp_port *p = arg;
	unsigned int b;

	if (p->reset_time > period / 4)
		p->reset_time = period / 4;
	if (data_is_output(p) && p->data_shadow != SHADOW_NONE) {
		b = (p->data_shadow & ~p->data_reset_mask) ^ p->data_reset_val;
		if (b != p->data_shadow) {
			wait_until(p->data_time + p->reset_time);
			rtapi_outb(b, p->pp.base);
			p->data_shadow = b;
		}
	}
	if (p->control_shadow != SHADOW_NONE) {
		b = (p->control_shadow & ~p->control_reset_mask) ^ p->control_reset_val;
		if (b != p->control_shadow) {
			wait_until(p->control_time + p->reset_time);
			rtapi_outb(b ^ CONTROL_INV, p->pp.base + 2);
			p->control_shadow = b;
		}
	}
}

static void pp_read_all(void *arg, long period)
{
	struct pp_all *a = arg;
	int n;

	for (n = 0; n < a->num; n++)
		pp_read(&a->port[n], period);
}

static void pp_write_all(void *arg, long period)
{
	struct pp_all *a = arg;
	int n;

	for (n = 0; n < a->num; n++)
		pp_write(&a->port[n], period);
}

static int export_out(struct out_pin *o, int port, int pin)
{
	int err = hal_pin_bit_newf(HAL_IN, &o->out, comp_id, "parport.%d.pin-%02d-out", port, pin);

	if (!err)
		err = hal_param_bit_newf(HAL_RW, &o->invert, comp_id,
					 "parport.%d.pin-%02d-out-invert", port, pin);
	if (!err)
		err = hal_param_bit_newf(HAL_RW, &o->reset, comp_id,
					 "parport.%d.pin-%02d-out-reset", port, pin);
	return err;
}

static int export_in(struct in_pin *in, int port, int pin)
{
	int err = hal_pin_bit_newf(HAL_OUT, &in->in, comp_id, "parport.%d.pin-%02d-in", port, pin);

	if (!err)
		err = hal_pin_bit_newf(HAL_OUT, &in->in_not, comp_id,
				       "parport.%d.pin-%02d-in-not", port, pin);
	return err;
}

static int export_funct(const char *what, void (*fn)(void *, long), void *arg, int n)
{
	char name[HAL_NAME_LEN + 1];

	rtapi_snprintf(name, sizeof(name), "parport.%d.%s", n, what);
	return hal_export_funct(name, fn, arg, 0, 0, comp_id);
}

static int export_port(struct pp_port *p, int n)
{
	int i, err = 0;

	for (i = 0; !err && i < 8; i++)
		err = data_is_output(p) ? export_out(&p->data_out[i], n, i + 2)
					: export_in(&p->data_in[i], n, i + 2);
	for (i = 0; !err && i < 5; i++)
		err = export_in(&p->status_in[i], n, status_pin[i]);
	for (i = 0; !err && i < 4; i++)
		err = p->type == PARPORT_X ? export_in(&p->control_in[i], n, control_pin[i])
					   : export_out(&p->control_out[i], n, control_pin[i]);
	if (!err && data_is_output(p)) {
		err = hal_param_u32_newf(HAL_RW, &p->reset_time, comp_id, "parport.%d.reset-time", n);
		if (!err)
			err = hal_param_u32_newf(HAL_RW, &p->debug1, comp_id, "parport.%d.debug1", n);
		if (!err)
			err = hal_param_u32_newf(HAL_RW, &p->debug2, comp_id, "parport.%d.debug2", n);
	}
	if (!err)
		err = export_funct("read", pp_read, p, n);
	if (!err)
		err = export_funct("write", pp_write, p, n);
	if (!err)
		err = export_funct("reset", pp_reset, p, n);
	return err;
}

/* Claim the port and put it in the mode its type needs. */
static int open_port(struct pp_port *p, const struct parport_cfg_entry *e, int n)
{
	unsigned int modes = HAL_PARPORT_MODE_PCSPP;
	int err;

	if (e->type == PARPORT_EPP)
		modes |= HAL_PARPORT_MODE_EPP;
	if (e->type == PARPORT_X || e->type == PARPORT_IN)
		modes |= HAL_PARPORT_MODE_TRISTATE;
	err = hal_parport_get(comp_id, &p->pp, e->addr, 0, modes);
	if (err) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_parport: port %d (%s0x%x): cannot claim it\n",
				n, e->addr < 16 ? "Linux parport " : "", e->addr);
		return err;
	}
	p->type = e->type;
	p->data_shadow = p->control_shadow = SHADOW_NONE;
	if (e->type == PARPORT_IN)
		rtapi_outb(rtapi_inb(p->pp.base + 2) | CONTROL_DIR_IN, p->pp.base + 2);
	if (e->type == PARPORT_EPP && p->pp.base_hi)
		rtapi_outb(0x94, p->pp.base_hi + 2);	/* ECR: EPP mode */
	return 0;
}

static void release_ports(void)
{
	int n;

	for (n = 0; all && n < all->num; n++)
		hal_parport_release(&all->port[n].pp);
}

int rtapi_app_main(void)
{
	struct parport_cfg_entry e[PARPORT_MAX_PORTS];
	char why[96];
	int n, num, err;

	num = parport_cfg_parse(cfg ? cfg : "", e, why, sizeof(why));
	if (num < 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_parport: cfg=\"%s\": %s\n", cfg ? cfg : "", why);
		return num;
	}
	comp_id = hal_init("hal_parport");
	if (comp_id < 0)
		return comp_id;
	all = hal_malloc(sizeof(*all));
	if (all)
		all->port = hal_malloc(num * (long)sizeof(*all->port));
	if (!all || !all->port) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hal_parport: out of HAL memory\n");
		hal_exit(comp_id);
		return -ENOMEM;
	}
	all->num = 0;
	err = 0;
	for (n = 0; !err && n < num; n++) {
		err = open_port(&all->port[n], &e[n], n);
		if (!err)
			all->num = n + 1;
		if (!err)
			err = export_port(&all->port[n], n);
	}
	if (!err)
		err = hal_export_funct("parport.read-all", pp_read_all, all, 0, 0, comp_id);
	if (!err)
		err = hal_export_funct("parport.write-all", pp_write_all, all, 0, 0, comp_id);
	if (err) {
		release_ports();
		hal_exit(comp_id);
		return err;
	}
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	release_ports();
	hal_exit(comp_id);
}

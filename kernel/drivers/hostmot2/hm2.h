/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2.h - the hostmot2 core's state for one board, shared by the core files and the
 * function-module files (hm2_<module>.c, with their float arithmetic in
 * hm2_<module>_fp.c). Everything here lives in hal_malloc() memory owned by the
 * board driver's component, so it goes away with the board.
 *
 * Who writes what: the registration code (hm2_core.c, init time) fills the
 * descriptors and pins; afterwards only the board's exported HAL functions (read,
 * write, read_gpio, write_gpio, all in one thread or, for the gpio ones, serialised
 * by the board being thread-safe) touch the module state. */
#ifndef HM2_H
#define HM2_H

#include "rtapi.h"
#include "hal.h"
#include "hm2_llio.h"
#include "hm2_idrom.h"
#include "hm2_config.h"
#include "hm2_serial.h"

/* the sub-driver API (hm2_serial.h) is exported from the files that define it */
#include "rtapi_export.h"

#define HM2_ERRLEN 160
/* orders a sub-driver's updates against the board's thread (both flavors) */
#define hm2_mb() __atomic_thread_fence(__ATOMIC_SEQ_CST)
#define HM2_TRAM_MAX 32

void hm2_msg(const struct hm2_llio *llio, int level, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
#define HM2_ERR(hm2, ...) hm2_msg((hm2)->llio, RTAPI_MSG_ERR, __VA_ARGS__)
#define HM2_WARN(hm2, ...) hm2_msg((hm2)->llio, RTAPI_MSG_WARN, __VA_ARGS__)
#define HM2_INFO(hm2, ...) hm2_msg((hm2)->llio, RTAPI_MSG_INFO, __VA_ARGS__)

/* ---- pins ---- */
enum hm2_pin_dir { HM2_PIN_IN = 0, HM2_PIN_OUT = 1 };

struct hm2_gpio {			/* HAL objects of one IO pin */
	hal_bit_t *in, *in_not;		/* written by read/read_gpio */
	hal_bit_t *out;			/* full GPIO only */
	hal_bit_t is_output;		/* full GPIO only */
	hal_bit_t is_opendrain, invert_output;	/* full GPIO and module outputs */
};

struct hm2_pin {
	struct hm2_pd pd;
	int port, bit;			/* IOPort instance and bit */
	int gtag;			/* owner: HM2_GTAG_IOPORT = plain GPIO */
	int dir;			/* the owner's direction (modules) */
	struct hm2_gpio gpio;
};

/* ---- TRAM: registers transferred every cycle ---- */
struct hm2_tram_entry {
	rtapi_u32 addr;
	int size;			/* bytes */
	rtapi_u32 **buf;		/* the module's pointer, set when buffers are allocated */
};

struct hm2_tram {
	struct hm2_tram_entry rd[HM2_TRAM_MAX], wr[HM2_TRAM_MAX];
	int num_rd, num_wr;
	int rd_bytes, wr_bytes;
	rtapi_u32 *rd_buf, *wr_buf;
};

/* ---- function modules ---- */
struct hm2_ioport {
	const struct hm2_md *md;
	int num;
	rtapi_u32 *data_rd, *data_wr;	/* TRAM: one word per port */
	rtapi_u32 ddr[HM2_LLIO_MAX_CONNECTORS], alt[HM2_LLIO_MAX_CONNECTORS];
	rtapi_u32 od[HM2_LLIO_MAX_CONNECTORS], inv[HM2_LLIO_MAX_CONNECTORS];
	rtapi_u32 w_ddr[HM2_LLIO_MAX_CONNECTORS], w_od[HM2_LLIO_MAX_CONNECTORS];
	rtapi_u32 w_inv[HM2_LLIO_MAX_CONNECTORS];	/* last written */
	int module_outputs_on;		/* set by the first write(): modules may drive */
};

struct hm2_watchdog {
	const struct hm2_md *md;	/* NULL: no watchdog in the firmware */
	hal_bit_t *has_bit;		/* pin, I/O: set by read, cleared by the user */
	hal_u32_t timeout_ns;		/* param */
	rtapi_u32 written_timeout_ns;
	int enable;			/* false until the first write() */
	int needs_force_write;		/* a bite was seen; reset when has_bit is cleared */
	rtapi_u32 *status_rd, *reset_wr;	/* TRAM */
};

struct hm2_led {
	const struct hm2_md *md;
	int num;
	hal_bit_t **led;		/* led.CR01... */
	rtapi_u32 written;
	int force;
};

struct hm2_raw {
	int on;
	hal_u32_t *read_address, *read_data, *write_address, *write_data;
	hal_bit_t *write_strobe, *dump_state;
	rtapi_u32 rd_word;		/* queued read target */
};

struct hm2_encoder_inst {
	hal_s32_t *count, *rawcounts;
	hal_float_t *position, *position_interpolated, *position_latched;
	hal_float_t *velocity, *velocity_rpm;
	hal_bit_t *reset, *index_enable, *probe_enable;
	hal_bit_t *input_a, *input_b, *input_index;
	hal_bit_t *quad_error_enable, *quad_error;
	hal_float_t scale, vel_timeout;
	hal_bit_t index_invert, index_mask, index_mask_invert, counter_mode, filter, probe_invert;
	/* read() state */
	rtapi_s64 raw;			/* extended count */
	rtapi_s64 zero;			/* raw value that reads as count 0 */
	rtapi_u16 prev16, prev_event_ts;
	rtapi_s32 time_since_event_ns;
	int has_event;
	rtapi_u32 control;		/* last written control word */
	rtapi_u32 written_control;
	int prev_qe_enable;
};

struct hm2_encoder {			/* plain (GTag 4) or muxed (GTag 12): never both */
	const struct hm2_md *md;
	int num;
	int muxed;
	hal_float_t *muxed_skew;	/* pin, ns; muxed version > 3 only */
	rtapi_u32 skew_ticks, written_skew;	/* filter-rate bits 31..28 */
	struct hm2_encoder_inst *inst;
	hal_u32_t *sample_frequency;	/* pin */
	hal_bit_t *hires_timestamp;	/* pin */
	hal_s32_t timer_number;		/* param, only with a DPLL */
	rtapi_u32 written_sample_frequency, written_tsdiv;
	int written_hires, written_timer;
	rtapi_u32 *counter_rd, *control_rd, *tscount_rd;	/* TRAM */
	rtapi_u32 tsdiv;
	int has_timer;
};

struct hm2_stepgen_inst {
	hal_float_t *position_cmd, *velocity_cmd;
	hal_s32_t *counts;
	hal_float_t *position_fb, *position_latched, *velocity_fb;
	hal_bit_t *enable, *position_reset, *control_type;
	hal_bit_t *index_enable, *probe_enable;	/* firmware 0xC2 only */
	hal_bit_t index_invert, probe_invert;
	hal_float_t position_scale, maxvel, maxaccel;
	hal_u32_t steplen, stepspace, dirsetup, dirhold, step_type;
	hal_bit_t swap_step_dir;
	hal_u32_t table_data[4];
	/* read/write state */
	rtapi_s64 subcounts, zero;	/* 16.16 steps */
	rtapi_u32 prev_acc;
	double old_position_cmd, vel;	/* written by write() (in _fp.c) */
	rtapi_u32 w_steplen, w_stepspace, w_dirsetup, w_dirhold, w_mode, w_table_sum;
	int force;
};

struct hm2_stepgen {
	const struct hm2_md *md;
	int num;
	struct hm2_stepgen_inst *inst;
	rtapi_u32 *rate_wr, *acc_rd;	/* TRAM */
	hal_s32_t timer_number;
	int written_timer, has_timer;
};

struct hm2_pwmgen_inst {
	hal_bit_t *enable, *offset_mode, *dither;
	hal_float_t *value;
	hal_float_t scale;
	hal_s32_t output_type;
	rtapi_u32 w_mode;
};

struct hm2_pwmgen {
	const struct hm2_md *md;
	int num;
	struct hm2_pwmgen_inst *inst;
	hal_u32_t pwm_frequency, pdm_frequency;	/* params, Hz */
	rtapi_u32 w_pwm_frequency, w_pdm_frequency, w_enable;
	int bits;			/* PWM resolution chosen from pwm_frequency */
	rtapi_u32 pwm_dds, pdm_dds;
	rtapi_u32 *value_wr;		/* TRAM */
	int force;
};

struct hm2_dpll {
	const struct hm2_md *md;	/* NULL: none, or num_dplls=0 */
	hal_float_t *timer_us[4], *base_freq_khz, *phase_error_us;
	hal_u32_t *time_const, *plimit, *ddsize, *prescale;
	rtapi_u32 *control1_rd, *phase_rd;	/* TRAM */
	rtapi_u32 w_base_rate, w_control0, w_control1, w_timers12, w_timers34;
	int writes;			/* write() calls so far, up to 100 */
	int force;
};

struct hm2_tppwm_inst {
	hal_float_t *a_value, *b_value, *c_value;
	hal_bit_t *enable, *fault;
	hal_u32_t deadtime;		/* ns */
	hal_float_t scale, sample_time;
	hal_bit_t fault_invert;
	rtapi_u32 setup, w_setup, w_enable;	/* setup: computed in _fp.c */
};

struct hm2_tppwm {
	const struct hm2_md *md;
	int num;
	struct hm2_tppwm_inst *inst;
	hal_u32_t frequency;		/* param, Hz */
	rtapi_u32 w_frequency, dds;
	rtapi_u32 *value_wr, *status_rd;	/* TRAM */
	int force;
};

/* one BSPI instance; the frames' words live here (not in the TRAM buffers) because
 * sub-drivers add them after the board registered */
struct hm2_bspi_inst {
	char name[HAL_NAME_LEN + 1];	/* "hm2_5i23.0.bspi.0" */
	struct hostmot2 *hm2;
	rtapi_u32 cd[16];
	int cd_dirty;			/* descriptors to (re)write at the next write() */
	rtapi_u32 frame_wr[HM2_BSPI_FRAMES], frame_rd[HM2_BSPI_FRAMES];
	int frame_chan[HM2_BSPI_FRAMES];
	int frame_echo[HM2_BSPI_FRAMES];	/* a reply word comes back (descriptor bit 31 clear) */
	int num_frames;
	volatile int active;		/* frames registered and allocated: sent every cycle */
	int sent;			/* write() sent them: read() takes the replies */
	int num_echo;			/* frames with a reply */
	rtapi_u32 count_rd;		/* FIFO counts, read before the replies */
	rtapi_u32 pending[16], pending_chan[16];	/* hm2_bspi_write_chan words */
	volatile int num_pending;
	int (*volatile read_fn)(void *);
	int (*volatile write_fn)(void *);
	void *volatile read_data, *volatile write_data;
	volatile int in_callback;
};

struct hm2_bspi {
	const struct hm2_md *md;
	int num;
	struct hm2_bspi_inst *inst;
};

struct hm2_uart_inst {
	char name[HAL_NAME_LEN + 1];	/* "hm2_5i23.0.uart.0" */
	struct hostmot2 *hm2;
	rtapi_u32 bitrate;
	rtapi_s32 tx_mode, rx_mode;
	volatile int dirty;		/* setup to write at the next write() */
};

struct hm2_uart {
	const struct hm2_md *tx_md, *rx_md;
	int num;
	struct hm2_uart_inst *inst;
};

struct hostmot2 {
	struct hm2_llio *llio;
	struct hm2_config cfg;
	struct hm2_idrom idrom;
	rtapi_u32 idrom_offset;
	struct hm2_md md[HM2_MAX_MODULE_DESCRIPTORS];
	int num_mds;
	struct hm2_pin *pin;
	int num_pins;
	struct hm2_tram tram;
	hal_bit_t io_error;		/* param <board>.io_error */
	volatile int closing;		/* hm2_unregister() ran: the functions do nothing */
	int read_requested;
	long period_ns;			/* of the thread running write(), for the DPLL */
	struct hm2_ioport ioport;
	struct hm2_watchdog watchdog;
	struct hm2_led led;
	struct hm2_raw raw;
	struct hm2_encoder encoder;
	struct hm2_stepgen stepgen;
	struct hm2_pwmgen pwmgen;
	struct hm2_dpll dpll;
	struct hm2_tppwm tppwm;
	struct hm2_bspi bspi;
	struct hm2_uart uart;
};

/* core services for the module files */
int hm2_tram_add_read(struct hostmot2 *hm2, rtapi_u32 addr, int size, rtapi_u32 **buf);
int hm2_tram_add_write(struct hostmot2 *hm2, rtapi_u32 addr, int size, rtapi_u32 **buf);
int hm2_write_now(struct hostmot2 *hm2, rtapi_u32 addr, const void *buf, int size);
int hm2_read_now(struct hostmot2 *hm2, rtapi_u32 addr, void *buf, int size);
int hm2_tram_allocate(struct hostmot2 *hm2);
int hm2_tram_request_reads(struct hostmot2 *hm2);
int hm2_tram_receive_reads(struct hostmot2 *hm2);
int hm2_tram_write(struct hostmot2 *hm2);
int hm2_tram_flush_writes(struct hostmot2 *hm2);
/* Give the pins of md's first n instances to the module (hostmot2.md section 6). */
void hm2_pins_allocate(struct hostmot2 *hm2, int gtag, int n);

/* The function modules, one verb set each (table in hm2_core.c):
 *   parse(hm2, md)    - check the MD, decide the instance count, register TRAM
 *   export(hm2)       - HAL pins/params (after the TRAM buffers exist)
 *   init_fp(hm2)      - float defaults; called inside rtapi_fpu_begin/end
 *   force_write(hm2)  - write every setup register (load and watchdog recovery)
 *   read(hm2, period) - after the TRAM read: registers -> HAL (FP allowed)
 *   write(hm2, period)- before the TRAM write: HAL -> registers, then on-change writes
 */
int hm2_ioport_parse(struct hostmot2 *hm2, const struct hm2_md *md);
int hm2_ioport_export(struct hostmot2 *hm2);
void hm2_ioport_force_write(struct hostmot2 *hm2);
void hm2_ioport_read(struct hostmot2 *hm2);
void hm2_ioport_write(struct hostmot2 *hm2);	/* data + on-change config */
void hm2_ioport_print_pins(struct hostmot2 *hm2);

int hm2_watchdog_parse(struct hostmot2 *hm2, const struct hm2_md *md);
int hm2_watchdog_export(struct hostmot2 *hm2);
void hm2_watchdog_force_write(struct hostmot2 *hm2);
void hm2_watchdog_read(struct hostmot2 *hm2);
void hm2_watchdog_write(struct hostmot2 *hm2, long period);
void hm2_watchdog_bite_now(struct hostmot2 *hm2);

int hm2_led_parse(struct hostmot2 *hm2, const struct hm2_md *md);
int hm2_led_export(struct hostmot2 *hm2);
void hm2_led_write(struct hostmot2 *hm2);

/* hm2_firmware.c: firmware= of the config string (registration step 2) */
int hm2_firmware_load(struct hostmot2 *hm2);

int hm2_raw_export(struct hostmot2 *hm2);
void hm2_raw_read(struct hostmot2 *hm2);
void hm2_raw_write(struct hostmot2 *hm2);

int hm2_encoder_parse(struct hostmot2 *hm2, const struct hm2_md *md);
int hm2_encoder_export(struct hostmot2 *hm2);
void hm2_encoder_force_write(struct hostmot2 *hm2);
void hm2_encoder_write(struct hostmot2 *hm2);
void hm2_encoder_init_fp(struct hostmot2 *hm2);
void hm2_encoder_read_fp(struct hostmot2 *hm2, long period);
void hm2_encoder_prepare_fp(struct hostmot2 *hm2);	/* after the first read: count = 0 */
void hm2_encoder_write_fp(struct hostmot2 *hm2);	/* muxed-skew ns -> clocks */

int hm2_stepgen_parse(struct hostmot2 *hm2, const struct hm2_md *md);
int hm2_stepgen_export(struct hostmot2 *hm2);
void hm2_stepgen_force_write(struct hostmot2 *hm2);
void hm2_stepgen_write(struct hostmot2 *hm2);	/* on-change timing/mode registers */
void hm2_stepgen_init_fp(struct hostmot2 *hm2);
void hm2_stepgen_read_fp(struct hostmot2 *hm2, long period);
void hm2_stepgen_prepare_write_fp(struct hostmot2 *hm2, long period);
void hm2_stepgen_prepare(struct hostmot2 *hm2);	/* after the first read */

int hm2_pwmgen_parse(struct hostmot2 *hm2, const struct hm2_md *md);
int hm2_pwmgen_export(struct hostmot2 *hm2);
void hm2_pwmgen_force_write(struct hostmot2 *hm2);
void hm2_pwmgen_write(struct hostmot2 *hm2);
void hm2_pwmgen_init_fp(struct hostmot2 *hm2);
void hm2_pwmgen_prepare_write_fp(struct hostmot2 *hm2);

int hm2_dpll_parse(struct hostmot2 *hm2, const struct hm2_md *md);
int hm2_dpll_export(struct hostmot2 *hm2);
void hm2_dpll_force_write(struct hostmot2 *hm2);
void hm2_dpll_init_fp(struct hostmot2 *hm2);
void hm2_dpll_read_fp(struct hostmot2 *hm2);
void hm2_dpll_write_fp(struct hostmot2 *hm2, long period);	/* computes, then writes */

int hm2_tppwm_parse(struct hostmot2 *hm2, const struct hm2_md *md);
int hm2_tppwm_export(struct hostmot2 *hm2);
void hm2_tppwm_force_write(struct hostmot2 *hm2);
void hm2_tppwm_read(struct hostmot2 *hm2);
void hm2_tppwm_write(struct hostmot2 *hm2);
rtapi_u32 hm2_tppwm_deadtime_reg(struct hostmot2 *hm2, int i);
void hm2_tppwm_init_fp(struct hostmot2 *hm2);
void hm2_tppwm_prepare_write_fp(struct hostmot2 *hm2);

/* BSPI and UART: the sub-driver API is hm2_serial.h; these are the core's verbs */
int hm2_bspi_parse(struct hostmot2 *hm2, const struct hm2_md *md);
int hm2_bspi_export(struct hostmot2 *hm2);	/* registers the names */
void hm2_bspi_force_write(struct hostmot2 *hm2);
int hm2_bspi_request_reads(struct hostmot2 *hm2);	/* with the per-cycle reads */
void hm2_bspi_read(struct hostmot2 *hm2);	/* sub-drivers' read functions */
void hm2_bspi_write(struct hostmot2 *hm2);	/* their write functions, then the frames */
void hm2_bspi_cleanup(struct hostmot2 *hm2);	/* unregister: forget the names */

int hm2_uart_parse(struct hostmot2 *hm2, const struct hm2_md *md);	/* TX and RX MDs */
int hm2_uart_allocate(struct hostmot2 *hm2);	/* after all MDs: count and pins */
int hm2_uart_export(struct hostmot2 *hm2);
void hm2_uart_force_write(struct hostmot2 *hm2);
void hm2_uart_write(struct hostmot2 *hm2);
void hm2_uart_cleanup(struct hostmot2 *hm2);

/* A second name, prefix.alias, for the pin or param prefix.name (hal_pin_alias). */
int hm2_alias_pin(struct hostmot2 *hm2, const char *prefix, const char *name, const char *alias);
int hm2_alias_param(struct hostmot2 *hm2, const char *prefix, const char *name, const char *alias);
/* hostmot2.txt's aliases for module output pins: <module>.<NN>.<pin>.invert_output
 * and .is_opendrain name the gpio.NNN params (hm2_alias.c). */
int hm2_alias_module_pins(struct hostmot2 *hm2);
/* A read done with the per-cycle reads: queued when the board batches. */
int hm2_tram_extra_read(struct hostmot2 *hm2, rtapi_u32 addr, void *buf, int size);

#endif /* HM2_H */

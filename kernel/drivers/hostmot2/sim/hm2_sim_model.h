/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_sim_model.h - a register-level model of a HostMot2 FPGA, the "hardware" behind
 * the hm2_sim board driver. It holds a real IDROM (header, module and pin
 * descriptors of one layout, hm2_sim_layouts.c) and models the modules behind it:
 * IOPort output stage (DDR, alt source, open drain, invert), watchdog countdown and
 * bite, encoders counting from the A/B/Z pin levels, stepgen accumulators, and plain
 * registers (PWM, LED, DPLL) that read back what was written.
 *
 * Time: the model runs on its own ClockLow; hm2_sim_model_advance() moves it forward
 * to the given time (the board calls it with rtapi_get_time() at every bus
 * transaction). The pins outside the FPGA are two bit arrays: ext_in (what the
 * outside world drives) and level (what the connector shows). Integer-only. */
#ifndef HM2_SIM_MODEL_H
#define HM2_SIM_MODEL_H

#include "rtapi.h"

#define SIM_MAX_PINS 144
#define SIM_MAX_PORTS 6
#define SIM_MAX_INST 16
#define SIM_MAX_MODULES 12
#define SIM_WORDS (0x10000 / 4)
#define SIM_FIFO 16			/* BSPI and UART FIFO depth */
#define SIM_7I65_CHANNELS 8
#define SIM_7I65_INPUTS 4

/* one module descriptor of a layout */
struct sim_md {
	rtapi_u8 gtag, version, clock_tag, instances;
	rtapi_u16 base;
	rtapi_u8 num_registers;
	rtapi_u8 instance_stride_sel;	/* 0: 4 bytes, 1: 0x40 */
	rtapi_u32 multiple_registers;
};

struct sim_layout {
	const char *board;		/* "5i25": HAL prefix hm2_5i25.N */
	const char *firmware;		/* what it imitates, for messages */
	const char *idrom_name;		/* 8 chars, "MESA5I25" */
	int ports, port_width, num_leds;
	const char *connector[SIM_MAX_PORTS];
	int bspi_7i65;			/* a 7i65 card hangs on BSPI 0 */
	rtapi_u32 clock_low, clock_high, fpga_size, fpga_pins;
	struct sim_md md[SIM_MAX_MODULES];	/* ends at gtag 0 */
	rtapi_u32 pd[SIM_MAX_PINS];		/* io_width entries */
};

/* faults a layout can be given, to present each IDROM refusal */
enum sim_fault {
	SIM_FAULT_NONE, SIM_FAULT_NO_COOKIE, SIM_FAULT_BAD_NAME, SIM_FAULT_IDROM_OFFSET_0,
	SIM_FAULT_IDROM_TYPE, SIM_FAULT_PORT_WIDTH, SIM_FAULT_IO_WIDTH, SIM_FAULT_IO_PORTS,
	SIM_FAULT_CLOCK_LOW, SIM_FAULT_CLOCK_HIGH, SIM_FAULT_PD_SENTINEL, SIM_FAULT_NO_IOPORT,
	SIM_FAULT_MD_INCONSISTENT, SIM_FAULT_CLOCK_TAG, SIM_FAULT_DUPLICATE_MD,
	SIM_FAULT_COUNT
};

struct sim_encoder {
	rtapi_u16 count, ts, latched;
	rtapi_u32 control;		/* bits 15..3 as written/updated */
	int pin_a, pin_b, pin_idx;	/* IO indices, -1 = none */
	int a, b, idx;			/* last sampled levels */
	int quad_error;
};

/* a quadrature counter bank: the plain encoder (GTag 4) or the muxed one (12) */
struct sim_qcount {
	rtapi_u32 base;			/* 0 = absent */
	int num, muxed;
	rtapi_u32 tsdiv, filter;
	struct sim_encoder enc[SIM_MAX_INST];
};

/* three-phase PWM (GTag 19): registers plus the fault latch */
struct sim_tppwm {
	rtapi_u32 value, enable, setup;
	int fault;			/* latched, clears enable */
	int pin_fault;
};

/* Buffered SPI (GTag 14): 16 channel descriptors, a TX FIFO of (data, descriptor)
 * and an RX FIFO; frames are shifted out at the descriptor's bit rate */
struct sim_bspi {
	rtapi_u32 cd[16];
	int cd_writes;			/* descriptors arrive #15 first, #0 last */
	rtapi_u32 tx[SIM_FIFO], tx_cd[SIM_FIFO], rx[SIM_FIFO];
	int tx_n, rx_n;
	rtapi_u64 busy_until;		/* ClockLow tick the frame in progress ends */
};

/* the Mesa 7i65 behind BSPI 0: two AD5754 DACs (CS1, CS2), an AD7329 ADC (CS3)
 * measuring the DAC outputs, a CPLD (CS4) with 8 amplifier enables, 4 digital inputs
 * and its own watchdog; CS0 loops data back */
struct sim_7i65 {
	rtapi_s16 dac[SIM_7I65_CHANNELS];	/* output codes, +-10 V full scale */
	int adc_next;			/* channel the next ADC result is for */
	rtapi_u32 enables;
	rtapi_u8 din[SIM_7I65_INPUTS];	/* from outside */
	rtapi_u64 last_cpld_tick;	/* its watchdog bites 50 ms after the last CPLD frame */
	int bitten;
};

/* UART (GTags 9/10) with a loop-back plug: bytes leave the TX FIFO at the TX bit rate
 * and arrive in the RX FIFO when the RX bit rate matches (else they are lost) */
struct sim_uart {
	rtapi_u8 tx[SIM_FIFO], rx[SIM_FIFO];
	int tx_n, rx_n;
	rtapi_u32 tx_rate, rx_rate, tx_mode, rx_mode;
	rtapi_u64 busy_until;
};

struct sim_stepgen {
	rtapi_u64 acc;			/* 48-bit accumulator, steps << 32 */
	rtapi_u32 rate, mode;
	int pin_step, pin_dir;
};

struct hm2_sim_model {
	const struct sim_layout *layout;
	rtapi_u32 mem[SIM_WORDS];	/* IDROM and every plain register */
	int num_pins;
	/* module bases from the layout (0 = absent) */
	rtapi_u32 base_ioport, base_watchdog, base_stepgen, base_tppwm, base_bspi;
	rtapi_u32 base_uart_tx, base_uart_rx;
	int num_stepgens, num_tppwm, num_bspi, num_uart;
	/* IOPort */
	rtapi_u32 data[SIM_MAX_PORTS], ddr[SIM_MAX_PORTS], alt[SIM_MAX_PORTS], od[SIM_MAX_PORTS];
	rtapi_u32 inv[SIM_MAX_PORTS];
	rtapi_u8 ext_in[SIM_MAX_PINS], level[SIM_MAX_PINS];
	/* watchdog */
	rtapi_u32 wd_timer, wd_reload, wd_status;
	/* encoders and stepgens */
	struct sim_qcount qc[2];	/* [0] plain, [1] muxed */
	rtapi_u8 mux_in[SIM_MAX_INST][3];	/* muxed encoder N's A, B, index from outside */
	int mux_sel;			/* the select output, toggling */
	int pin_mux_sel;
	struct sim_stepgen sg[SIM_MAX_INST];
	struct sim_tppwm tp[SIM_MAX_INST];
	struct sim_bspi bspi[2];
	struct sim_7i65 card;
	struct sim_uart uart[2];
	/* time */
	long long last_ns;
	rtapi_u64 ticks;		/* ClockLow cycles since start */
	rtapi_u32 frac_ns;		/* remainder of the ns -> ticks conversion */
	/* bus statistics (the bench reads them) */
	rtapi_u32 words_read, words_written, transactions;
};

const struct sim_layout *hm2_sim_layout_find(const char *board);
const char *hm2_sim_layout_names(void);		/* "5i25, 5i20" for messages */
/* the first layout with this many connectors of this width, or NULL */
const struct sim_layout *hm2_sim_layout_shaped(int ports, int port_width);
int hm2_sim_fault_find(const char *name);	/* enum sim_fault or -1 */
const char *hm2_sim_fault_names(void);

/* Build the register image of layout with one fault (SIM_FAULT_NONE for none). */
void hm2_sim_model_init(struct hm2_sim_model *m, const struct sim_layout *layout, int fault,
			long long now_ns);
void hm2_sim_model_advance(struct hm2_sim_model *m, long long now_ns);
/* the serial modules (hm2_sim_serial.c), called by the model */
void hm2_sim_serial_advance(struct hm2_sim_model *m);
int hm2_sim_serial_read(struct hm2_sim_model *m, rtapi_u32 addr, rtapi_u32 *v);
int hm2_sim_serial_write(struct hm2_sim_model *m, rtapi_u32 addr, rtapi_u32 v);
rtapi_u32 hm2_sim_model_read(struct hm2_sim_model *m, rtapi_u32 addr);
void hm2_sim_model_write(struct hm2_sim_model *m, rtapi_u32 addr, rtapi_u32 value);

#endif /* HM2_SIM_MODEL_H */

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_plx.c - PLX 9030 and 9054/9056 FPGA reset and programming (hm2_plx.h). */
#include "rtapi.h"
#include "hm2_plx.h"
#include "hm2_bitfile.h"

/* Old 5i20 EEPROMs leave READY# input disabled on the local spaces; HostMot2
 * answers with READY#, so every access would wait for the bridge's timeout. */
void hm2_plx9030_fix_ready(struct rtapi_pci_bar *ctrl, const char *name)
{
	int i;

	for (i = 0; i < 4; i++) {
		unsigned long reg = PLX9030_LAS0BRD + 4 * i;
		rtapi_u32 v = rtapi_pci_readl(ctrl, reg);

		if (!(v & PLX9030_LASBRD_READY)) {
			rtapi_print_msg(RTAPI_MSG_INFO, "%s: PLX 9030 LAS%dBRD had READY# off; "
					"turned on\n", name, i);
			rtapi_pci_writel(ctrl, reg, v | PLX9030_LASBRD_READY);
		}
	}
}

static void send_bitstream(struct rtapi_pci_bar *data, const rtapi_u8 *p, rtapi_u32 size)
{
	rtapi_u32 i;

	for (i = 0; i < size; i++)
		rtapi_pci_writeb(data, 0, hm2_bitfile_reverse(p[i]));
}

int hm2_plx9030_reset(struct rtapi_pci_bar *ctrl, const char *name)
{
	rtapi_u32 c = rtapi_pci_readl(ctrl, PLX9030_CTRL), s;
	int i;

	c = (c & ~PLX9030_PROGRAM) | PLX9030_WRITE | PLX9030_LED;
	rtapi_pci_writel(ctrl, PLX9030_CTRL, c);
	s = rtapi_pci_readl(ctrl, PLX9030_CTRL);
	if (s & (PLX9030_DONE | PLX9030_INIT)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: the FPGA did not reset: DONE %d, /INIT %d with "
				"/PROGRAM low (PLX 9030 GPIO 0x%08X)\n", name, !!(s & PLX9030_DONE),
				!!(s & PLX9030_INIT), s);
		return -EIO;
	}
	rtapi_pci_writel(ctrl, PLX9030_CTRL, c | PLX9030_PROGRAM);
	for (i = 0; i < PLX_INIT_POLLS; i++)
		if (rtapi_pci_readl(ctrl, PLX9030_CTRL) & PLX9030_INIT)
			return 0;
	rtapi_print_msg(RTAPI_MSG_ERR, "%s: the FPGA did not come out of /INIT after /PROGRAM\n",
			name);
	return -EIO;
}

int hm2_plx9030_program(struct rtapi_pci_bar *ctrl, struct rtapi_pci_bar *data,
			const rtapi_u8 *bitstream, rtapi_u32 size, const char *name)
{
	rtapi_u32 c = rtapi_pci_readl(ctrl, PLX9030_CTRL), s;
	const char *why = 0;

	/* /WRITE low enables the data port; /LED low lights the LED meanwhile */
	rtapi_pci_writel(ctrl, PLX9030_CTRL, c & ~(PLX9030_WRITE | PLX9030_LED));
	send_bitstream(data, bitstream, size);
	s = rtapi_pci_readl(ctrl, PLX9030_CTRL);
	if (!(s & PLX9030_INIT))
		why = "/INIT went low: CRC error in the bitstream";
	else if (!(s & PLX9030_DONE))
		why = "the FPGA did not assert DONE (not a bitstream for it, or in the wrong bit order)";
	c |= PLX9030_WRITE | PLX9030_LED;
	if (why) {
		/* leave it held in reset, unconfigured */
		rtapi_pci_writel(ctrl, PLX9030_CTRL, c & ~PLX9030_PROGRAM);
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: programming failed after %u bytes: %s\n", name,
				size, why);
		return -EIO;
	}
	rtapi_pci_writel(ctrl, PLX9030_CTRL, c);
	return 0;
}

int hm2_plx9054_reset(struct rtapi_pci_bar *ctrl, const char *name)
{
	rtapi_u32 c = rtapi_pci_readl(ctrl, PLX9054_CNTRL);
	int i;

	c |= PLX9054_USERI_IN | PLX9054_USERO_OUT;
	rtapi_pci_writel(ctrl, PLX9054_CNTRL, c);
	rtapi_pci_writel(ctrl, PLX9054_CNTRL, c & ~PLX9054_PROGRAM);
	if (rtapi_pci_readl(ctrl, PLX9054_CNTRL) & PLX9054_DONE) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: DONE stays high with /PROGRAM low: the FPGA "
				"cannot be reset (wrong I/O address?)\n", name);
		return -EIO;
	}
	rtapi_pci_writel(ctrl, PLX9054_CNTRL, c | PLX9054_PROGRAM);
	for (i = 0; i < PLX_INIT_POLLS; i++)	/* >= 100 us for the FPGA to clear */
		(void)rtapi_pci_readl(ctrl, PLX9054_DELAY_REG);
	return 0;
}

int hm2_plx9054_program(struct rtapi_pci_bar *ctrl, struct rtapi_pci_bar *data,
			const rtapi_u8 *bitstream, rtapi_u32 size, const char *name)
{
	int i;

	send_bitstream(data, bitstream, size);
	for (i = 0; i < PLX_DONE_POLLS; i++)
		if (rtapi_pci_readl(ctrl, PLX9054_CNTRL) & PLX9054_DONE)
			return 0;
	rtapi_print_msg(RTAPI_MSG_ERR, "%s: programming failed after %u bytes: the FPGA did not "
			"assert DONE (not a bitstream for it, or in the wrong bit order)\n", name, size);
	return -EIO;
}

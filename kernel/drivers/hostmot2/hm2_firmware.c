/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_firmware.c - the config string's firmware=F (hostmot2(9)): step 2 of
 * registration. F is fetched with rtapi_request_firmware (kernel flavor: the kernel's
 * firmware loader, /lib/firmware; simulated flavor: HAL_FIRMWARE_PATH, then the same
 * directories), parsed by the shared .BIT reader, its part name compared with the
 * board's FPGA, and handed to the board driver's reset and program_fpga (the board
 * bit-reverses the bytes for its configuration port). Boards that boot from flash
 * have no program_fpga: the keyword is then ignored with a note. Init code only. */
#include "rtapi.h"
#include "rtapi_string.h"
#include "rtapi_firmware.h"
#include "hal.h"
#include "hm2.h"
#include "hm2_bitfile.h"

int hm2_firmware_load(struct hostmot2 *hm2)
{
	struct hm2_llio *llio = hm2->llio;
	const char *name = hm2->cfg.firmware;
	const struct rtapi_firmware *fw;
	struct hm2_bitfile bf;
	char err[HM2_ERRLEN];
	int rc;

	if (!llio->program_fpga) {
		if (name[0])
			HM2_INFO(hm2, "firmware=%s ignored: this board runs the firmware in its flash "
				 "(change it with mesaflash)", name);
		return 0;
	}
	if (!name[0]) {
		HM2_WARN(hm2, "no firmware= given: the FPGA is not programmed and must still hold "
			 "a HostMot2 firmware from an earlier load");
		return 0;
	}
	rc = rtapi_request_firmware(&fw, name);
	if (rc == -ENOENT) {
		HM2_ERR(hm2, "firmware %s not found: install it as /lib/firmware/%s (simulated flavor: "
			"or in a directory of HAL_FIRMWARE_PATH)", name, name);
		return rc;
	}
	if (rc) {
		HM2_ERR(hm2, "firmware %s cannot be read (%d)", name, rc);
		return rc;
	}
	rc = hm2_bitfile_parse(fw->data, fw->size, &bf, err, sizeof(err));
	if (!rc)
		rc = hm2_bitfile_check_part(&bf, llio->fpga_part_number, err, sizeof(err));
	if (rc) {
		HM2_ERR(hm2, "firmware %s: %s", name, err);
		rtapi_release_firmware(fw);
		return rc;
	}
	HM2_INFO(hm2, "firmware %s: design '%s', part %s, built %s %s, %u bytes of bitstream", name,
		 bf.design, bf.part, bf.date, bf.time, bf.size);
	rc = llio->reset ? llio->reset(llio) : 0;
	if (rc)
		HM2_ERR(hm2, "firmware %s: the FPGA could not be reset for programming (%d)", name, rc);
	else {
		rc = llio->program_fpga(llio, bf.data, bf.size);
		if (rc)
			HM2_ERR(hm2, "firmware %s: programming the FPGA failed (%d)", name, rc);
	}
	rtapi_release_firmware(fw);
	return rc;
}

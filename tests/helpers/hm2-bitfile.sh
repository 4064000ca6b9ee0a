# hm2-bitfile.sh - sourced by the hostmot2 firmware tests (sh, also busybox): HAL
# ships no Mesa bitfiles, so the tests make their own Xilinx .BIT files.
#   hm2_bitfile NAME PART [KIND]  writes $HM2_FW_DIR/NAME (e.g. hm2/5i20/t.bit): the
#     13-byte header, chunks a/b/c/d, and chunk e holding a bitstream the simulated
#     configuration port accepts (dummy word, sync 0xAA995566, frame bytes, DESYNC).
#     KIND: good (default); reversed (every bitstream byte stored bit-reversed, so
#     after the driver's reversal the port sees the wrong bit order); short (cut in
#     the middle of the bitstream); badheader (first header byte wrong).
# The directory: the kernel's firmware_class.path in the kernel flavor (the test VM
# points it at a directory everyone may write), else $TEST_TMPDIR/firmware, exported
# as HAL_FIRMWARE_PATH for rtapi_app.
if [ "${HAL_TEST_FLAVOR:-sim}" = kernel ]; then
	HM2_FW_DIR=$(cat /sys/module/firmware_class/parameters/path)
else
	HM2_FW_DIR=${TEST_TMPDIR:-/tmp}/firmware
	export HAL_FIRMWARE_PATH=$HM2_FW_DIR
fi

hm2_bitfile() {
	mkdir -p "$(dirname "$HM2_FW_DIR/$1")"
	awk -v part="$2" -v kind="${3:-good}" 'function rev(b,  r, i) {
		r = 0
		for (i = 0; i < 8; i++) { r = r * 2 + b % 2; b = int(b / 2) }
		return r
	}
	function byte(b) { out = out sprintf("\\%03o", b) }
	function str(tag, s,  n, i) {
		n = length(s) + 1
		byte(tag); byte(int(n / 256)); byte(n % 256)
		for (i = 1; i <= length(s); i++) byte(ord[substr(s, i, 1)])
		byte(0)
	}
	BEGIN {
		for (i = 32; i < 127; i++) ord[sprintf("%c", i)] = i
		split("0 9 15 240 15 240 15 240 15 240 0 0 1", h, " ")
		if (kind == "badheader") h[1] = 1
		for (i = 1; i <= 13; i++) byte(h[i])
		str(97, "hm2test.ncd;UserID=0xFFFFFFFF"); str(98, part)
		str(99, "2026/11/24"); str(100, "12:00:00")
		n = split("255 255 255 255 170 153 85 102", s, " ")
		for (i = 0; i < 200; i++) s[++n] = (i * 37 + 11) % 256
		split("48 0 128 1 0 0 0 13", t, " ")
		for (i = 1; i <= 8; i++) s[++n] = t[i]
		byte(101); byte(0); byte(0); byte(int(n / 256)); byte(n % 256)
		if (kind == "short") n = n - 50
		for (i = 1; i <= n; i++) byte(kind == "reversed" ? rev(s[i]) : s[i])
		print out
	}' >"$HM2_FW_DIR/$1.esc"
	printf "$(cat "$HM2_FW_DIR/$1.esc")" >"$HM2_FW_DIR/$1"
	rm -f "$HM2_FW_DIR/$1.esc"
}

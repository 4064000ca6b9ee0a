# pluto-firmware.sh - sourced by the pluto_servo and pluto_step tests (sh, also
# busybox): HAL does not ship the Pluto-P images, so the tests make their own.
#   pluto_firmware FILE [SIZE]  writes a dummy image of SIZE bytes (default 19897, a
#     real .rbf's size) as FILE (pluto_servo.rbf or pluto_step.rbf) in the pluto/
#     directory the driver reads, and sets PLUTO_SUM to the config-sum the Pluto model
#     of sim_parport must report after an upload: the sum of (i + 1) * byte i over the
#     19895 bytes sent, mod 2^32.
#   pluto_no_firmware FILE  removes it again.
# The directory: the kernel's firmware_class.path in the kernel flavor (the test VM
# points it at a directory everyone may write), else $TEST_TMPDIR/firmware, exported
# as HAL_FIRMWARE_PATH for rtapi_app.
if [ "${HAL_TEST_FLAVOR:-sim}" = kernel ]; then
	PLUTO_FW_DIR=$(cat /sys/module/firmware_class/parameters/path)
else
	PLUTO_FW_DIR=${TEST_TMPDIR:-/tmp}/firmware
	export HAL_FIRMWARE_PATH=$PLUTO_FW_DIR
fi

pluto_firmware() {
	mkdir -p "$PLUTO_FW_DIR/pluto"
	# bytes 1..255 from a small LCG (no NUL: printf's escapes stay simple)
	awk -v n="${2:-19897}" 'BEGIN {
		x = 1; sum = 0
		for (i = 0; i < n; i++) {
			x = (x * 75 + 74) % 65537; b = 1 + x % 255
			printf "\\%03o", b
			if (i < 19895) sum += (i + 1) * b
		}
		printf " %.0f\n", sum % 4294967296
	}' >"$PLUTO_FW_DIR/pluto/$1.esc"
	read -r esc PLUTO_SUM <"$PLUTO_FW_DIR/pluto/$1.esc"
	printf "$esc" >"$PLUTO_FW_DIR/pluto/$1"
	rm -f "$PLUTO_FW_DIR/pluto/$1.esc"
}

pluto_no_firmware() {
	rm -f "$PLUTO_FW_DIR/pluto/$1"
}

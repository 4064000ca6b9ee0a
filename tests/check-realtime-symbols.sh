#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# Realtime code must build as kernel modules: it may only call RTAPI/HAL, and the
# few string/memory functions the kernel itself provides. This lists every
# undefined symbol of the realtime modules and of the HAL library objects and
# fails on anything else (a libc or libm call slipped in). Board drivers also call
# the hostmot2 core's exports (hm2_register, hm2_unregister, hm2_board_*); kinstest calls the loaded
# kinematics module's (kernel/kins/kinematics.h).
# Usage: check-realtime-symbols.sh RTLIB_DIR HAL_RT_ARCHIVE
set -u
rtlib=$1 archive=$2
allowed='^(rtapi_[a-z0-9_]+|hal_[a-z0-9_]+|hm2_register|hm2_unregister|hm2_board_(find|at|fits)|kinematics(Forward|Inverse|Home|Type|Switchable|Switch)|memcpy|memset|memmove|memcmp|strlen|strnlen|strcmp|strncmp|strcpy|strncpy|strchr|strrchr|strstr|strcat|strncat|__stack_chk_fail|__cxa_finalize|__gmon_start__|_ITM_[A-Za-z]+|_GLOBAL_OFFSET_TABLE_)$'
status=0
check() {	# $1 = what, stdin = undefined symbol names
	bad=$(sed 's/@.*//' | sort -u | grep -Ev "$allowed")
	if [ -n "$bad" ]; then
		echo "$1 calls outside RTAPI/HAL: $(echo $bad)"
		status=1
	fi
}
for so in "$rtlib"/*.so; do
	nm -D --undefined-only "$so" | awk '{print $NF}' | check "$(basename "$so")"
done
nm --undefined-only "$archive" 2>/dev/null | awk 'NF {print $NF}' | grep -v ':$' | check "$(basename "$archive")"
[ $status -eq 0 ] && echo "realtime code: only RTAPI/HAL and kernel-provided string functions"
exit $status

#!/bin/sh
# dkms-conf.sh MANIFEST - prints dkms.conf: one BUILT_MODULE entry for rtapi,
# hal_lib, rtapi_parport_linux and each module of modules.manifest, all built by kernel/Makefile.kmod
# into out/ against the kernel DKMS builds for. #MODULE_VERSION# is dh_dkms's.
set -eu
cat <<'HEAD'
PACKAGE_NAME="hal"
PACKAGE_VERSION="#MODULE_VERSION#"
MAKE[0]="make -f kernel/Makefile.kmod KDIR=${kernel_source_dir} KMOD_BUILD=out"
CLEAN="rm -rf out"
AUTOINSTALL="yes"
HEAD
i=0
for m in rtapi hal_lib rtapi_parport_linux $(awk '!/^[ \t]*(#|$)/ { print $1 }' "$1"); do
	printf 'BUILT_MODULE_NAME[%d]="%s"\nBUILT_MODULE_LOCATION[%d]="out/"\nDEST_MODULE_LOCATION[%d]="/updates/dkms"\n' \
		$i "$m" $i $i
	i=$((i + 1))
done

#!/bin/sh
# kmod-deps-check.sh DIR - the kernel flavor's module dependencies (modinfo depends=,
# what modprobe loads first) in the built *.ko of DIR:
#  - no module depends on a kinematics module (one exporting kinematicsForward): they
#    are interchangeable, motion finds the loaded one at run time (kernel/kins/kins_bind.h),
#    and a recorded dependency would make modprobe load one of them by name;
#  - motmod depends on the RTAPI and HAL modules only.
# Exit 1 naming each offender. Run by tests/kernel/run-kernel-tests.sh after the build.
dir=${1:?usage: kmod-deps-check.sh DIR}
command -v modinfo >/dev/null || { echo "kmod-deps-check: modinfo not found (kmod)" >&2; exit 2; }
kins=
for ko in "$dir"/*.ko; do
	[ -e "$ko" ] || { echo "kmod-deps-check: no .ko in $dir" >&2; exit 2; }
	if nm "$ko" 2>/dev/null | grep -q ' __ksymtab_kinematicsForward$'; then
		kins="$kins $(basename "$ko" .ko)"
	fi
done
rc=0
for ko in "$dir"/*.ko; do
	name=$(basename "$ko" .ko)
	deps=$(modinfo -F depends "$ko" | tr ',' ' ')
	for d in $deps; do
		case " $kins " in *" $d "*)
			echo "kmod-deps-check: $name depends on the kinematics module $d" >&2
			rc=1 ;;
		esac
		if [ "$name" = motmod ]; then
			case $d in rtapi|hal_lib) ;; *)
				echo "kmod-deps-check: motmod depends on $d (only rtapi and hal_lib allowed)" >&2
				rc=1 ;;
			esac
		fi
	done
done
[ $rc = 0 ] && echo "kmod-deps-check: no module depends on a kinematics module ($(echo $kins | wc -w) of them); motmod: rtapi, hal_lib only"
exit $rc

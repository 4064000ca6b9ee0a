#!/bin/sh
# check-near.sh RESULT WANT - the kinematics cases' checkresult: every line "NAME VALUE
# [TOL]" of WANT needs a line "NAME GOT" in RESULT (the last one) with |GOT - VALUE| <=
# TOL (default 2e-6: kinematics.md's vectors have six decimals); a WANT line "= TEXT"
# needs the line TEXT verbatim.
# Prints what is missing or off; exit 0 when nothing is.
awk -v tol=2e-6 '
	FNR == NR { if ($1 == "=") { sub(/^= /, ""); text[$0] = 1 } else { want[$1] = $2; tol_of[$1] = NF > 2 ? $3 : tol }; next }
	{ seen[$0] = 1; if (NF == 2) got[$1] = $2 }
	END {
		bad = 0
		for (t in text) if (!(t in seen)) { print "missing line: " t; bad = 1 }
		for (n in want) {
			if (!(n in got)) { print "missing: " n; bad = 1; continue }
			d = got[n] - want[n]
			if (d < 0) d = -d
			if (d > tol_of[n] + 0) { print n ": " got[n] ", want " want[n]; bad = 1 }
		}
		exit bad
	}' "$2" "$1"

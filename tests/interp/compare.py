#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
# compare.py EXPECTED ACTUAL - line by line; the text between numbers must be equal,
# numbers may differ by 2e-4 (gcode.md 16 gives some values rounded). Prints the first
# difference; exit status 1 if any.
import re
import sys

NUM = re.compile(r'-?\d+\.\d+|-?\d+')


def split(line):
    return NUM.split(line), [float(n) for n in NUM.findall(line)]


want = open(sys.argv[1]).read().splitlines()
got = open(sys.argv[2]).read().splitlines()
for i in range(max(len(want), len(got))):
    w = want[i] if i < len(want) else '<missing>'
    g = got[i] if i < len(got) else '<missing>'
    wt, wn = split(w)
    gt, gn = split(g)
    if wt != gt or len(wn) != len(gn) or any(abs(a - b) > 2e-4 for a, b in zip(wn, gn)):
        print('line %d differs:\n  expected: %s\n  got:      %s' % (i + 1, w, g))
        sys.exit(1)

halrun -k -f alias.hal 2>&1 | sed -E 's#(memory: +)[0-9]+/[0-9]+#\1USED/TOTAL#'

# Code addresses and argument pointers differ from run to run.
halrun -f show.hal 2>&1 | sed -E 's/[0-9a-f]{16}/XXXXXXXXXXXXXXXX/g'

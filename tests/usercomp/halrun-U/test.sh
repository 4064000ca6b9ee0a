# halrun -U stops running userspace components (SIGTERM, waits) before it unloads
# the realtime side; a halrun file's own loadusr components go at the end of the run.
halcmd loadusr -W hal_testcomp a
halcmd loadusr -W hal_testcomp b
pa=$(halcmd -s show comp a | awk '{ print $4 }')
pb=$(halcmd -s show comp b | awk '{ print $4 }')
halrun -U
echo "halrun -U: $?"
kill -0 "$pa" 2>/dev/null && echo "a still running" || echo "a gone"
kill -0 "$pb" 2>/dev/null && echo "b still running" || echo "b gone"
printf 'loadusr -Wn c hal_testcomp c\nshow comp c\n' > "${TEST_TMPDIR:-/tmp}/u.hal"
halrun -f "${TEST_TMPDIR:-/tmp}/u.hal" | sed 's/  *[0-9][0-9]*  *ready/ PID ready/; s/^ *[0-9][0-9]* /ID /'
echo "halrun -f: $?"
halrun -f /dev/null
echo "halrun again: $?"

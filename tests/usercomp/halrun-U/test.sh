# halrun -U stops running userspace components (SIGTERM, waits) before it unloads
# the realtime side; a halrun file's own loadusr components go at the end of the run.
# gone: no such process, or a zombie (exited; its parent, init here, may reap it late
# or, in some containers, never)
gone() { ! kill -0 "$1" 2>/dev/null || [ "$(sed 's/.*) //' "/proc/$1/stat" 2>/dev/null | cut -c1)" = Z ]; }
halcmd loadusr -Wn a hal_testcomp a
halcmd loadusr -Wn b hal_testcomp b
pa=$(halcmd -s show comp a | awk '{ print $4 }')
pb=$(halcmd -s show comp b | awk '{ print $4 }')
halrun -U
echo "halrun -U: $?"
gone "$pa" && echo "a gone" || echo "a still running"
gone "$pb" && echo "b gone" || echo "b still running"
printf 'loadusr -Wn c hal_testcomp c\nshow comp c\n' > "${TEST_TMPDIR:-/tmp}/u.hal"
halrun -f "${TEST_TMPDIR:-/tmp}/u.hal" | sed 's/  *[0-9][0-9]*  *ready/ PID ready/; s/^ *[0-9][0-9]* /ID /'
echo "halrun -f: $?"
halrun -f /dev/null
echo "halrun again: $?"

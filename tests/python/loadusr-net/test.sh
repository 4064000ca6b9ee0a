# A Python userspace component started with loadusr -Wn, netted between realtime
# components running in a thread: constant -> pydouble (Python) -> abs, not.
# wait_for PIN VALUE: poll (up to 10 s) until getp PIN prints VALUE.
wait_for() {
	i=0
	while [ "$(halcmd getp "$1")" != "$2" ] && [ $i -lt 200 ]; do sleep 0.05; i=$((i + 1)); done
	echo "$1 = $(halcmd getp "$1")"
}
halcmd loadrt threads name1=t period1=1000000
halcmd loadrt constant
halcmd loadrt abs
halcmd loadrt not
halcmd addf constant.0 t
halcmd addf abs.0 t
halcmd addf not.0 t
halcmd setp constant.0.value -1.25
halcmd start
halcmd loadusr -Wn pydouble python3 pydouble.py
echo "loadusr: $?"
halcmd -s show comp pydouble | awk '{ print $2, $3, $5 }'
halcmd -s show pin pydouble | awk '{ print $2, $3, $5 }'
halcmd -s show param pydouble | awk '{ print $2, $3, $5 }'
halcmd net a constant.0.out pydouble.in
halcmd net b pydouble.out abs.0.in
halcmd net neg pydouble.negative not.0.in
wait_for abs.0.out 2.5
wait_for not.0.out FALSE
halcmd setp pydouble.gain -3
wait_for abs.0.out 3.75
wait_for not.0.out TRUE
halcmd getp pydouble.out
# the pin is driven by a signal: halcmd refuses, exit 1
halcmd setp pydouble.in 1
echo "setp linked input: $?"
# the same name again: a second Python process gets hal.error and exits 1
halcmd loadusr -w python3 pydouble.py 2> "$TEST_TMPDIR/err"
echo "second pydouble: $?"
grep -v '^ ' "$TEST_TMPDIR/err" | grep -v '^Traceback'
echo "listed: $(halcmd -s show comp pydouble | wc -l)"
halcmd unloadusr pydouble
echo "unloadusr: $?"
echo "after unloadusr: $(halcmd -s show comp pydouble | wc -l) listed"
halcmd -s show sig | awk '{ print $1, $3 }'
halrun -U
echo "halrun -U: $?"

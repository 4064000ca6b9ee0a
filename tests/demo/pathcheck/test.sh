# toolpath_check finds what is wrong: a sampled path within the G64 P tolerance passes;
# a corner cut too far, an arc run the wrong way, a program not run to its end and lost
# samples fail; bad input gets exit 2 and a message naming file and line.
for s in good cut cw half overrun; do
	echo "== $s"
	toolpath_check check path.canon $s.samples
	echo "exit $?"
done
echo "== cut, TOL 0.2 given"
toolpath_check check path.canon cut.samples 0.2
echo "exit $?"
echo "== no tolerance in the program"
toolpath_check check notol.canon good.samples 2>&1
echo "exit $?"
echo "== bad input"
toolpath_check check bad.canon good.samples 2>&1
echo "exit $?"
toolpath_check check path.canon short.samples 2>&1
echo "exit $?"
toolpath_check check path.canon 2>&1
echo "exit $?"
toolpath_check path path.canon 0 0 zero 2>&1
echo "exit $?"
echo "== path"
toolpath_check path path.canon 0 0 0 | sed -n '1,3p;$p'
toolpath_check path path.canon 0 0 0 | wc -l | tr -d ' '

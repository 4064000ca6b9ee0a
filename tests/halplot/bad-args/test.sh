halplot -o chart.jpg; echo "exit $?"
halplot -n 1; echo "exit $?"
halplot -s 10x10; echo "exit $?"
halplot -c; echo "exit $?"
halplot nonsense; echo "exit $?"
halplot -n 10 -o "$TEST_TMPDIR/x.svg"; echo "no sampler: exit $?"
halcmd loadrt sampler cfg=f depth=10
halplot -n 10 -o "$TEST_TMPDIR/x.svg"; echo "not on a thread: exit $?"
halrun -U

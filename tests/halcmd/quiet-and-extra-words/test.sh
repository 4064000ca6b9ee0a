# -Q prints nothing at all, even for a failing command (its exit status still says so);
# words after "-f FILE" are ignored (halcmd(1)).
halrun -Q -f cmds.hal
echo "exit $?"
halrun -f cmds.hal these words are ignored
echo "exit $?"

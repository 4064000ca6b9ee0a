# Lines with a NUL used to be cut at it: 'setp siggen.0.offset 2\0005' set 2.
printf 'loadrt siggen\nsetp siggen.0.offset 2\0005\nsetp siggen.0.offset\000junk 1\necho \033[2Jcleared\ngetp siggen.0.offset\n' > "$TEST_TMPDIR/nul.hal"
{ halrun -k -f "$TEST_TMPDIR/nul.hal"; echo "exit $?"; } 2>&1 | sed "s|$TEST_TMPDIR/||"
# a directory is not an empty file
{ halcmd -f "$TEST_TMPDIR"; echo "exit $?"; } 2>&1 | sed "s|$TEST_TMPDIR|TMP|"
{ printf 'source %s\necho not reached\n' "$TEST_TMPDIR" | halcmd; echo "exit $?"; } 2>&1 | sed "s|$TEST_TMPDIR|TMP|"
# an endless line stops at the bound instead of growing without end
halcmd -f /dev/zero
echo "exit $?"
# an unknown command full of escape sequences is named, not played to the terminal
printf '\033]0;title\007x\n' | halcmd
echo "exit $?"
# non-ASCII names are refused for what they are
halcmd newsig caf$(printf '\303\251') bit
echo "exit $?"

# shuttlexpress --help (and -h) prints the usage on stdout and exits 0 instead of
# taking it for a device; a device that is not there still exits 1.
shuttlexpress --help
echo "exit $?"
shuttlexpress -h >/dev/null
echo "-h exit $?"
shuttlexpress /nonexistent/hidraw9 2>&1
echo "missing device exit $(shuttlexpress /nonexistent/hidraw9 >/dev/null 2>&1; echo $?)"

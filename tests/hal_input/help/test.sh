# hal_input --help (and -h) prints the usage on stdout and exits 0 without looking
# for devices or joining the HAL; a bad option still exits 1 with the usage on stderr.
hal_input --help
echo "exit $?"
hal_input -h >/dev/null
echo "-h exit $?"
hal_input -X foo 2>&1 | head -n 1
echo "bad option exit $(hal_input -X foo >/dev/null 2>&1; echo $?)"

# Every load-time refusal of hal_parport prints one message and leaves nothing
# loaded: bad addresses, too many or no ports, a port busy (twice in cfg), a range
# straddling a device; afterwards the port is free for a good load.
halrun -k -f errors.hal
echo "exit $?"

# halstreamer without a streamer FIFO: one line on stderr, exit status 1.
halstreamer -c 2 < /dev/null
echo "exit $?"
halstreamer -c 8 < /dev/null
echo "exit $?"

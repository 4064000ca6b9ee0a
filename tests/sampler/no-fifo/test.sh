# halsampler without a sampler FIFO: one line on stderr, exit status 1.
halsampler -c 3 -n 1
echo "exit $?"

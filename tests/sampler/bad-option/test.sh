# Bad options: a message, the usage, exit status 1.
halsampler -c 9
echo "exit $?"
halsampler -q
echo "exit $?"

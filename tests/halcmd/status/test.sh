halrun status lock
halrun status mem | sed -E 's#(memory: +)[0-9]+/[0-9]+#\1USED/TOTAL#'
halrun status bogus
echo "exit $?"

halrun status lock
halrun status mem | sed -E 's#[0-9]+/[0-9]+#USED/TOTAL#'
halrun status bogus
echo "exit $?"

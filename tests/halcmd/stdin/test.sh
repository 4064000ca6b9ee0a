printf 'echo from stdin\n\nsetp nosuch 1\necho not reached\n' | halrun -f
echo "exit $?"
printf 'echo a\nbogus\necho b\n' | halrun -k
echo "exit $?"

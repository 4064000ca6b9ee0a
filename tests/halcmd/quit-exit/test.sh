printf 'echo a\nexit\necho b\n' | halrun -f
echo "exit $?"

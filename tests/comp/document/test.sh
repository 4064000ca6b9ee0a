# comp --document writes the man page of lowpass.comp (date masked: it is today's).
set -e
tmp=${TEST_TMPDIR:-$(mktemp -d)}
comp --document -o "$tmp/lowpass.9" ../../../kernel/components/lowpass.comp
sed 's/"9" "[0-9-]*"/"9" "DATE"/' "$tmp/lowpass.9"

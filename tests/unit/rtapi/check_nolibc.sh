#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-or-later
# check_nolibc.sh OBJ... - fail when an object needs a symbol from outside RTAPI
# (libc, libm, libgcc): the kernel flavor links the same code without them.
# Allowed: what the kernel exports as well (memset, memcpy, memmove, memcmp, strlen:
# gcc turns plain loops into calls to them; the stack protector's __stack_chk_fail)
# and the instrumentation of sanitizer builds (__asan_*, __ubsan_*).
status=0
passed=0
failed=0
for obj in "$@"; do
  if ! undef=$(nm -u "$obj"); then
    echo "$obj: nm failed"
    failed=$((failed + 1))
    continue
  fi
  bad=$(echo "$undef" | awk 'NF {print $NF}' |
        grep -v -E '^(_GLOBAL_OFFSET_TABLE_|__stack_chk_fail|mem(set|cpy|move|cmp)|strlen)$' |
        grep -v -E '^(rtapi_|rtm_|__asan_|__ubsan_|__sanitizer_)')
  if [ -n "$bad" ]; then
    echo "$(basename "$obj") needs symbols from outside RTAPI:" $bad
    failed=$((failed + 1))
  else
    echo "$(basename "$obj"): needs nothing from libc, libm or libgcc"
    passed=$((passed + 1))
  fi
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]

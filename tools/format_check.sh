#!/usr/bin/env bash
# Checks (default) or applies (--fix) the project's C++ style (.clang-format) on every .cpp and
# .hpp file under src/, verification/ and tests/. The check names each file that differs and
# exits 1; `make format` fixes them.
#   tools/format_check.sh [--fix]
set -eu
files=$(find src verification tests \( -name '*.cpp' -o -name '*.hpp' \) | LC_ALL=C sort)
if [ "${1:-}" = --fix ]; then
  exec clang-format -i --style=file $files
fi
# One clang-format for all files: it reports each line that differs as "FILE:LINE:COL: error".
bad=$(clang-format --dry-run --Werror --style=file $files 2>&1 | sed -n 's/^\([^:]*\.[ch]pp\):[0-9]*:[0-9]*: error.*/\1/p' | sort -u)
for f in $bad; do echo "format: $f differs from .clang-format (make format fixes it)"; done
echo "format: $(echo "$files" | wc -l) files, $(echo -n "$bad" | grep -c . || true) not in the project's style"
[ -z "$bad" ]

#!/usr/bin/env bash
# The C API under fuzzing: `make install` into a temporary prefix, build
# test/integration/capi_fuzz.c.in (C) against it with -fsanitize=address,undefined (the installed
# header and shared library, as a C host does), run it.  The program asserts the
# contract of include/hertzdamp.h (see its header) over random and adversarial
# doubles; a sanitizer report or a crash ends it without its summary line, which
# run_tests.sh counts as a failure.
set -u
cd "$(dirname "$0")/../.."
name=capi_fuzz
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix
if ! make --no-print-directory install PREFIX="$prefix" >"$tmp/install.log" 2>&1; then
  tail -n 20 "$tmp/install.log"; echo "FAIL $name: make install"; echo "$name: 0 passed, 1 failed"; exit 1
fi
cc=${CC:-cc}
if ! "$cc" -std=c99 -O1 -g -Wall -Wextra -Werror -fsanitize=address,undefined -fno-sanitize-recover=undefined \
     -x c test/integration/capi_fuzz.c.in -x none -I"$prefix/include" -L"$prefix/lib" -Wl,-rpath,"$prefix/lib" -lhertzdamp -lm \
     -o "$tmp/capi_fuzz" >"$tmp/cc.log" 2>&1; then
  cat "$tmp/cc.log"; echo "FAIL $name: compile test/integration/capi_fuzz.c.in"; echo "$name: 0 passed, 1 failed"; exit 1
fi
# the Fortran runtime is not instrumented: no leak report for its own allocations
ASAN_OPTIONS=detect_leaks=0:abort_on_error=0 UBSAN_OPTIONS=print_stacktrace=1 "$tmp/capi_fuzz" 300000

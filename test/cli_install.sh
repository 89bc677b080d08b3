#!/usr/bin/env bash
# `make install` into a temporary prefix, then use it the way a non-fpm user does:
# layout, no GSL/BLAS/LAPACK in the core, header constants equal to the Fortran ones,
# the legacy Fortran 77 and C examples built with only their documented link lines,
# and their numbers against the module API (bit-identical) and the targets.
# Also: a failing install leaves the prefix untouched.
set -u
cd "$(dirname "$0")/.."
root=$PWD
name=cli_install
passed=0; failed=0
check() {  # label, command...
  local label=$1; shift
  if "$@" >/dev/null 2>&1; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL $name: $label"; fi
}
finish() { echo "$name: $passed passed, $failed failed"; [ "$failed" -eq 0 ]; exit; }

fpm=${HERTZDAMP_FPM:-}
[ -n "$fpm" ] || { [ -x .venv/bin/fpm ] && fpm=$root/.venv/bin/fpm; } || true
[ -n "$fpm" ] || fpm=$(command -v fpm || true)
case "$fpm" in /*) ;; ?*) fpm=$root/$fpm ;; esac
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix

# ------------------------------------------------------------ install and layout
if ! make --no-print-directory install PREFIX="$prefix" FPM="$fpm" >"$tmp/install.log" 2>&1; then
  cat "$tmp/install.log"; check "make install" false; finish
fi
check "make install" true
for f in lib/libhertzdamp.a lib/libhertzdamp.so include/hertzdamp.h include/hertzdamp/hertzdamp.mod \
         include/hertzdamp/hertzdamp_capi.mod lib/pkgconfig/hertzdamp.pc; do
  check "installed $f" test -s "$prefix/$f"
done
check "installed bin/hertzdamp" test -x "$prefix/bin/hertzdamp"
check "no staging directory left" test -z "$(find "$prefix" -name '.hertzdamp-install*')"
check "GSL peer not installed" test ! -e "$prefix/include/hertzdamp/hertzdamp_gsl.mod"
check "GSL peer not in the archive" bash -c "! ar t '$prefix/lib/libhertzdamp.a' | grep -q gsl"
if [ -n "${HERTZDAMP_BIN:-}" ] && [ -x "${HERTZDAMP_BIN:-}" ]; then
  check "installed CLI equals the built one" cmp <("$prefix/bin/hertzdamp" constants) <("$HERTZDAMP_BIN" constants)
fi

# ------------------------------------------------------------ symbols
undef=$(nm -u "$prefix/lib/libhertzdamp.a" | awk 'NF == 2 {print $2}' | sort -u)
check "archive: no GSL/CBLAS symbols" bash -c "! grep -Eq '^(gsl_|cblas_)' <<<'$undef'"
check "archive: no LAPACK/BLAS symbols" bash -c "! grep -Eq '^(dgesv_|dgels|dgetr|dpotr|dsyev|dgemm_|dgemv_|ddot_|daxpy_)' <<<'$undef'"
check "archive: needs only hertzdamp, libgfortran, libgcc helpers and libc/libm" bash -c \
  "! grep -Evq '^(__hertzdamp_|_gfortran_|__gfortran|__ieee_[a-z_]+_MOD_|__[a-z]+[0-9][a-z0-9]*|_GLOBAL_OFFSET_TABLE_|[a-z][a-z0-9_]*$)' <<<'$undef'"
check "shared library: no libgsl/liblapack/libblas" bash -c "! ldd '$prefix/lib/libhertzdamp.so' | grep -Eq 'libgsl|liblapack|libblas|libopenblas'"
dyn=$(nm -D --defined-only "$prefix/lib/libhertzdamp.so" | awk '{print $3}')
for sym in hertzdamp_invert hertzdamp_forward hertzdamp_strerror hertzdamp_invert_ hertzdamp_forward_ \
           hertzdamp_invert_n_ hertzdamp_message_; do
  check "shared library exports $sym" grep -qx "$sym" <<<"$dyn"
done

# ------------------------------------------------------------ header constants = Fortran constants
hdr=$(sed -nE 's/^#define (HD_[A-Z_]+) +([0-9]+).*/\1=\2/p' include/hertzdamp.h | sort)
fortran=$(sed -nE 's/.*integer, parameter, public :: (HD_[A-Z_]+) = ([0-9]+).*/\1=\2/p' src/hertzdamp_status.f90 | sort)
check "hertzdamp.h #defines equal hertzdamp_status" test "$hdr" = "$fortran"
check "hertzdamp.h has the status codes" test "$(wc -l <<<"$hdr")" -ge 20

# ------------------------------------------------------------ examples with their documented link lines
cp -r example/legacy_dem example/c "$tmp/"
check "legacy example builds (make PREFIX=...)" make --no-print-directory -C "$tmp/legacy_dem" PREFIX="$prefix"
check "C example builds (make PREFIX=...)" make --no-print-directory -C "$tmp/c" PREFIX="$prefix"
"$tmp/legacy_dem/dem" >"$tmp/legacy.out" 2>&1; check "legacy example runs" test $? -eq 0
"$tmp/c/dem_c" >"$tmp/c.out" 2>&1; check "C example runs" test $? -eq 0
check "C example: no rebound reported with status 1" grep -q '^# k = 1, d = 2, m = 1, u = 1: status 1 (no rebound' "$tmp/c.out"
check "legacy example: 5 contacts" test "$(grep -c '^contact' "$tmp/legacy.out")" -eq 5
check "C example: 5 contacts" test "$(grep -c '^contact' "$tmp/c.out")" -eq 5
# achieved ratio near the target 0.8 (10 steps per contact: O(dt^2) stepping error, gravity);
# predicted e and T_c from hertzdamp_forward equal the targets
check "legacy example: achieved v_out/u_in within 0.1 of e" \
  awk '/^contact/ { if ($6 < 0.7 || $6 > 0.9) bad = 1; n++ } END { exit (bad || n != 5) }' "$tmp/legacy.out"
check "legacy example: forward gives back e and T_c (1e-9)" \
  awk '/^contact/ { if (($8 - 0.8)^2 > 1e-18*0.64 || ($9/1e-4 - 1)^2 > 1e-18) bad = 1 } END { exit bad }' "$tmp/legacy.out"

# The same k, d from three routes for every (e, T_c, m, u_in) of the legacy run:
# legacy external (the run above), C API (./dem_c e tc m u), module API (checker).
cat >"$tmp/checker.f90" <<'F90'
program checker
    use hertzdamp, only: hertzdamp_rk, hertzdamp_invert
    use hertzdamp_flat, only: legacy_method
    implicit none
    real(hertzdamp_rk) :: e, tc, m, u, k, d
    integer :: status
    character(len=64) :: arg
    call get_command_argument(1, arg); read (arg, *) e
    call get_command_argument(2, arg); read (arg, *) tc
    call get_command_argument(3, arg); read (arg, *) m
    call get_command_argument(4, arg); read (arg, *) u
    call hertzdamp_invert(e, tc, m, u, 0, k, d, status, method=legacy_method)
    if (status /= 0) error stop 1
    write (*, '(es25.16e3, 1x, es25.16e3)') k, d
end program checker
F90
check "module checker builds against the installed .mod files" \
  gfortran -I"$prefix/include/hertzdamp" "$tmp/checker.f90" -L"$prefix/lib" -Wl,-rpath,"$prefix/lib" -lhertzdamp \
  -o "$tmp/checker"
while read -r _ _ u k d _; do
  read -r kc dc _ < <("$tmp/c/dem_c" 0.8 1e-4 1e-3 "$u")
  read -r km dm < <("$tmp/checker" 0.8 1e-4 1e-3 "$u")
  check "u_in = $u: C API k, d bit-identical to legacy" awk -v a="$k" -v b="$kc" -v c="$d" -v e="$dc" \
    'BEGIN { exit !(a + 0 == b + 0 && c + 0 == e + 0) }'
  check "u_in = $u: module API k, d bit-identical to legacy" awk -v a="$k" -v b="$km" -v c="$d" -v e="$dm" \
    'BEGIN { exit !(a + 0 == b + 0 && c + 0 == e + 0) }'
done < <(grep '^contact' "$tmp/legacy.out")

# the modern-API example, compiled against the installed modules
check "example_invert builds against the installed prefix" gfortran -I"$prefix/include/hertzdamp" \
  example/example_invert.f90 -L"$prefix/lib" -Wl,-rpath,"$prefix/lib" -lhertzdamp -o "$tmp/example_invert"
"$tmp/example_invert" >"$tmp/example_invert.out" 2>&1
check "example_invert runs" test $? -eq 0
check "example_invert: e = 0.7, T_c = 10 dt (longer where k_phys is used), 5 contacts" awk \
  'NR > 1 { n++; if ($7 != "0.70000000" || ($6 == "F" && $8 != "10.00000") || ($6 == "T" && $8 <= 10)) bad = 1 }
   END { exit (bad || n != 5) }' \
  "$tmp/example_invert.out"
check "example_invert: the k_phys bound is active for some contacts, not all" \
  awk 'NR > 1 { t += ($6 == "T"); f += ($6 == "F") } END { exit !(t > 0 && f > 0) }' "$tmp/example_invert.out"

# static archive and pkg-config link lines
check "C example links the static archive" make --no-print-directory -C "$tmp/c" -B PREFIX="$prefix" \
  LDLIBS="$prefix/lib/libhertzdamp.a -lgfortran -lm"
check "static C example: no libhertzdamp.so needed" bash -c "! ldd '$tmp/c/dem_c' | grep -q libhertzdamp"
"$tmp/c/dem_c" >"$tmp/c_static.out" 2>&1
check "static C example: same output" cmp "$tmp/c.out" "$tmp/c_static.out"
if command -v pkg-config >/dev/null; then
  pc=$(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --cflags --libs --static hertzdamp | xargs)
  check "pkg-config flags" test "$pc" = "-I$prefix/include -I$prefix/include/hertzdamp -L$prefix/lib -lhertzdamp -lgfortran -lm"
  # shellcheck disable=SC2086
  check "C example builds with pkg-config" cc -O2 "$tmp/c/dem.c" $pc -Wl,-rpath,"$prefix/lib" -o "$tmp/dem_pc"
fi

# ------------------------------------------------------------ a failed install changes nothing
bad=$tmp/badprefix; mkdir -p "$bad" "$tmp/fakebin"; echo keep >"$bad/sentinel"
printf '#!/bin/sh\necho "\tlibgsl.so.27 => /usr/lib/libgsl.so.27"\n' >"$tmp/fakebin/ldd"; chmod +x "$tmp/fakebin/ldd"
PATH="$tmp/fakebin:$PATH" bash tools/install.sh "$fpm" "-O3 -march=x86-64-v2 -funroll-loops -fPIC" "$bad" >"$tmp/bad.log" 2>&1
check "install refuses a core that links GSL" test $? -ne 0
check "failed install leaves the prefix as it was" test "$(cd "$bad" && find . -mindepth 1)" = "./sentinel"

finish

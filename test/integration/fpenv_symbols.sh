#!/usr/bin/env bash
# No entry point of the installed library saves and restores the floating-point
# environment on each call (issue 11).  gfortran inserts calls to
# _gfortran_ieee_procedure_entry / _gfortran_ieee_procedure_exit (about 250 ns a call)
# into every procedure whose own scope sees a symbol of an IEEE intrinsic module, and
# a `use` of any library module inside an external subroutine brings such symbols
# along (src/hertzdamp_capi.f90 explains).  This builds and installs the core with
# CMake, as `make install` does, disassembles the installed shared and static
# libraries, and fails if any function in them calls those routines: the legacy
# externals (hertzdamp_invert_ ...), the C functions (hertzdamp_c_*) and every module
# procedure.  A fixture with the pattern that caused it first shows that the check
# sees such calls with this compiler.
set -u
cd "$(dirname "$0")/../.."
passed=0; failed=0
check() {  # label, condition status (0 = pass)
  if [ "$2" -eq 0 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL fpenv_symbols: $1"; fi
}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# functions of an object or library that call the save/restore routines
offenders() {
  objdump -dr --no-show-raw-insn "$1" 2>/dev/null | awk '
    /^[0-9a-f]+ <[^>]*>:$/ { fn = $2; gsub(/[<>:]/, "", fn) }
    /_gfortran_ieee_procedure_(entry|exit)/ { if (!(fn in seen)) { seen[fn] = 1; print fn } }'
}

# ---- the check sees the pattern: an external that uses a module which uses ieee_arithmetic
cat >"$tmp/fixture.f90" <<'EOF'
module fixture_ieee
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
contains
    pure real(8) function finite_or_zero(x)
        real(8), intent(in) :: x
        finite_or_zero = merge(x, 0.0d0, ieee_is_finite(x))
    end function finite_or_zero
end module fixture_ieee
subroutine fixture_external(x, y)
    use fixture_ieee, only: finite_or_zero
    implicit none
    real(8), intent(in) :: x
    real(8), intent(out) :: y
    y = finite_or_zero(x)
end subroutine fixture_external
EOF
(cd "$tmp" && gfortran -O3 -fPIC -c fixture.f90 -o fixture.o) 2>/dev/null
check "fixture compiles" $?
check "the check finds the save/restore in an external that uses such a module" \
  $(offenders "$tmp/fixture.o" | grep -qx 'fixture_external_'; echo $?)

# ---- the installed library (core only: the program is not needed here)
prefix=$tmp/prefix
cmake -S . -B "$tmp/build" -DCMAKE_INSTALL_PREFIX="$prefix" -DHERTZDAMP_BUILD_CLI=OFF >"$tmp/cmake.log" 2>&1 &&
  cmake --build "$tmp/build" -j 2 >>"$tmp/cmake.log" 2>&1 && cmake --install "$tmp/build" >>"$tmp/cmake.log" 2>&1
rc=$?
check "cmake build and install of the core (see log below)" $rc
[ "$rc" -eq 0 ] || tail -n 20 "$tmp/cmake.log"
so=$(find "$prefix" -name 'libhertzdamp.so' | head -n 1)
ar=$(find "$prefix" -name 'libhertzdamp.a' | head -n 1)
check "installed shared library present" $([ -n "$so" ]; echo $?)
check "installed static library present" $([ -n "$ar" ]; echo $?)

if [ -n "$so" ] && [ -n "$ar" ]; then
  exported=$(nm -D --defined-only "$so" | awk '$2 == "T" { print $3 }')
  for name in hertzdamp_invert_ hertzdamp_invert_bounded_ hertzdamp_pair_ hertzdamp_forward_ hertzdamp_invert_n_ \
              hertzdamp_invert_law_ hertzdamp_pair_law_ hertzdamp_forward_law_ hertzdamp_c_invert_law \
              hertzdamp_c_pair_law hertzdamp_c_forward_law hertzdamp_c_invert_law_n hertzdamp_invert_law_n_ \
              hertzdamp_c_pair_init hertzdamp_c_pair_kd hertzdamp_pair_init_ hertzdamp_pair_kd_ \
              hertzdamp_c_pair_stats hertzdamp_c_host_min_steps \
              hertzdamp_message_ hertzdamp_c_invert hertzdamp_c_invert_bounded hertzdamp_c_invert_n \
              hertzdamp_c_pair hertzdamp_c_forward hertzdamp_c_strerror; do
    check "entry point $name exported" $(grep -qx "$name" <<<"$exported"; echo $?)
  done
  for lib in "$so" "$ar"; do
    bad=$(offenders "$lib" | sort -u)
    check "no function of $(basename "$lib") calls _gfortran_ieee_procedure_entry/exit${bad:+ (found in: $(tr '\n' ' ' <<<"$bad"))}" \
      $([ -z "$bad" ]; echo $?)
    # and the library does not even reference them
    check "$(basename "$lib") has no undefined reference to the save/restore routines" \
      $(nm "$lib" 2>/dev/null | grep -q 'U _gfortran_ieee_procedure_'; [ $? -ne 0 ]; echo $?)
  done
fi

echo "fpenv_symbols: $passed passed, $failed failed"
[ "$failed" -eq 0 ]

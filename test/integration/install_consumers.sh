#!/usr/bin/env bash
# `make install` into a temporary prefix, then use the installed core every way a
# DEM code does: plain flags (legacy fixed form, C shared and static), pkg-config
# (shared with rpath, static archive), CMake find_package (modern Fortran, C with the
# archive, a fixed-form host built the MFiX way: host archive first, --as-needed),
# CMake pkg_check_modules, the legacy include file (and the type errors it must
# catch), an fpm path dependency; and the MFiX layout (issue 21): the calls in a
# static library of a subdirectory under an old cmake_minimum_required, the host
# installed, with the README's CMP0079 and rpath settings (and without them).  Checks the layout, that the core holds no
# application or peer code and needs only the Fortran runtime, the header constants,
# and the numbers of every route against the module API (bit for bit).
# A failing install leaves the prefix untouched.
set -u
cd "$(dirname "$0")/../.."
root=$PWD
name=install_consumers
passed=0; failed=0
check() {  # label, command...
  local label=$1; shift
  if "$@" >"$tmp/check.log" 2>&1; then passed=$((passed + 1)); else
    failed=$((failed + 1)); echo "FAIL $name: $label"; head -n 15 "$tmp/check.log" | sed 's/^/    /'; fi
}
finish() { echo "$name: $passed passed, $failed failed"; [ "$failed" -eq 0 ]; exit; }

fpm=${HERTZDAMP_FPM:-$root/.venv/bin/fpm}
case "$fpm" in /*) ;; *) fpm=$root/$fpm ;; esac
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix

# ------------------------------------------------------------ install and layout
if ! make --no-print-directory install PREFIX="$prefix" >"$tmp/install.log" 2>&1; then
  cat "$tmp/install.log"; check "make install" false; finish
fi
check "make install" true
# one source of the release flags (issue 31): the installed library is compiled with the
# flags of data/release_flags.txt, which the Makefile hands to fpm (what the benchmarks run)
want_flags=$(make -s --no-print-directory --eval='print-flags: ; @echo $(RELEASE_FLAGS)' print-flags)
check "CMake compiles the core with the Makefile's RELEASE_FLAGS ($want_flags)" \
  grep -qF "Fortran_FLAGS = $want_flags -" build/cmake/CMakeFiles/hertzdamp_objects.dir/flags.make
check "the Makefile's RELEASE_FLAGS are data/release_flags.txt's" test "$want_flags" = "$(grep -v '^#' data/release_flags.txt)"
for f in lib/libhertzdamp.a lib/libhertzdamp.so lib/libhertzdamp.so.0 include/hertzdamp.h include/hertzdamp.fi \
         include/hertzdamp/hertzdamp.mod include/hertzdamp/hertzdamp_capi.mod lib/pkgconfig/hertzdamp.pc \
         lib/pkgconfig/hertzdamp-static.pc lib/cmake/hertzdamp/hertzdampConfig.cmake \
         lib/cmake/hertzdamp/hertzdampConfigVersion.cmake lib/cmake/hertzdamp/hertzdampTargets.cmake \
         share/man/man1/hertzdamp.1; do
  check "installed $f" test -s "$prefix/$f"
done
check "installed bin/hertzdamp" test -x "$prefix/bin/hertzdamp"
# a fresh clone has no build/ yet: the install must create its build directory's parent
# before CMake writes its logs beside it.  tools/install.sh's own steps (the parent, the
# logs, the staging, the runtime check, the copy) run against a stand-in cmake that
# configures nothing and installs the tree just built by CMake above (a second real
# build of the same sources took about a minute of the 15-minute budget)
mkdir -p "$tmp/stub"
cat >"$tmp/stub/cmake" <<'STUB'
#!/usr/bin/env bash
# stand-in cmake: -S . -B DIR -DCMAKE_INSTALL_PREFIX=P | --build DIR ... | --install DIR
case $1 in
  -S) dir=$4; mkdir "$dir" && printf '%s\n' "${5#-DCMAKE_INSTALL_PREFIX=}" >"$dir/prefix" ;;
  --build) test -s "$2/prefix" ;;
  --install) to=$DESTDIR$(cat "$2/prefix"); mkdir -p "$to" && cp -a "$HERTZDAMP_STUB_TREE/." "$to/" ;;
  *) exit 2 ;;
esac
STUB
chmod +x "$tmp/stub/cmake"
check "install into a build directory whose parent does not exist (stand-in cmake)" \
  env PATH="$tmp/stub:$PATH" HERTZDAMP_STUB_TREE="$prefix" bash tools/install.sh "$tmp/prefix_fresh" "$tmp/fresh/build/cmake"
check "... its parent and CMake's logs beside the build directory were made" \
  test -d "$tmp/fresh/build/cmake" -a -f "$tmp/fresh/build/cmake.configure.log" -a -f "$tmp/fresh/build/cmake.build.log"
check "fresh install has the library" test -s "$tmp/prefix_fresh/lib/libhertzdamp.so.0"
check "man page renders" bash -c "man -l '$prefix/share/man/man1/hertzdamp.1' 2>/dev/null | grep -q hertzdamp || \
  groff -man -Tascii '$prefix/share/man/man1/hertzdamp.1' | grep -q hertzdamp"
check "no staging directory left in the prefix" test -z "$(find "$prefix" -name '*stage*')"
if [ -n "${HERTZDAMP_BIN:-}" ] && [ -x "${HERTZDAMP_BIN:-}" ]; then
  check "installed CLI equals the fpm-built one (constants)" \
    cmp <("$prefix/bin/hertzdamp" constants --format csv) <("$HERTZDAMP_BIN" constants --format csv)
fi

# ------------------------------------------------------------ the core holds the core only
# only the public modules are installed (issue 31): the umbrella and the C binding; the
# module checker below builds with them alone
installed_modules=$(cd "$prefix/include/hertzdamp" && ls ./*.mod | sed 's|^\./||; s|\.mod$||' | sort | xargs)
check "installed modules = the public ones (hertzdamp, hertzdamp_capi)" test "$installed_modules" = "hertzdamp hertzdamp_capi"
defined=$(nm --defined-only "$prefix/lib/libhertzdamp.a" 2>/dev/null | awk 'NF == 3 {print $3}')
check "archive: no DEM engine, scene reader or GSL peer symbols" \
  bash -c "! grep -Eiq 'hertzdamp_(dem|scene|gsl)' <<<'$defined'"
defined_so=$(nm -D --defined-only "$prefix/lib/libhertzdamp.so" | awk '{print $3}')
check "shared library: no DEM engine, scene reader or GSL peer symbols" \
  bash -c "! grep -Eiq 'hertzdamp_(dem|scene|gsl)' <<<'$defined_so'"
undef=$(nm -u "$prefix/lib/libhertzdamp.a" | awk 'NF == 2 {print $2}' | sort -u)
check "archive: needs only libgfortran, libgcc helpers and libc/libm" bash -c \
  "! grep -Evq '^(__hertzdamp_|_gfortran_|__gfortran|__ieee_[a-z_]+_MOD_|__[a-z]+[0-9][a-z0-9]*|_GLOBAL_OFFSET_TABLE_|[a-z][a-z0-9_]*$)' <<<'$undef'"
check "archive: no GSL, CBLAS, LAPACK or BLAS symbols" \
  bash -c "! grep -Eq '^(gsl_|cblas_|dgesv_|dgels|dgetr|dpotr|dsyev|dgemm_|dgemv_|ddot_|daxpy_)' <<<'$undef'"
needed=$(readelf -d "$prefix/lib/libhertzdamp.so" | sed -nE 's/.*\(NEEDED\).*\[(.*)\]/\1/p' | sort | xargs)
check "shared library needs only the Fortran runtime and libc/libm ($needed)" \
  bash -c "! tr ' ' '\n' <<<'$needed' | grep -Ev '^(libgfortran|libquadmath|libm\.|libc\.|libgcc_s)'"
check "shared library has soname libhertzdamp.so.0" \
  bash -c "readelf -d '$prefix/lib/libhertzdamp.so' | grep -q 'SONAME.*libhertzdamp.so.0'"
for sym in hertzdamp_c_invert hertzdamp_c_invert_bounded hertzdamp_c_invert_n hertzdamp_c_pair hertzdamp_c_forward \
           hertzdamp_c_strerror hertzdamp_invert_ hertzdamp_invert_bounded_ hertzdamp_pair_ hertzdamp_forward_ \
           hertzdamp_invert_n_ hertzdamp_message_ hertzdamp_c_invert_law hertzdamp_c_pair_law hertzdamp_c_forward_law \
           hertzdamp_invert_law_ hertzdamp_pair_law_ hertzdamp_forward_law_ hertzdamp_c_invert_law_n \
           hertzdamp_invert_law_n_ hertzdamp_c_pair_init hertzdamp_c_pair_kd hertzdamp_pair_init_ hertzdamp_pair_kd_ \
           hertzdamp_c_pair_stats hertzdamp_c_host_min_steps; do
  check "shared library exports $sym" grep -qx "$sym" <<<"$defined_so"
done
# the C names never equal a legacy name without gfortran's underscore (-fno-underscoring)
# (the legacy link names end in gfortran's underscore: their names without it)
legacy=$( (grep -hoiE '^ *subroutine +hertzdamp_[a-z_]+' src/hertzdamp_legacy.f90 | awk '{print tolower($2)}';
          sed -nE "s/.*bind\(c, name='(hertzdamp_[a-z_]+)_'\).*/\1/p" src/hertzdamp_capi.f90) | sort -u)
cnames=$(sed -nE "s/.*bind\(c, name='(hertzdamp_c_[a-z_]+)'\).*/\1/p" src/hertzdamp_capi.f90 src/hertzdamp_pair.f90)
check "the legacy and C names were found" test "$(wc -w <<<"$legacy $cnames")" -ge 24
check "no C name equals a legacy external's name" bash -c "! grep -Fxq -f <(echo '$legacy') <<<'$cnames'"

# ------------------------------------------------------------ header constants = Fortran constants
hdr=$(sed -nE 's/^#define HERTZDAMP_([A-Z_]+) +([0-9]+).*/\1=\2/p' include/hertzdamp.h | grep -v '^PAIR_SIZE=' | sort)
# (every code a C caller passes or gets: statuses, contact ends, laws, hosts; not the
# Fortran-only method and integrator codes)
fortran=$(sed -nE 's/.*integer, parameter, public :: HD_([A-Z_]+) = ([0-9]+).*/\1=\2/p' src/*.f90 |
          grep -Ev '^(METHOD|MODEL|EVENT)_' | sort -u)
check "hertzdamp.h HERTZDAMP_* equal the library's HD_* codes (status, end, law, host)" test "$hdr" = "$fortran"
# the pair's size: the header's HERTZDAMP_PAIR_SIZE is the module's hertzdamp_pair_size
check "hertzdamp.h HERTZDAMP_PAIR_SIZE = hertzdamp_pair_size of the registry" test \
  "$(sed -nE 's/^#define HERTZDAMP_PAIR_SIZE +([0-9]+).*/\1/p' include/hertzdamp.h)" = \
  "$(sed -nE 's/.*integer, parameter, public :: hertzdamp_pair_size = ([0-9]+).*/\1/p' src/hertzdamp_registry.f90)"
check "hertzdamp.h has the status codes" test "$(wc -l <<<"$hdr")" -ge 20
check "hertzdamp.h: no unprefixed macro" bash -c "! grep -E '^#define ' include/hertzdamp.h | grep -Ev '^#define HERTZDAMP_'"
check "hertzdamp.h compiles as C99 and C++ with -Wall -Werror" bash -c \
  "echo '#include <hertzdamp.h>' | cc -std=c99 -Wall -Wextra -Werror -I'$prefix/include' -fsyntax-only -x c - &&
   echo '#include <hertzdamp.h>' | c++ -Wall -Wextra -Werror -I'$prefix/include' -fsyntax-only -x c++ -"

# ------------------------------------------------------------ examples with their documented link lines
cp -r example/legacy_dem example/c "$tmp/"
check "legacy example builds (make PREFIX=...)" make --no-print-directory -C "$tmp/legacy_dem" PREFIX="$prefix"
check "legacy example: its Makefile passes include/ (hertzdamp.fi), not the module directory" \
  bash -c "make -n -B -C '$tmp/legacy_dem' PREFIX=/P | grep -q -- '-I/P/include dem.f' && \
           ! make -n -B -C '$tmp/legacy_dem' PREFIX=/P | grep -q -- '-I/P/include/hertzdamp'"
check "C example builds (make PREFIX=...)" make --no-print-directory -C "$tmp/c" PREFIX="$prefix"
"$tmp/legacy_dem/dem" >"$tmp/legacy.out" 2>&1; check "legacy example runs" test $? -eq 0
"$tmp/c/dem_c" >"$tmp/c.out" 2>&1; check "C example runs" test $? -eq 0
check "C example: no rebound reported with status 1" grep -q '^# k = 1, d = 2, m = 1, u = 1: status 1 (no rebound' "$tmp/c.out"
check "legacy example: 5 contacts" test "$(grep -c '^contact' "$tmp/legacy.out")" -eq 5
check "C example: 5 contacts" test "$(grep -c '^contact' "$tmp/c.out")" -eq 5
# achieved ratio near the target 0.8 (10 steps per contact, first-order damping, gravity);
# predicted e and T_c from hertzdamp_forward equal the targets to the fit's accuracy
check "legacy example: achieved v_out/u_in within 0.1 of e" \
  awk '/^contact/ { if ($6 < 0.7 || $6 > 0.9) bad = 1; n++ } END { exit (bad || n != 5) }' "$tmp/legacy.out"
check "legacy example: forward gives back e and T_c (1e-12)" \
  awk '/^contact/ { if (($8 / 0.8 - 1)^2 > 1e-24 || ($9/1e-4 - 1)^2 > 1e-24) bad = 1 } END { exit bad }' "$tmp/legacy.out"
# its explicit Euler loop (MFiX's EULER) over 1000 onset phases, e = 0.5, N = 10: with
# HERTZDAMP_PAIR_INIT(IHOST = 2) the mean e and T_c within 1e-3 of the targets, and the
# phase sampling allows it (variation / phases, the bound of its error, below 1e-3);
# with IHOST = 0 (the continuous constants) they miss by more than 1e-3
# (fields: 3 ihost, 5 phases, 7 steps, then after four labels 12 e_err, 13 tc_err, 14 e_var/n, 15 tc_var/n)
check "legacy example: Euler loop, IHOST = 2: mean e and T_c within 1e-3 over 1000 phases" \
  awk '/^euler ihost +2 / { n++; if ($5 != 1000 || $12^2 > 1e-6 || $13^2 > 1e-6 || $14 > 1e-3 || $15 > 1e-3) bad = 1 }
       END { exit (bad || n != 1) }' "$tmp/legacy.out"
check "legacy example: Euler loop, IHOST = 0: the continuous constants miss e or T_c by more than 1e-3" \
  awk '/^euler ihost +0 / { n++; if ($12^2 <= 1e-6 && $13^2 <= 1e-6) bad = 1 } END { exit (bad || n != 1) }' "$tmp/legacy.out"
# the same loop with per-contact constants (HERTZDAMP_PAIR_INIT_PHASE, HERTZDAMP_ONSET_PHASE,
# HERTZDAMP_PAIR_KD_PHASE; issue 32): every single contact's e and T_c within 1e-5 over
# 1000 phases, e = 0.2, 0.5, 0.9, N = 10 and 20 (measured: 5.1e-9 and 1.5e-9 at most)
# (fields: 3 e, 5 phases, 7 steps, 10 max_e_err, 11 max_tc_err)
check "legacy example: Euler loop, phase form: every contact's e and T_c within 1e-5 over 1000 phases" \
  awk '/^euler-phase / { n++; if ($5 != 1000 || $10 > 1e-5 || $11 > 1e-5) bad = 1 } END { exit (bad || n != 6) }' \
  "$tmp/legacy.out"

# The same k, d from three routes for every (e, T_c, m, u_in) of the legacy run:
# legacy external (the run above), C API (./dem_c e tc m u), module API (checker).
cat >"$tmp/checker.f90" <<'F90'
program checker
    use hertzdamp, only: hertzdamp_rk, hertzdamp_invert
    implicit none
    real(hertzdamp_rk) :: e, tc, m, u, k, d
    integer :: status
    character(len=64) :: arg
    call get_command_argument(1, arg); read (arg, *) e
    call get_command_argument(2, arg); read (arg, *) tc
    call get_command_argument(3, arg); read (arg, *) m
    call get_command_argument(4, arg); read (arg, *) u
    call hertzdamp_invert(e, tc, m, u, 0, k, d, status)
    if (status /= 0) error stop 1
    write (*, '(es25.16e3, 1x, es25.16e3)') k, d
end program checker
F90
check "module checker builds against the installed .mod files (-I flags)" \
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
check "example_invert runs" "$tmp/example_invert"

# ------------------------------------------------------------ the new C entry points, from C
cat >"$tmp/capi.c" <<'C'
#include <math.h>
#include <stdio.h>
#include <hertzdamp.h>
/* pair constants + the two inline formulas reproduce hertzdamp_c_invert to 1e-14;
   the bounded call keeps k_phys where it is the softer; the array call is the scalar
   call bit for bit; NULL pointers give HERTZDAMP_BAD_ARGUMENT. */
int main(void) {
    const double es[4] = {1.0, 0.9, 0.5, 0.05}, us[4] = {0.01, 1.0, 3.0, 20.0};
    const double m = 2e-6, tc = 1e-5;
    int bad = 0;
    for (int end = HERTZDAMP_END_OVERLAP; end <= HERTZDAMP_END_FORCE; end++)
        for (int i = 0; i < 4; i++) {
            double alpha, tau, k, d, kb, db, kn[1], dn[1];
            int st[1];
            if (hertzdamp_c_pair(es[i], end, &alpha, &tau) != HERTZDAMP_OK) bad |= 1;
            if (hertzdamp_c_invert(es[i], tc, m, us[i], end, &k, &d) != HERTZDAMP_OK) bad |= 2;
            double kf = m * pow(tau / tc, 2.5) / sqrt(us[i]), df = alpha * m * tau / tc;
            if (fabs(kf / k - 1) > 1e-14 || (d > 0 ? fabs(df / d - 1) > 1e-14 : df != 0)) bad |= 4;
            /* bound far above: same as unbounded, bit for bit; far below: k = k_phys */
            if (hertzdamp_c_invert_bounded(es[i], tc, m, us[i], 1e6 * k, end, &kb, &db) != HERTZDAMP_OK ||
                kb != k || db != d) bad |= 8;
            if (hertzdamp_c_invert_bounded(es[i], tc, m, us[i], 1e-3 * k, end, &kb, &db) != HERTZDAMP_OK ||
                kb != 1e-3 * k || (alpha > 0 &&
                fabs(db / (alpha * pow(m, 0.6) * pow(kb, 0.4) * pow(us[i], 0.2)) - 1) > 1e-13)) bad |= 16;
            if (hertzdamp_c_invert_n(1, &es[i], &tc, &m, &us[i], end, kn, dn, st) != HERTZDAMP_OK ||
                st[0] != 0 || kn[0] != k || dn[0] != d) bad |= 32;
        }
    double a, t;
    if (hertzdamp_c_pair(0.5, 0, &a, NULL) != HERTZDAMP_BAD_ARGUMENT) bad |= 64;
    if (hertzdamp_c_pair(2.0, 0, &a, &t) != HERTZDAMP_BAD_RESTITUTION || a != 0 || t != 0) bad |= 128;
    /* damping laws: law 0 = the linear calls bit for bit; the pair formulas of the law
       reproduce hertzdamp_c_invert_law; forward_law gives back e and tc; bad law code */
    for (int law = HERTZDAMP_DAMPING_LINEAR; law <= HERTZDAMP_DAMPING_KUWABARA_KONO; law++)
        for (int end = HERTZDAMP_END_OVERLAP; end <= HERTZDAMP_END_FORCE; end++)
            for (int i = 1; i < 4; i++) {
                const double q = 0.25 * law;
                double alpha, tau, k, d, k0, d0, e, tcb, kn[1], dn[1];
                int st[1];
                if (hertzdamp_c_invert_law(es[i], tc, m, us[i], 0.0, law, end, &k, &d) != HERTZDAMP_OK ||
                    hertzdamp_c_pair_law(es[i], law, end, &alpha, &tau) != HERTZDAMP_OK) bad |= 256;
                double ts = tc / tau, kf = m * pow(ts, -2.5) / sqrt(us[i]), df = alpha * m / ts / pow(us[i] * ts, q);
                if (fabs(kf / k - 1) > 1e-14 || fabs(df / d - 1) > 1e-14) bad |= 512;
                if (law == HERTZDAMP_DAMPING_LINEAR &&
                    (hertzdamp_c_invert(es[i], tc, m, us[i], end, &k0, &d0) != HERTZDAMP_OK || k0 != k || d0 != d))
                    bad |= 1024;
                if (hertzdamp_c_forward_law(k, d, m, us[i], law, end, &e, &tcb) != HERTZDAMP_OK ||
                    fabs(e / es[i] - 1) > 1e-12 || fabs(tcb / tc - 1) > 1e-12) bad |= 2048;
                if (hertzdamp_c_invert_law_n(1, &es[i], &tc, &m, &us[i], law, end, kn, dn, st) != HERTZDAMP_OK ||
                    st[0] != 0 || kn[0] != k || dn[0] != d) bad |= 8192;
            }
    if (hertzdamp_c_invert_law(0.5, tc, m, 1.0, 0.0, 3, 0, &a, &t) != HERTZDAMP_BAD_LAW) bad |= 4096;
    printf("%d\n", bad);
    return bad != 0;
}
C
check "C program using the new entry points builds (C99, -Wall -Werror)" cc -std=c99 -Wall -Wextra -Werror \
  "$tmp/capi.c" -I"$prefix/include" -L"$prefix/lib" -Wl,-rpath,"$prefix/lib" -lhertzdamp -lm -o "$tmp/capi"
check "C: pair formulas, bounded, array and damping-law entry points agree with hertzdamp_c_invert" "$tmp/capi"

# ------------------------------------------------------------ the per-pair API three ways, bit for bit
# The same grid (laws, contact ends, hosts none and lammps, e, contacts with and without
# the bound, a bad speed) through C (hertzdamp_c_pair_init/_kd), a fixed-form caller through
# hertzdamp.fi (HERTZDAMP_PAIR_INIT/_KD with REAL(8) PAIR(HERTZDAMP_PAIR_SIZE)) and the module
# API (hertzdamp_pair_init/_kd): every status, the eight doubles of the pair's header, k and d
# printed as bit patterns, and the three outputs compared byte for byte.
cat >"$tmp/pair.c" <<'C'
#include <stdio.h>
#include <string.h>
#include <hertzdamp.h>
static void hex(double x) { unsigned long long b; memcpy(&b, &x, sizeof b); printf(" %016llX", b); }
int main(void) {
    const double es[3] = {0.9, 0.5, 0.1}, tcs[3] = {1e-5, 1e-40, 3e-4}, ms[3] = {2e-6, 1.0, 1e35},
                 us[3] = {0.5, 3.0, -1e-3}, kps[3] = {0.0, 1e3, -1.0};
    for (int host = HERTZDAMP_HOST_NONE; host <= HERTZDAMP_HOST_LAMMPS; host++)
        for (int law = 0; law <= 2; law++)
            for (int end = 0; end <= 1; end++)
                for (int i = 0; i < 3; i++) {
                    hertzdamp_pair_t p;
                    int st = hertzdamp_c_pair_init(es[i], law, end, host, 20.0, &p);
                    printf("%d", st);
                    for (int j = 0; j < 8; j++) hex(p.v[j]);
                    printf("\n");
                    for (int c = 0; c < 3; c++)
                        for (int b = 0; b < 3; b++) {
                            double k, d;
                            st = hertzdamp_c_pair_kd(&p, tcs[c], ms[c], us[c], kps[b], &k, &d);
                            printf("%d", st); hex(k); hex(d); printf("\n");
                        }
                }
    return 0;
}
C
cat >"$tmp/pair.f" <<'F'
      PROGRAM PAIRF
      IMPLICIT NONE
      INCLUDE 'hertzdamp.fi'
      DOUBLE PRECISION ES(3), TCS(3), MS(3), US(3), KPS(3)
      REAL(8) PAIR(HERTZDAMP_PAIR_SIZE)
      DOUBLE PRECISION K, D
      INTEGER IHOST, ILAW, IEND, I, C, B, IERR, J
      DATA ES /0.9D0, 0.5D0, 0.1D0/, TCS /1D-5, 1D-40, 3D-4/
      DATA MS /2D-6, 1D0, 1D35/, US /0.5D0, 3D0, -1D-3/
      DATA KPS /0D0, 1D3, -1D0/
      DO IHOST = 0, 1
      DO ILAW = 0, 2
      DO IEND = 0, 1
      DO I = 1, 3
        CALL HERTZDAMP_PAIR_INIT(ES(I), ILAW, IEND, IHOST, 20D0, PAIR,
     &                           IERR)
        WRITE (*, '(I0,8(1X,Z16.16))') IERR, (PAIR(J), J = 1, 8)
        DO C = 1, 3
        DO B = 1, 3
          CALL HERTZDAMP_PAIR_KD(PAIR, TCS(C), MS(C), US(C), KPS(B),
     &                           K, D, IERR)
          WRITE (*, '(I0,2(1X,Z16.16))') IERR, K, D
        END DO
        END DO
      END DO
      END DO
      END DO
      END DO
      END
F
cat >"$tmp/pairm.f90" <<'F90'
program pairm
    use hertzdamp, only: hertzdamp_rk, hertzdamp_pair_t, hertzdamp_pair_init, hertzdamp_pair_kd
    implicit none
    integer, parameter :: wp = hertzdamp_rk
    real(wp), parameter :: es(3) = [0.9_wp, 0.5_wp, 0.1_wp], tcs(3) = [1e-5_wp, 1e-40_wp, 3e-4_wp], &
                           ms(3) = [2e-6_wp, 1.0_wp, 1e35_wp], us(3) = [0.5_wp, 3.0_wp, -1e-3_wp], &
                           kps(3) = [0.0_wp, 1e3_wp, -1.0_wp]
    type(hertzdamp_pair_t) :: p
    real(wp) :: k, d
    integer :: host, law, iend, i, c, b, st
    do host = 0, 1
        do law = 0, 2
            do iend = 0, 1
                do i = 1, 3
                    call hertzdamp_pair_init(es(i), law, iend, host, 20.0_wp, p, st)
                    write (*, '(i0,8(1x,z16.16))') st, p%alpha, p%tau_c, p%alpha_cont, p%steps, p%law, p%iend, &
                        p%host, p%marker
                    do c = 1, 3
                        do b = 1, 3
                            if (kps(b) > 0.0_wp) then
                                call hertzdamp_pair_kd(p, tcs(c), ms(c), us(c), k, d, st, k_phys=kps(b))
                            else
                                call hertzdamp_pair_kd(p, tcs(c), ms(c), us(c), k, d, st)
                            end if
                            write (*, '(i0,2(1x,z16.16))') st, k, d
                        end do
                    end do
                end do
            end do
        end do
    end do
end program pairm
F90
check "per-pair C client builds (C99, -Wall -Werror)" cc -std=c99 -Wall -Wextra -Werror "$tmp/pair.c" \
  -I"$prefix/include" -L"$prefix/lib" -Wl,-rpath,"$prefix/lib" -lhertzdamp -o "$tmp/pair_c"
check "per-pair fixed-form client builds through hertzdamp.fi (-Wall -Werror)" gfortran -Wall -Werror \
  -I"$prefix/include" "$tmp/pair.f" -L"$prefix/lib" -Wl,-rpath,"$prefix/lib" -lhertzdamp -o "$tmp/pair_f"
check "per-pair module client builds" gfortran -I"$prefix/include/hertzdamp" "$tmp/pairm.f90" -L"$prefix/lib" \
  -Wl,-rpath,"$prefix/lib" -lhertzdamp -o "$tmp/pair_m"
"$tmp/pair_c" >"$tmp/pair_c.out" 2>&1; "$tmp/pair_f" >"$tmp/pair_f.out" 2>&1; "$tmp/pair_m" >"$tmp/pair_m.out" 2>&1
check "per-pair: 360 records, successes and failures among them" bash -c \
  "test \$(wc -l <'$tmp/pair_m.out') -eq 360 && grep -q '^0 ' '$tmp/pair_m.out' && grep -qv '^0 ' '$tmp/pair_m.out'"
check "per-pair: C = module, bit for bit (statuses, the pair header, k, d)" cmp "$tmp/pair_c.out" "$tmp/pair_m.out"
check "per-pair: fixed form through hertzdamp.fi = module, bit for bit" cmp "$tmp/pair_f.out" "$tmp/pair_m.out"

# ------------------------------------------------------------ the _n functions under aliasing
# A result array over an input array: in place (d over tc) and shifted by -3 .. 3 elements
# (k over e), three passes of 256 contacts: the results of separate arrays, bit for bit.
cat >"$tmp/alias.c" <<'C'
#include <stdio.h>
#include <string.h>
#include <hertzdamp.h>
#define N 700
int main(void) {
    static double e[N], tc[N], m[N], u[N], k[N], d[N], buf[2 * N], t2[N];
    static int st[N], st2[N];
    int bad = 0;
    for (int i = 0; i < N; i++) {
        e[i] = 0.05 + 0.9 * (i % 97) / 97.0; tc[i] = 1e-5 * (1 + i % 7); m[i] = 1e-3 * (1 + i % 5);
        u[i] = 0.1 * (1 + i % 11);
    }
    for (int law = 0; law <= 2; law++) {
        hertzdamp_c_invert_law_n(N, e, tc, m, u, law, 0, k, d, st);
        for (int shift = -3; shift <= 3; shift++) {
            double *E = buf + N / 2, *K = E + shift;
            memcpy(E, e, sizeof e);
            memcpy(t2, tc, sizeof tc);
            hertzdamp_c_invert_law_n(N, E, t2, m, u, law, 0, K, t2, st2);
            for (int i = 0; i < N; i++)
                if (memcmp(&K[i], &k[i], 8) || memcmp(&t2[i], &d[i], 8) || st2[i] != st[i]) bad++;
        }
    }
    printf("%d\n", bad);
    return bad != 0;
}
C
check "aliasing client builds (-fsanitize=address)" cc -std=c99 -Wall -Werror -fsanitize=address "$tmp/alias.c" \
  -I"$prefix/include" -L"$prefix/lib" -Wl,-rpath,"$prefix/lib" -lhertzdamp -o "$tmp/alias"
check "_law_n with k over e shifted by -3..3 and d over tc in place: the bits of separate arrays, in bounds" \
  env ASAN_OPTIONS=detect_leaks=0 "$tmp/alias"

# ------------------------------------------------------------ static archive and pkg-config
check "C example links the static archive" make --no-print-directory -C "$tmp/c" -B PREFIX="$prefix" \
  LDLIBS="$prefix/lib/libhertzdamp.a -lgfortran -lm"
check "static C example: no libhertzdamp.so needed" bash -c "! ldd '$tmp/c/dem_c' | grep -q libhertzdamp"
"$tmp/c/dem_c" >"$tmp/c_static.out" 2>&1
check "static C example: same output" cmp "$tmp/c.out" "$tmp/c_static.out"
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
v_fpm=$(sed -nE 's/^version *= *"([^"]+)".*/\1/p' fpm.toml)
check "pkg-config version = fpm.toml ($v_fpm)" test "$(pkg-config --modversion hertzdamp)" = "$v_fpm"
check "CMake package version = fpm.toml" grep -q "PACKAGE_VERSION \"$v_fpm\"" "$prefix/lib/cmake/hertzdamp/hertzdampConfigVersion.cmake"
# shellcheck disable=SC2046
check "pkg-config (shared): C example builds (it uses libm itself)" cc -O2 "$tmp/c/dem.c" $(pkg-config --cflags --libs hertzdamp) \
  -lm -o "$tmp/dem_pc"
check "pkg-config (shared): runs from any directory, libhertzdamp.so found by rpath" \
  bash -c "cd / && env -u LD_LIBRARY_PATH '$tmp/dem_pc' | grep -q '^contact'"
# shellcheck disable=SC2046
check "pkg-config (static): C example builds" cc -O2 "$tmp/c/dem.c" $(pkg-config --cflags --libs hertzdamp-static) \
  -o "$tmp/dem_pcs"
check "pkg-config (static): the archive is linked (no libhertzdamp.so needed)" \
  bash -c "! ldd '$tmp/dem_pcs' | grep -q libhertzdamp && '$tmp/dem_pcs' | grep -q '^contact'"
# shellcheck disable=SC2046
check "pkg-config (shared): fixed-form legacy example builds and runs" bash -c \
  "gfortran '$tmp/legacy_dem/dem.f' $(pkg-config --cflags --libs hertzdamp) -o '$tmp/dem_f_pc' && '$tmp/dem_f_pc' | grep -q '^contact'"

# ------------------------------------------------------------ the legacy include file
cat >"$tmp/inc_ok.f" <<'F'
      PROGRAM INCOK
      IMPLICIT NONE
      INCLUDE 'hertzdamp.fi'
      DOUBLE PRECISION K, D, A, T
      INTEGER IERR
      CALL HERTZDAMP_INVERT(0.5D0, 1D-5, 1D-3, 1D0, 0, K, D, IERR)
      IF (IERR .NE. 0) STOP 1
      CALL HERTZDAMP_PAIR(0.5D0, 0, A, T, IERR)
      IF (IERR .NE. 0 .OR. A .LE. 0D0) STOP 2
      CALL HERTZDAMP_INVERT_BOUNDED(0.5D0, 1D-5, 1D-3, 1D0, 1D20, 0,
     &                              K, D, IERR)
      IF (IERR .NE. 0) STOP 3
      CALL HERTZDAMP_INVERT_LAW(0.5D0, 1D-5, 1D-3, 1D0, 0D0, 1, 0,
     &                          K, D, IERR)
      IF (IERR .NE. 0) STOP 4
      WRITE (*,'(A)') 'ok'
      END
F
check "include file: fixed-form client compiles (-Wall -Werror) and runs" bash -c \
  "gfortran -Wall -Werror -I'$prefix/include' '$tmp/inc_ok.f' -L'$prefix/lib' -Wl,-rpath,'$prefix/lib' \
   -lhertzdamp -o '$tmp/inc_ok' && '$tmp/inc_ok' | grep -qx ok"
cp "$tmp/inc_ok.f" "$tmp/inc_ok_free.f90"
sed -i 's/^     &/     \&/; s/1D20, 0,$/1D20, 0, \&/; s/0D0, 1, 0,$/0D0, 1, 0, \&/' "$tmp/inc_ok_free.f90"
check "include file: the same client in free form compiles" \
  gfortran -ffree-form -I"$prefix/include" -c "$tmp/inc_ok_free.f90" -o "$tmp/inc_free.o"
sed 's/DOUBLE PRECISION K, D, A, T/REAL K, D\n      DOUBLE PRECISION A, T/' "$tmp/inc_ok.f" >"$tmp/inc_real4.f"
check "include file: a REAL*4 argument is a compile error" \
  bash -c "! gfortran -I'$prefix/include' -c '$tmp/inc_real4.f' -o '$tmp/r4.o' 2>'$tmp/r4.err' && grep -q 'REAL(4) to REAL(8)' '$tmp/r4.err'"
check "include file: -fdefault-real-8 (DOUBLE PRECISION -> REAL(16)) is a compile error" \
  bash -c "! gfortran -fdefault-real-8 -I'$prefix/include' -c '$tmp/inc_ok.f' -o '$tmp/r8.o' 2>'$tmp/r8.err' && grep -q 'REAL(16) to REAL(8)' '$tmp/r8.err'"
check "include file: -fdefault-real-8 -fdefault-double-8 compiles (DOUBLE PRECISION stays REAL(8))" \
  gfortran -fdefault-real-8 -fdefault-double-8 -I"$prefix/include" -c "$tmp/inc_ok.f" -o "$tmp/r88.o"
check "without the include file the REAL*4 call compiles silently (what the include file prevents)" \
  bash -c "sed '/INCLUDE/d' '$tmp/inc_real4.f' > '$tmp/noinc.f' && gfortran -c '$tmp/noinc.f' -o '$tmp/noinc.o'"

# ------------------------------------------------------------ CMake consumers
cmake_consumer() {  # dir, extra cmake args...
  local dir=$1; shift
  cmake -S "$dir" -B "$dir/build" -DCMAKE_PREFIX_PATH="$prefix" "$@" >"$dir/configure.log" 2>&1 &&
    cmake --build "$dir/build" >"$dir/build.log" 2>&1 || { cat "$dir/configure.log" "$dir/build.log"; return 1; }
}
# (a) modern Fortran: use hertzdamp through the imported target
mkdir -p "$tmp/cm_mod"; cp example/example_invert.f90 "$tmp/cm_mod/"
cat >"$tmp/cm_mod/CMakeLists.txt" <<'CM'
cmake_minimum_required(VERSION 3.18)
project(modern LANGUAGES Fortran)
find_package(hertzdamp 0.2 CONFIG REQUIRED)
add_executable(example_invert example_invert.f90)
target_link_libraries(example_invert PRIVATE hertzdamp::hertzdamp)
CM
check "CMake: find_package + hertzdamp::hertzdamp, modern Fortran (use hertzdamp) builds" cmake_consumer "$tmp/cm_mod"
check "CMake: modern Fortran consumer runs" bash -c "'$tmp/cm_mod/build/example_invert' | grep -q '0.70000000'"
# (b) C only, with the static archive (the target brings the Fortran runtime)
mkdir -p "$tmp/cm_c"; cp example/c/dem.c "$tmp/cm_c/"
cat >"$tmp/cm_c/CMakeLists.txt" <<'CM'
cmake_minimum_required(VERSION 3.18)
project(cdem LANGUAGES C)
find_package(hertzdamp CONFIG REQUIRED)
add_executable(dem_c dem.c)
target_link_libraries(dem_c PRIVATE hertzdamp::hertzdamp_static)
CM
check "CMake: C-only project links hertzdamp::hertzdamp_static" cmake_consumer "$tmp/cm_c"
check "CMake: static C consumer runs, same output as the shared example" cmp <("$tmp/cm_c/build/dem_c") "$tmp/c.out"
# (c) a fixed-form host built the MFiX way: the host's code in a static archive, the
#     program linked from it, the library after the host objects, --as-needed
mkdir -p "$tmp/cm_mfix"; cp example/legacy_dem/dem.f "$tmp/cm_mfix/host.f"
sed -i 's/^      PROGRAM DEM$/      SUBROUTINE HOST/; s/^      END$/      END SUBROUTINE HOST/' "$tmp/cm_mfix/host.f"
printf '      PROGRAM MAIN\n      CALL HOST\n      END\n' >"$tmp/cm_mfix/main.f"
cat >"$tmp/cm_mfix/CMakeLists.txt" <<'CM'
cmake_minimum_required(VERSION 3.18)
project(mfixlike LANGUAGES Fortran)
set(CMAKE_EXE_LINKER_FLAGS "${CMAKE_EXE_LINKER_FLAGS} -Wl,--as-needed")
find_package(hertzdamp CONFIG REQUIRED)
add_library(host STATIC host.f)
target_link_libraries(host PUBLIC hertzdamp::hertzdamp)
add_executable(mfixlike main.f)
target_link_libraries(mfixlike PRIVATE host)
CM
check "CMake: fixed-form host archive + --as-needed links hertzdamp" cmake_consumer "$tmp/cm_mfix"
check "CMake: the MFiX-style host runs its 5 contacts" bash -c "[ \$('$tmp/cm_mfix/build/mfixlike' | grep -c '^contact') -eq 5 ]"
# (d) the same host with pkg_check_modules (IMPORTED_TARGET)
mkdir -p "$tmp/cm_pc"; cp "$tmp/cm_mfix/host.f" "$tmp/cm_mfix/main.f" "$tmp/cm_pc/"
cat >"$tmp/cm_pc/CMakeLists.txt" <<'CM'
cmake_minimum_required(VERSION 3.18)
project(mfixpc LANGUAGES Fortran)
set(CMAKE_EXE_LINKER_FLAGS "${CMAKE_EXE_LINKER_FLAGS} -Wl,--as-needed")
find_package(PkgConfig REQUIRED)
pkg_check_modules(HERTZDAMP REQUIRED IMPORTED_TARGET hertzdamp)
add_library(host STATIC host.f)
target_link_libraries(host PUBLIC PkgConfig::HERTZDAMP)
add_executable(mfixpc main.f)
target_link_libraries(mfixpc PRIVATE host)
CM
check "CMake: pkg_check_modules(hertzdamp) host builds" cmake_consumer "$tmp/cm_pc"
check "CMake: pkg_check_modules host runs" bash -c "[ \$('$tmp/cm_pc/build/mfixpc' | grep -c '^contact') -eq 5 ]"
# (e) a fixed-form host with the include file, through the CMake target's include path
mkdir -p "$tmp/cm_inc"; cp "$tmp/inc_ok.f" "$tmp/cm_inc/"
cat >"$tmp/cm_inc/CMakeLists.txt" <<'CM'
cmake_minimum_required(VERSION 3.18)
project(incok LANGUAGES Fortran)
find_package(hertzdamp CONFIG REQUIRED)
add_executable(inc_ok inc_ok.f)
target_link_libraries(inc_ok PRIVATE hertzdamp::hertzdamp)
CM
check "CMake: fixed-form client with INCLUDE 'hertzdamp.fi' builds" cmake_consumer "$tmp/cm_inc"
check "CMake: include-file client runs" bash -c "'$tmp/cm_inc/build/inc_ok' | grep -qx ok"
# (g) the MFiX layout (issue 21): the calls in a static library of a subdirectory, an
#     old cmake_minimum_required (3.10 < 3.13: policy CMP0079 off), the library linked
#     to hertzdamp from the top level, the program installed.  The README's recipe:
#     CMP0079 NEW, and CMAKE_INSTALL_RPATH_USE_LINK_PATH or the static target.
mkdir -p "$tmp/cm_sub/model"
cp "$tmp/cm_mfix/host.f" "$tmp/cm_mfix/main.f" "$tmp/cm_sub/"
mv "$tmp/cm_sub/host.f" "$tmp/cm_sub/model/host.f"
cat >"$tmp/cm_sub/CMakeLists.txt" <<'CM'
cmake_minimum_required(VERSION 3.10)
project(subhost LANGUAGES Fortran)
set(CMAKE_EXE_LINKER_FLAGS "${CMAKE_EXE_LINKER_FLAGS} -Wl,--as-needed")
if(HOST_RPATH)
  set(CMAKE_INSTALL_RPATH_USE_LINK_PATH ON)
endif()
find_package(hertzdamp 0.2 CONFIG REQUIRED)
add_subdirectory(model)
add_executable(subhost main.f)
target_link_libraries(subhost PRIVATE dem_core)
if(HOST_POLICY)
  cmake_policy(SET CMP0079 NEW)
endif()
target_link_libraries(dem_core PUBLIC ${HOST_TARGET})
install(TARGETS subhost DESTINATION bin)
CM
echo 'add_library(dem_core STATIC host.f)' >"$tmp/cm_sub/model/CMakeLists.txt"
check "hosts' sources: the legacy example uses INCLUDE 'hertzdamp.fi'" grep -q "^      INCLUDE 'hertzdamp.fi'" \
  "$tmp/cm_sub/model/host.f"
sub_host() {  # build dir, target, policy ON|OFF, rpath ON|OFF: configure, build, install into <dir>/inst
  local b=$tmp/cm_sub/$1
  cmake -S "$tmp/cm_sub" -B "$b" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_INSTALL_PREFIX="$b/inst" \
    -DHOST_TARGET="$2" -DHOST_POLICY="$3" -DHOST_RPATH="$4" >"$b.configure.log" 2>&1 &&
    cmake --build "$b" >"$b.build.log" 2>&1 && cmake --install "$b" >"$b.install.log" 2>&1 ||
    { cat "$b.configure.log" "$b.build.log" 2>/dev/null; return 1; }
}
runs_installed() {  # installed program: from /, no LD_LIBRARY_PATH, 5 contacts
  bash -c "cd / && [ \$(env -u LD_LIBRARY_PATH '$1' | grep -c '^contact') -eq 5 ]"
}
check "CMake, calls in a subdirectory's static library, minimum 3.10, CMP0079 NEW, rpath: builds and installs" \
  sub_host b_shared hertzdamp::hertzdamp ON ON
check "... the program runs in the build tree" \
  bash -c "[ \$('$tmp/cm_sub/b_shared/subhost' | grep -c '^contact') -eq 5 ]"
check "... the installed program runs (CMAKE_INSTALL_RPATH_USE_LINK_PATH)" runs_installed "$tmp/cm_sub/b_shared/inst/bin/subhost"
check "... the same host with hertzdamp::hertzdamp_static and no rpath setting: installed, it runs" \
  bash -c "$(declare -f sub_host); tmp='$tmp' prefix='$prefix' sub_host b_static hertzdamp::hertzdamp_static ON OFF"
check "... the static host needs no libhertzdamp.so" \
  bash -c "! ldd '$tmp/cm_sub/b_static/inst/bin/subhost' | grep -q libhertzdamp && \
           cd / && [ \$('$tmp/cm_sub/b_static/inst/bin/subhost' | grep -c '^contact') -eq 5 ]"
# what the recipe prevents: without CMP0079 the old minimum refuses the link; without
# the rpath setting the installed program does not find libhertzdamp.so
sub_host b_nopolicy hertzdamp::hertzdamp OFF ON >/dev/null 2>&1
check "without CMP0079 NEW (minimum 3.10) CMake refuses to link the subdirectory's library" \
  grep -q 'not built in this directory' "$tmp/cm_sub/b_nopolicy.configure.log"
sub_host b_norpath hertzdamp::hertzdamp ON OFF >/dev/null 2>&1
check "without CMAKE_INSTALL_RPATH_USE_LINK_PATH the installed program misses libhertzdamp.so" \
  bash -c "env -u LD_LIBRARY_PATH ldd '$tmp/cm_sub/b_norpath/inst/bin/subhost' | grep -q 'libhertzdamp.so.0 => not found'"
# (f) the version check refuses an incompatible request
mkdir -p "$tmp/cm_ver"
printf 'cmake_minimum_required(VERSION 3.18)\nproject(v LANGUAGES NONE)\nfind_package(hertzdamp 9.0 CONFIG REQUIRED)\n' \
  >"$tmp/cm_ver/CMakeLists.txt"
check "CMake: find_package(hertzdamp 9.0) fails (version file)" bash -c "! cmake_consumer '$tmp/cm_ver'"

# ------------------------------------------------------------ an fpm path dependency
mkdir -p "$tmp/fpmdep/app"
cat >"$tmp/fpmdep/fpm.toml" <<EOF
name = "fpmdep"
[dependencies]
hertzdamp = { path = "$(realpath --relative-to="$tmp/fpmdep" "$root")" }
EOF
cp example/example_invert.f90 "$tmp/fpmdep/app/main.f90"
(cd "$tmp/fpmdep" && "$fpm" build --verbose >"$tmp/fpmdep.log" 2>&1)
check "fpm dependent builds" test $? -eq 0
check "fpm dependent: no GSL, LAPACK or BLAS on any link line" bash -c "! grep -Eiq -- '-l(gsl|gslcblas|lapack|blas)\b' '$tmp/fpmdep.log'"
check "fpm dependent: compiles no application, peer or CLI source" \
  bash -c "! grep -Eq '(^|[[:space:]/])(packages/[a-z]+/src/[a-z_]+|app/hertzdamp_[a-z_]+)\.f90' '$tmp/fpmdep.log'"
check "fpm dependent runs" bash -c "cd '$tmp/fpmdep' && '$fpm' run 2>/dev/null | grep -q '0.70000000'"

# ------------------------------------------------------------ a failed install changes nothing
bad=$tmp/badprefix; mkdir -p "$bad" "$tmp/fakebin"; echo keep >"$bad/sentinel"
printf '#!/bin/sh\necho "\tlibgsl.so.27 => /usr/lib/libgsl.so.27"\n' >"$tmp/fakebin/ldd"; chmod +x "$tmp/fakebin/ldd"
PATH="$tmp/fakebin:$PATH" bash tools/install.sh "$bad" >"$tmp/bad.log" 2>&1
check "install refuses a core that links GSL" test $? -ne 0
check "failed install leaves the prefix as it was" test "$(cd "$bad" && find . -mindepth 1)" = "./sentinel"
check "install refuses a relative prefix" bash -c "! bash tools/install.sh relative/prefix"

finish

#!/usr/bin/env bash
# What a fixed-form DEM code pays for HERTZDAMP_INVERT: a fixed-form Fortran 77-style
# program built against an INSTALLED hertzdamp (`make install PREFIX=...`, linked like
# a host links it: -lhertzdamp, shared and static), calling the legacy external once per
# contact, against the module procedure hertzdamp_invert called the same way, in one
# process: 10^6 contacts (e uniform in [0.05, 0.99], m, u, T_c log-uniform over
# [1e-9, 1] kg, [1e-3, 10] m/s, [1e-7, 1e-3] s), rounds that time both loops in turn,
# medians of 7 rounds.  Not a test (speed is never asserted): doc/performance.md cites it.
#
#   tools/legacy_client_bench.sh [PREFIX]
#
# Without PREFIX it runs `make install` into a temporary prefix first.  The host side is
# compiled with `gfortran -O2` (a host's own flags; the library keeps its release flags).
set -euo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
prefix=${1:-}
if [ -z "$prefix" ]; then
  prefix=$tmp/prefix
  make --no-print-directory install PREFIX="$prefix" >"$tmp/install.log" 2>&1 || { tail -n 20 "$tmp/install.log"; exit 1; }
fi
libdir=$(dirname "$(find "$prefix" -name 'libhertzdamp.so' | head -n 1)")
moddir=$prefix/include/hertzdamp
[ -d "$libdir" ] && [ -f "$moddir/hertzdamp.mod" ] || { echo "no installed hertzdamp under $prefix" >&2; exit 1; }

cat >"$tmp/legacy_client.f" <<'EOF'
C     A fixed-form host: HERTZDAMP_INVERT once per contact (implicit interface, as a
C     Fortran 77 DEM calls it) against the module call, rounds of both loops in turn.
      PROGRAM LEGBEN
      IMPLICIT NONE
      INTEGER N, NR
      PARAMETER (N = 1000000, NR = 7)
      DOUBLE PRECISION E(N), TC(N), XM(N), U(N), XK(N), D(N)
      DOUBLE PRECISION XK2(N), D2(N), T(NR, 2), X(4), TMED(2)
      INTEGER IERR(N), IERR2(N), I, R, NBAD
      INTEGER*8 SEED, C0, C1, RATE
      SEED = 20261122
      DO 10 I = 1, N
         CALL LCG(SEED, X)
         E(I) = 0.05D0 + 0.94D0 * X(1)
         XM(I) = 10.0D0 ** (-9.0D0 + 9.0D0 * X(2))
         U(I) = 10.0D0 ** (-3.0D0 + 4.0D0 * X(3))
         TC(I) = 10.0D0 ** (-7.0D0 + 4.0D0 * X(4))
   10 CONTINUE
C     warm-up, then rounds
      CALL LEGLOOP(N, E, TC, XM, U, XK, D, IERR)
      CALL MODLOOP(N, E, TC, XM, U, XK2, D2, IERR2)
      DO 20 R = 1, NR
         CALL SYSTEM_CLOCK(C0, RATE)
         CALL LEGLOOP(N, E, TC, XM, U, XK, D, IERR)
         CALL SYSTEM_CLOCK(C1)
         T(R, 1) = DBLE(C1 - C0) / DBLE(RATE) / DBLE(N) * 1.0D9
         CALL SYSTEM_CLOCK(C0, RATE)
         CALL MODLOOP(N, E, TC, XM, U, XK2, D2, IERR2)
         CALL SYSTEM_CLOCK(C1)
         T(R, 2) = DBLE(C1 - C0) / DBLE(RATE) / DBLE(N) * 1.0D9
   20 CONTINUE
      NBAD = 0
      DO 30 I = 1, N
         IF (XK(I) .NE. XK2(I) .OR. D(I) .NE. D2(I) .OR.
     &       IERR(I) .NE. IERR2(I)) NBAD = NBAD + 1
   30 CONTINUE
      CALL MEDIAN(T(1, 1), NR, TMED(1))
      CALL MEDIAN(T(1, 2), NR, TMED(2))
      WRITE (*, '(A, F8.2, A)') 'legacy HERTZDAMP_INVERT   ', TMED(1),
     &   ' ns per contact (median of 7 rounds)'
      WRITE (*, '(A, F8.2, A)') 'module hertzdamp_invert   ', TMED(2),
     &   ' ns per contact (median of 7 rounds)'
      WRITE (*, '(A, F8.3, A)') 'ratio legacy / module     ',
     &   TMED(1) / TMED(2), ' (target: at most 1.3)'
      WRITE (*, '(A, I8)') 'contacts that differ (k, d, ierr): ',
     &   NBAD
      END

      SUBROUTINE LEGLOOP(N, E, TC, XM, U, XK, D, IERR)
      IMPLICIT NONE
      INTEGER N, IERR(N), I
      DOUBLE PRECISION E(N), TC(N), XM(N), U(N), XK(N), D(N)
      DO 10 I = 1, N
         CALL HERTZDAMP_INVERT(E(I), TC(I), XM(I), U(I), 0,
     &                         XK(I), D(I), IERR(I))
   10 CONTINUE
      END

      SUBROUTINE MODLOOP(N, E, TC, XM, U, XK, D, IERR)
      USE HERTZDAMP, ONLY: HZINV => HERTZDAMP_INVERT
      IMPLICIT NONE
      INTEGER N, IERR(N), I
      DOUBLE PRECISION E(N), TC(N), XM(N), U(N), XK(N), D(N)
      DO 10 I = 1, N
         CALL HZINV(E(I), TC(I), XM(I), U(I), 0, XK(I), D(I), IERR(I))
   10 CONTINUE
      END

C     Four uniform numbers in (0, 1), Park-Miller.
      SUBROUTINE LCG(SEED, X)
      IMPLICIT NONE
      INTEGER*8 SEED
      DOUBLE PRECISION X(4)
      INTEGER J
      DO 10 J = 1, 4
         SEED = MOD(16807 * SEED, 2147483647_8)
         X(J) = DBLE(SEED) / 2147483647.0D0
   10 CONTINUE
      END

C     Median of a short array (insertion sort of a copy).
      SUBROUTINE MEDIAN(A, N, XMED)
      IMPLICIT NONE
      INTEGER N, I, J
      DOUBLE PRECISION A(N), B(64), V, XMED
      DO 10 I = 1, N
         B(I) = A(I)
   10 CONTINUE
      DO 30 I = 2, N
         V = B(I)
         J = I - 1
   20    IF (J .GE. 1) THEN
            IF (B(J) .GT. V) THEN
               B(J + 1) = B(J)
               J = J - 1
               GO TO 20
            END IF
         END IF
         B(J + 1) = V
   30 CONTINUE
      XMED = B((N + 1) / 2)
      END
EOF

echo "# tools/legacy_client_bench.sh: fixed-form host (gfortran -O2) against the installed hertzdamp in $prefix"
echo "# machine: nproc=$(nproc), cpu: $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'); $(gfortran --version | head -n 1)"
for kind in shared static; do
  if [ "$kind" = shared ]; then
    gfortran -O2 -ffixed-form -I"$moddir" "$tmp/legacy_client.f" -L"$libdir" -Wl,-rpath,"$libdir" -lhertzdamp \
      -o "$tmp/client_$kind"
  else
    gfortran -O2 -ffixed-form -I"$moddir" "$tmp/legacy_client.f" "$libdir/libhertzdamp.a" -o "$tmp/client_$kind"
  fi
  echo "## linked with the $kind library"
  (cd "$tmp" && "./client_$kind")
done

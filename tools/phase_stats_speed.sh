#!/usr/bin/env bash
# The CPU time of one set of phase statistics (hertzdamp_host_mean: e, tau_c over the onset
# phase, the unit of work of every host solve and of hertzdamp_host_min_steps), this tree
# beside another revision (SRC=dir, its src/: git archive REV src | tar -x -C /tmp/old):
# both cores built with the release flags (tools/core_package.bash), each case timed
# alternately, RUNS times (default 5), the median per revision and their ratio.
#   SRC=/tmp/old/src bash tools/phase_stats_speed.sh [RUNS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
runs=${1:-5}
old=${SRC:?SRC=dir of the other revision src/}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
source "$root/tools/core_package.bash"
cat >"$tmp/ps.f90" <<'F'
program ps
    use hertzdamp_host, only: hertzdamp_host_mean, hertzdamp_host_stats
    implicit none
    type(hertzdamp_host_stats) :: s
    integer :: st, i, n, law, iend, host
    integer(8) :: c0, c1, cr
    real(8) :: a, h, t
    character(len=32) :: arg
    call get_command_argument(1, arg); read (arg, *) a
    call get_command_argument(2, arg); read (arg, *) h
    call get_command_argument(3, arg); read (arg, *) law
    call get_command_argument(4, arg); read (arg, *) iend
    call get_command_argument(5, arg); read (arg, *) host
    ! repeated until 0.3 s have passed: the time per set of statistics
    n = 0
    call system_clock(c0, cr)
    do
        call hertzdamp_host_mean(a, h, law, iend, host, s, st)
        n = n + 1
        call system_clock(c1)
        t = real(c1 - c0, 8) / real(cr, 8)
        if (t >= 0.3d0) exit
    end do
    print '(i0,1x,es23.16,1x,es23.16,1x,es12.5)', st, s%e_mean, s%tau_mean, t / n
end program ps
F
for v in new old; do
  src="$root/src"; [ "$v" = old ] && src=$old
  core_package "$tmp/$v" "$src" "$tmp/ps.f90"
  (cd "$tmp/$v" && "${FPM:-$root/.venv/bin/fpm}" build --flag "$(grep -v '^#' "$root/data/release_flags.txt")" >"$tmp/$v.log" 2>&1) \
    || { cat "$tmp/$v.log" >&2; exit 1; }
  cp "$(find "$tmp/$v/build" -type f -name ps -perm -u+x | head -1)" "$tmp/ps_$v"
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
# alpha h law end host: at the solutions of lammps, linear, e = 1e-3, N = 263 and of
# mfix-euler, kuwabara-kono, e = 1e-4, N = 113 (tools/min_steps_time.sh's two cases), and
# tsuji, alpha = 1, h = 0.05 on mfix-ab2 and verlet
while read -r a h law iend host name; do
  tn=(); to=()
  for ((r = 1; r <= runs; r++)); do
    read -r sn en taun t <<<"$("$tmp/ps_new" "$a" "$h" "$law" "$iend" "$host")"; tn+=("$t")
    read -r so eo tauo t <<<"$("$tmp/ps_old" "$a" "$h" "$law" "$iend" "$host")"; to+=("$t")
  done
  mn=$(printf '%s\n' "${tn[@]}" | sort -g | sed -n "$(( (runs + 1) / 2 ))p")
  mo=$(printf '%s\n' "${to[@]}" | sort -g | sed -n "$(( (runs + 1) / 2 ))p")
  awk -v n="$name" -v mn="$mn" -v mo="$mo" -v en="$en" -v eo="$eo" -v sn="$sn" -v so="$so" 'BEGIN {
    printf "%-34s status %s/%s  e_mean %.16g / %.16g  %8.3f ms  other %8.3f ms  ratio %.2f\n",
      n, sn, so, en, eo, 1e3 * mn, 1e3 * mo, mo / mn }'
done <<'CASES'
1.110735 0.0341129 0 0 1 lammps-linear-e1e-3-N263
8.584122 0.3363771 2 0 2 mfix-euler-kuwabara-e1e-4-N113
1.0 0.05 1 0 3 mfix-ab2-tsuji-a1-h0.05
1.0 0.05 1 0 4 verlet-tsuji-a1-h0.05
CASES
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"

#!/usr/bin/env bash
# `make bench`: the full work-precision run of `hertzdamp bench` with the release
# flags.  Writes
#   data/bench/bench.csv         '#' header (machine, compiler, flags, date, commit), then
#                                the CSV of `hertzdamp bench --format csv`
#   data/bench/bench.png         the work-precision diagram of that same run (--plot)
#   data/bench/bench.txt         a second full run in text form, with the 'figure:' lines
#   data/bench/bench_native.txt  a third run, text, of a build with -march=native instead
#                                of the release -march (what a user gains compiling for
#                                the machine at hand)
# Files are written to a temporary directory and moved into place at the end.
set -euo pipefail
fpm=$1; flags=$2
cd "$(dirname "$0")/.."
bin=$("$fpm" run hertzdamp --flag "$flags" --runner echo 2>/dev/null | tail -n 1)
out=data/bench
mkdir -p "$out"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

start=$SECONDS
"$bin" bench --format csv --plot "$tmp/bench.png" >"$tmp/run.csv"
t_csv=$((SECONDS - start))
start=$SECONDS
"$bin" bench --format text >"$tmp/bench.txt"
t_txt=$((SECONDS - start))
native_flags=$(sed -E 's/-march=[^ ]*/-march=native/' <<<"$flags")
grep -q -- '-march=native' <<<"$native_flags" || native_flags="$native_flags -march=native"
"$fpm" build --flag "$native_flags" >/dev/null 2>&1
bin_native=$("$fpm" run hertzdamp --flag "$native_flags" --runner echo 2>/dev/null | tail -n 1)
start=$SECONDS
"$bin_native" bench --format text >"$tmp/bench_native.txt"
t_nat=$((SECONDS - start))

fc=$(command -v gfortran || true)
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD -- src app packages 2>/dev/null || commit="$commit (with uncommitted changes in src/, app/ or packages/)"
{
  echo "# hertzdamp bench: full run written by \`make bench\` (tools/bench.sh: hertzdamp bench --format csv --plot bench.png)"
  echo "# date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "# machine: nproc=$(nproc), cpu: $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')"
  echo "# compiler: $( [ -n "$fc" ] && "$fc" --version | head -n 1 || echo unknown)"
  echo "# flags: $flags"
  echo "# commit: $commit"
  echo "# timing: wall clock per call, median of 5 batches of >= 0.1 s each (entry points: 5 rounds, one batch of each in turn); run time ${t_csv} s"
  echo "# integrators (rk45, GSL rkf45/rk8pd) use relative error control (absolute tolerance 1e-30 tol)"
  echo "# every damping law (column damping); forward errors against rk45 at tol 1e-15 of the law (e relative to max(e, 1e-3)); inverse errors against iterative at tol 1e-14 (tsuji: exact alpha)"
  if grep -q 'TEMPORARY stand-in' src/hertzdamp_inverse.f90 2>/dev/null; then
    echo "# WARNING: built with the TEMPORARY stand-in src/hertzdamp_inverse.f90 (rk45 secant for every method):"
    echo "#          the inverse and throughput rows do not measure the real fit/compact/series/pade inverses"
  fi
  echo "# the 'figure' lines (ratios) are in bench.txt, a second full run of the same build"
  cat "$tmp/run.csv"
} >"$tmp/bench.csv"
{
  echo "# hertzdamp bench --format text (make bench, $(date -u +%Y-%m-%dT%H:%M:%SZ), commit $commit, run time ${t_txt} s)"
  grep -E '^# (machine|compiler|flags|WARNING|         )' "$tmp/bench.csv" || true
  cat "$tmp/bench.txt"
} >"$tmp/bench_full.txt"
{
  echo "# hertzdamp bench --format text, built with -march=native (make bench, $(date -u +%Y-%m-%dT%H:%M:%SZ), commit $commit, run time ${t_nat} s)"
  grep -E '^# (machine|compiler)' "$tmp/bench.csv" || true
  echo "# flags: $native_flags (cpu flags: $(grep -m1 '^flags' /proc/cpuinfo | tr ' ' '\n' | grep -E '^(avx2|fma|avx512f)$' | tr '\n' ' '))"
  cat "$tmp/bench_native.txt"
} >"$tmp/bench_native_full.txt"
mv "$tmp/bench.csv" "$out/bench.csv"
mv "$tmp/bench_full.txt" "$out/bench.txt"
mv "$tmp/bench_native_full.txt" "$out/bench_native.txt"
mv "$tmp/bench.png" "$out/bench.png"
echo "wrote $out/bench.csv, $out/bench.png, $out/bench.txt, $out/bench_native.txt (runs of ${t_csv} s, ${t_txt} s and ${t_nat} s)"

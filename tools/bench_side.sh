#!/usr/bin/env bash
# Old and new `hertzdamp bench` side by side: runs `BIN bench --quick --damping LAW` of
# each program in turns, RUNS times each (default 7), and prints per entry point of the
# entry table the median ns per contact of each program and the ratio new / old, then the
# median of the pair table's ratio hertzdamp_c_pair_kd / bare formula (new program; the
# old one may not have the row).  Both programs must be release builds.
#   bash tools/bench_side.sh OLD_BIN NEW_BIN [RUNS] [LAW]
# The baseline of doc/performance.md: the commit before the redesign, f991267:
#   git archive f991267 | tar -x -C /tmp/old && (cd /tmp/old && fpm build --flag "$RELEASE_FLAGS")
set -euo pipefail
old=$1; new=$2; runs=${3:-7}; law=${4:-linear}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for ((r = 1; r <= runs; r++)); do
  for side in old new; do
    bin=${!side}
    "$bin" bench --quick --damping "$law" > "$tmp/out" 2>&1 || { cat "$tmp/out"; exit 1; }
    # "figure: LAW: entry points over N contacts, ns per contact (...): name ns (ratio), ..."
    grep "^figure: $law: entry points over" "$tmp/out" | sed 's/.*call)://' | tr ',' '\n' |
      awk -v s="$side" 'NF >= 2 {print s, $1, $2}' >> "$tmp/entry" || true
    grep '^figure: pair: ns per contact' "$tmp/out" |
      sed -n 's/.*hertzdamp_c_pair_kd [0-9.]* (\([0-9.]*\) x the bare.*/\1/p' | awk -v s="$side" '{print s, $1}' >> "$tmp/pair" || true
  done
done
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
printf '%-16s %10s %10s %10s   (ns per contact, medians of %d runs, %s)\n' way old new new/old "$runs" "$law"
for way in $(awk '$1 == "old" {print $2}' "$tmp/entry" | awk '!seen[$0]++'); do
  o=$(awk -v w="$way" '$1 == "old" && $2 == w {print $3}' "$tmp/entry" | median)
  n=$(awk -v w="$way" '$1 == "new" && $2 == w {print $3}' "$tmp/entry" | median)
  printf '%-16s %10.1f %10.1f %10.2f\n' "$way" "$o" "$n" "$(echo "$n / $o" | bc -l)"
done
for side in old new; do
  if grep -q "^$side " "$tmp/pair"; then
    printf 'c-pair-kd / bare (%s): %s (median of %d runs)\n' "$side" "$(awk -v s="$side" '$1 == s {print $2}' "$tmp/pair" | median)" "$runs"
  fi
done

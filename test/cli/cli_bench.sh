#!/usr/bin/env bash
# Checks of `hertzdamp bench`: the quick CSV run (header, finite non-negative numbers,
# for every damping law: accuracy of rk45 at tol 1e-10, of the fit and of the iterative
# baselines at the accuracy they are asked for, every entry point present; the tsuji
# rows against the closed form; the per-pair rows), --damping, the figures (every entry
# point of every law bit-identical to the module scalar call, the per-pair rows
# bit-identical; speed is reported, never asserted) and bad
# usage (exit code, empty stdout, no file left behind).
# $HERTZDAMP_BIN is the program.
set -u
bin=${HERTZDAMP_BIN:?HERTZDAMP_BIN must name the hertzdamp program}
passed=0; failed=0
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

check() {  # label, condition status (0 = pass)
  if [ "$2" -eq 0 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL cli_bench: $1"; fi
}

# ------------------------------------------------------------ the quick CSV run

timeout 120 "$bin" bench --quick --format csv >"$tmp/out.csv" 2>"$tmp/err.txt"
rc=$?

check "bench --quick --format csv exits 0 (got $rc: $(head -c 300 "$tmp/err.txt"))" $((rc != 0))

check "stderr empty on success" $([ ! -s "$tmp/err.txt" ]; echo $?)

header='problem,damping,method,setting,max_rel_err_e,max_rel_err_tau,max_rel_err_alpha,max_rel_err_k,max_rel_err_d,ns_per_call,rhs_evals'
check "CSV header" $([ "$(head -n 1 "$tmp/out.csv")" = "$header" ]; echo $?)
check "CSV has rows" $([ "$(wc -l <"$tmp/out.csv")" -gt 1 ]; echo $?)

# every row: 11 fields, known problem and law, numbers finite and >= 0 (or empty), ns_per_call present
bad=$(awk -F, 'NR > 1 {
    if (NF != 11) { print "line " NR ": " NF " fields"; next }
    if ($1 != "forward" && $1 != "inverse" && $1 != "entry" && $1 != "closed-form" && $1 != "pair") print "line " NR ": problem " $1
    if ($2 != "linear" && $2 != "tsuji" && $2 != "kuwabara-kono") print "line " NR ": damping " $2
    if ($3 == "") print "line " NR ": empty method"
    if ($10 == "") print "line " NR ": empty ns_per_call"
    for (i = 5; i <= 11; i++) {
        if ($i == "") continue
        if ($i !~ /^[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?$/) { print "line " NR " field " i ": " $i; continue }
        if ($i + 0 < 0) print "line " NR " field " i " negative: " $i
    }
}' "$tmp/out.csv")
check "rows well formed, numbers finite and non-negative ${bad:+($bad)}" $([ -z "$bad" ]; echo $?)

row() { awk -F, -v p="$1" -v l="$2" -v m="$3" -v s="$4" '$1 == p && $2 == l && $3 == m && $4 == s' "$tmp/out.csv"; }
below() {  # value, limit -> 0 if value < limit
  awk -v x="$1" -v l="$2" 'BEGIN { exit !(x != "" && x + 0 < l + 0) }'
}

for law in linear tsuji kuwabara-kono; do
  r=$(row forward $law rk45 1e-10)
  check "forward $law rk45 1e-10 row present" $([ -n "$r" ]; echo $?)
  if [ -n "$r" ]; then
    IFS=, read -r _ _ _ _ ee et _ _ _ ns rhs <<<"$r"
    below "$ee" 1e-9; check "forward $law rk45 1e-10: err e $ee < 1e-9" $?
    below "$et" 1e-9; check "forward $law rk45 1e-10: err tau_c $et < 1e-9" $?
    check "forward $law rk45 1e-10: rhs_evals present" $([ -n "$rhs" ]; echo $?)
  fi
  for tol in 1e-4 1e-6 1e-8 1e-10 1e-12; do
    check "forward $law rk45 $tol row present" $([ -n "$(row forward $law rk45 $tol)" ]; echo $?)
  done
  # the GSL peers integrate every law
  check "forward $law gsl-rk8pd rows present" $([ -n "$(row forward $law gsl-rk8pd 1e-8)" ]; echo $?)
  check "forward $law gsl-rkf45 rows present" $([ -n "$(row forward $law gsl-rkf45 1e-8)" ]; echo $?)
  # the iterative baselines meet the accuracy asked of alpha (against the reference at 1e-14)
  methods=iterative
  [ $law = linear ] && methods="iterative gsl-secant"
  for m in $methods; do
    for tol in 1e-6 1e-8 1e-10 1e-12; do
      r=$(row inverse $law $m $tol)
      check "inverse $law $m $tol row present" $([ -n "$r" ]; echo $?)
      if [ -n "$r" ]; then
        IFS=, read -r _ _ _ _ _ _ ea _ _ _ _ <<<"$r"
        below "$ea" "$tol"; check "inverse $law $m $tol: err alpha $ea < $tol" $?
      fi
    done
  done
  r=$(row forward $law fit '')
  check "forward $law fit row present" $([ -n "$r" ]; echo $?)
  if [ -n "$r" ]; then
    IFS=, read -r _ _ _ _ ee et _ _ _ _ _ <<<"$r"
    below "$ee" 1e-9; check "forward $law fit: err e $ee < 1e-9" $?
    below "$et" 1e-9; check "forward $law fit: err tau_c $et < 1e-9" $?
  fi
  r=$(row inverse $law fit '')
  check "inverse $law fit row present" $([ -n "$r" ]; echo $?)
  if [ -n "$r" ]; then
    IFS=, read -r _ _ _ _ _ _ ea ek ed _ _ <<<"$r"
    below "$ea" 1e-9; check "inverse $law fit: err alpha $ea < 1e-9" $?
    below "$ek" 1e-9; check "inverse $law fit: err k $ek < 1e-9" $?
    below "$ed" 1e-9; check "inverse $law fit: err d $ed < 1e-9" $?
  fi
  for w in module-scalar module-array c c-array legacy legacy-n; do
    check "entry point $w row present ($law)" \
      $([ -n "$(awk -F, -v w=$w -v l=$law '$1 == "entry" && $2 == l && $3 == w && $10 != ""' "$tmp/out.csv")" ]; echo $?)
  done
done

# every method of the project (linear law) and no gsl-secant, compact, series, pade row for the other laws
for n in 1 2 3 5 10 20; do
  check "forward series N=$n row present" $([ -n "$(row forward linear series N=$n)" ]; echo $?)
done
for m in pade compact; do
  check "forward $m row present" $([ -n "$(row forward linear $m '')" ]; echo $?)
done
for m in compact series pade; do
  check "inverse $m row present" $([ -n "$(row inverse linear $m '')" ]; echo $?)
done
check "linear-only methods only for the linear law" \
  $([ -z "$(awk -F, '$2 != "linear" && ($3 == "gsl-secant" || $3 == "compact" || $3 == "series" || $3 == "pade")' "$tmp/out.csv")" ]; echo $?)

# the tsuji inverse against its closed form: every row, the fit's alpha and the bound's d
# agree with the closed form to rounding
for w in closed-alpha fit-alpha closed-alpha-n fit-alpha-n closed-d bound-d closed-d-n bound-d-n; do
  check "closed-form $w row present" \
    $([ -n "$(awk -F, -v w=$w '$1 == "closed-form" && $2 == "tsuji" && $3 == w && $10 != ""' "$tmp/out.csv")" ]; echo $?)
done
r=$(awk -F, '$1 == "closed-form" && $3 == "fit-alpha"' "$tmp/out.csv")
IFS=, read -r _ _ _ _ _ _ ea _ _ _ _ <<<"$r"
below "$ea" 1e-14; check "closed-form: fit alpha within $ea < 1e-14 of sqrt5 beta(e)" $?
r=$(awk -F, '$1 == "closed-form" && $3 == "bound-d"' "$tmp/out.csv")
IFS=, read -r _ _ _ _ _ _ _ _ ed _ _ <<<"$r"
below "$ed" 1e-14; check "closed-form: bounded d within $ed < 1e-14 of alpha sqrt(m k)" $?

# the per-pair rows (linear law): the bare formula, the C and Fortran pair_kd, the arrays,
# the broadcast inverse (timed, never asserted)
for w in bare c-pair-kd pair-kd bare-vec pair-kd-array invert-each-tc-m invert-tc-m invert-tc c-pair-kd-phase \
    pair-kd-phase; do
  check "pair $w row present" \
    $([ -n "$(awk -F, -v w=$w '$1 == "pair" && $2 == "linear" && $3 == w && $10 != ""' "$tmp/out.csv")" ]; echo $?)
done

# --damping: the rows of one law
timeout 120 "$bin" bench --quick --damping kuwabara-kono --format csv --progress >"$tmp/kk.csv" 2>"$tmp/err.txt"
check "bench --quick --damping kuwabara-kono --progress exits 0 ($(head -c 300 "$tmp/err.txt"))" $?
# progress asked for: lines on stderr (not a terminal: full lines), the last at 100 %; stdout the table
check "bench --progress: progress lines on stderr" $(grep -q '^hertzdamp: bench: ' "$tmp/err.txt"; echo $?)
check "bench --progress: the CSV on stdout has no progress text" $(! grep -q 'hertzdamp: bench' "$tmp/kk.csv"; echo $?)
check "--damping kuwabara-kono: every row of that law, forward, inverse and entry ones" \
  $(awk -F, 'NR > 1 { n++; if ($2 != "kuwabara-kono") bad = 1; p[$1] = 1 }
             END { exit !(n > 20 && !bad && p["forward"] && p["inverse"] && p["entry"] && !p["closed-form"] && !p["pair"]) }' \
      "$tmp/kk.csv"; echo $?)

# ------------------------------------------------------------ the plot
if command -v gnuplot >/dev/null 2>&1; then
  "$bin" bench --quick --format json --plot "$tmp/wp.png" >"$tmp/out.json" 2>"$tmp/err.txt"
  rc=$?
  check "bench --quick --plot exits 0 (got $rc: $(head -c 300 "$tmp/err.txt"))" $((rc != 0))
  check "--plot writes a PNG" $([ "$(head -c 4 "$tmp/wp.png" 2>/dev/null | tail -c 3)" = PNG ]; echo $?)
  check "--plot leaves no temporary file" $([ ! -e "$tmp/wp.png.tmp" ]; echo $?)
  check "--format json is one JSON object with rows" \
    $(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert len(d["rows"]) > 0' "$tmp/out.json" \
      2>/dev/null; echo $?)
  # the run compared every entry point of every law with the module scalar call, bit for bit
  for law in linear tsuji kuwabara-kono; do
    check "figure: every entry point bit-identical to the module scalar call ($law)" \
      $(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert any(v.startswith(sys.argv[2] + ": entry points: k, d and status bit-identical") for k, v in d.items() if k.startswith("figure"))' "$tmp/out.json" $law 2>/dev/null; echo $?)
  done
  check "figure: the per-pair rows bit-identical (C, scalar, array pair_kd; broadcast inverse)" \
    $(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert any(v.startswith("pair: C, scalar and array pair_kd bit-identical") and "(0 results not ok)" in v for k, v in d.items() if k.startswith("figure"))' "$tmp/out.json" 2>/dev/null; echo $?)
  check "figure: the per-contact C call against the bare formula, with its target" \
    $(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert any(v.startswith("pair: ns per contact") and "target at most 1.50 x" in v for k, v in d.items() if k.startswith("figure"))' "$tmp/out.json" 2>/dev/null; echo $?)
  check "figure: tsuji array calls identical to one-contact calls, bound active everywhere" \
    $(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert any(v.startswith("tsuji: the fit") and "0 library results not ok, 0 contacts with the bound inactive, 0 contacts where an array call differs" in v for k, v in d.items() if k.startswith("figure"))' "$tmp/out.json" 2>/dev/null; echo $?)
fi

# ------------------------------------------------------------ bad usage
expect_fail() {  # label, expected exit code ('nz' = any non-zero), args...
  local label=$1 want=$2; shift 2
  "$bin" bench "$@" >"$tmp/o.txt" 2>"$tmp/e.txt"
  local got=$?
  if [ "$want" = nz ]; then
    check "$label: exit non-zero (got $got)" $((got == 0))
  else
    check "$label: exit $want (got $got)" $((got != want))
  fi
  check "$label: stdout empty" $([ ! -s "$tmp/o.txt" ]; echo $?)
  check "$label: one line on stderr" $([ "$(wc -l <"$tmp/e.txt")" -eq 1 ]; echo $?)
}
expect_fail "unknown option" 2 --quick --bogus
expect_fail "unknown --damping" 2 --quick --damping viscous
expect_fail "bad format" 2 --format xml
expect_fail "stray argument" 2 --quick extra
expect_fail "--plot without value" 2 --plot
expect_fail "unwritable --plot directory" 2 --quick --plot "$tmp/no/such/dir/p.png"
check "unwritable --plot: no file" $([ ! -e "$tmp/no/such/dir/p.png" ] && [ ! -e "$tmp/no" ]; echo $?)
mkdir "$tmp/ro" && chmod 555 "$tmp/ro"
if [ ! -w "$tmp/ro" ]; then   # (root can write anyway: then skip)
  expect_fail "read-only --plot directory" 2 --quick --plot "$tmp/ro/p.png"
  check "read-only --plot: no file" $([ -z "$(ls -A "$tmp/ro")" ]; echo $?)
fi
expect_fail "--plot onto a directory" 2 --quick --plot "$tmp"

echo "cli_bench: $passed passed, $failed failed"
[ "$failed" -eq 0 ]

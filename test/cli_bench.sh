#!/usr/bin/env bash
# Checks of `hertzdamp bench`: the quick CSV run (header, finite non-negative numbers,
# accuracy of rk45 at tol 1e-10, of the fit methods and of the iterative baselines at
# the accuracy they are asked for, every entry point present), the figures (every
# entry point bit-identical to the module scalar call; speed is reported, never
# asserted) and bad usage (exit code, empty stdout, no file left behind).
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

header='problem,method,setting,max_rel_err_e,max_rel_err_tau,max_rel_err_alpha,max_rel_err_k,max_rel_err_d,ns_per_call,rhs_evals'
check "CSV header" $([ "$(head -n 1 "$tmp/out.csv")" = "$header" ]; echo $?)
check "CSV has rows" $([ "$(wc -l <"$tmp/out.csv")" -gt 1 ]; echo $?)

# every row: 10 fields, known problem, numbers finite and >= 0 (or empty), ns_per_call present
bad=$(awk -F, 'NR > 1 {
    if (NF != 10) { print "line " NR ": " NF " fields"; next }
    if ($1 != "forward" && $1 != "inverse" && $1 != "entry") print "line " NR ": problem " $1
    if ($2 == "") print "line " NR ": empty method"
    if ($9 == "") print "line " NR ": empty ns_per_call"
    for (i = 4; i <= 10; i++) {
        if ($i == "") continue
        if ($i !~ /^[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?$/) { print "line " NR " field " i ": " $i; continue }
        if ($i + 0 < 0) print "line " NR " field " i " negative: " $i
    }
}' "$tmp/out.csv")
check "rows well formed, numbers finite and non-negative ${bad:+($bad)}" $([ -z "$bad" ]; echo $?)

row() { awk -F, -v p="$1" -v m="$2" -v s="$3" '$1 == p && $2 == m && $3 == s' "$tmp/out.csv"; }
below() {  # value, limit -> 0 if value < limit
  awk -v x="$1" -v l="$2" 'BEGIN { exit !(x != "" && x + 0 < l + 0) }'
}

r=$(row forward rk45 1e-10)
check "forward rk45 1e-10 row present" $([ -n "$r" ]; echo $?)
if [ -n "$r" ]; then
  IFS=, read -r _ _ _ ee et _ _ _ ns rhs <<<"$r"
  below "$ee" 1e-9; check "forward rk45 1e-10: err e $ee < 1e-9" $?
  below "$et" 1e-9; check "forward rk45 1e-10: err tau_c $et < 1e-9" $?
  check "forward rk45 1e-10: rhs_evals present" $([ -n "$rhs" ]; echo $?)
fi
for tol in 1e-4 1e-6 1e-8 1e-10 1e-12; do
  check "forward rk45 $tol row present" $([ -n "$(row forward rk45 $tol)" ]; echo $?)
done
check "forward gsl-rk8pd rows present" $([ -n "$(row forward gsl-rk8pd 1e-8)" ]; echo $?)
# the iterative baselines meet the accuracy asked of alpha (against the reference at 1e-14)
for m in iterative gsl-secant; do
  for tol in 1e-6 1e-8 1e-10 1e-12; do
    r=$(row inverse $m $tol)
    check "inverse $m $tol row present" $([ -n "$r" ]; echo $?)
    if [ -n "$r" ]; then
      IFS=, read -r _ _ _ _ _ ea _ _ _ _ <<<"$r"
      below "$ea" "$tol"; check "inverse $m $tol: err alpha $ea < $tol" $?
    fi
  done
done

# every method of the project and both GSL peers appear
for n in 1 2 3 5 10 20; do
  check "forward series N=$n row present" $([ -n "$(row forward series N=$n)" ]; echo $?)
done
for m in pade compact fit; do
  check "forward $m row present" $([ -n "$(row forward $m '')" ]; echo $?)
done
for m in fit compact series pade; do
  check "inverse $m row present" $([ -n "$(row inverse $m '')" ]; echo $?)
done
check "forward gsl-rkf45 rows present" $([ -n "$(row forward gsl-rkf45 1e-8)" ]; echo $?)
for w in module-scalar module-array c c-array legacy legacy-n; do
  check "entry point $w row present" $([ -n "$(awk -F, -v w=$w '$1 == "entry" && $2 == w && $9 != ""' "$tmp/out.csv")" ]; echo $?)
done

r=$(row forward fit '')
if [ -n "$r" ]; then
  IFS=, read -r _ _ _ ee et _ _ _ _ _ <<<"$r"
  below "$ee" 1e-9; check "forward fit: err e $ee < 1e-9" $?
  below "$et" 1e-9; check "forward fit: err tau_c $et < 1e-9" $?
fi
r=$(row inverse fit '')
if [ -n "$r" ]; then
  IFS=, read -r _ _ _ _ _ ea ek ed _ _ <<<"$r"
  below "$ea" 1e-9; check "inverse fit: err alpha $ea < 1e-9" $?
  below "$ek" 1e-9; check "inverse fit: err k $ek < 1e-9" $?
  below "$ed" 1e-9; check "inverse fit: err d $ed < 1e-9" $?
fi

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
  # the run compared every entry point with the module scalar call, bit for bit
  check "figure: every entry point bit-identical to the module scalar call" \
    $(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert any(v.startswith("entry points: k, d and status bit-identical") for k, v in d.items() if k.startswith("figure"))' "$tmp/out.json" 2>/dev/null; echo $?)
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

#!/usr/bin/env bash
# --damping on table, forward, invert, timestep and constants: the tsuji closed forms
# (overlap end: alpha = sqrt(5) beta(e), beta = -ln e / sqrt(pi^2 + ln^2 e); e the same
# at every speed; alpha_c = sqrt(5); e1 = pi/sqrt(5)), the velocity dependence of each
# law (alpha ~ u^(-1/5), u^0, u^(1/5)), invert -> forward round trips through the
# reference integrator, and the refusals (unknown law, methods of the linear law only).
SUITE=cli_damping
cd "$(dirname "$0")/../.."
. test/cli/cli_common.bash

# python3 checks on the CSV output in $OUT: the script gets the rows as dicts
pycheck() {  # label, python body (rows: list of dicts; fail with `raise SystemExit(1)`)
  local label=$1 body=$2
  check "$label" python3 -c "
import csv, math, sys
rows = list(csv.DictReader(l for l in open('$OUT') if not l.startswith('#')))
f = lambda r, k: float(r[k])
$body"
}

beta='beta = lambda e: -math.log(e) / math.sqrt(math.pi**2 + math.log(e)**2)'

# table, tsuji, overlap end: e(alpha) from the closed form, both methods
for m in rk45 fit; do
  run table --damping tsuji --method "$m" --alpha 0.01,0.1,0.5,1,2,2.2 --format csv
  # the fit covers e >= 1e-5 (alpha <= 2.17): alpha = 2.2 is outside it (exit 3)
  check "table tsuji $m: exit $([ $m = rk45 ] && echo 0 || echo 3)" test "$RC" -eq "$([ $m = rk45 ] && echo 0 || echo 3)"
  pycheck "table tsuji $m: ln e = -pi b/sqrt(1 - b^2), b = alpha/sqrt(5), to 1e-12 max(1, |ln e|) (rows with a result)" "
lnclosed = lambda a: -math.pi * (a / math.sqrt(5)) / math.sqrt(1 - a * a / 5)
assert len(rows) == 6
ok = [r for r in rows if r['status'] == 'ok']
bad = [r for r in ok if abs(math.log(f(r, 'e')) - lnclosed(f(r, 'alpha'))) > 1e-12 * max(1, abs(lnclosed(f(r, 'alpha'))))]
raise SystemExit(1 if bad or len(ok) < 5 else 0)"
done
run table --damping tsuji --alpha 2.3 --format csv
pycheck "table tsuji: alpha = 2.3 > sqrt(5) does not rebound" "
raise SystemExit(0 if rows[0]['status'] == 'no-rebound' else 1)"

# invert, tsuji: alpha column = sqrt(5) beta(e); forward (rk45) gives back e and T_c
run invert --damping tsuji --e 0.05,0.3,0.9 --tc 1e-5 --mass 2e-6 --velocity 0.01,1,10 --format csv
check "invert tsuji: exit 0" test "$RC" -eq 0
pycheck "invert tsuji: alpha = sqrt(5) beta(e) to 1e-13, the same at every speed" "
$beta
assert len(rows) == 9
raise SystemExit(0 if all(abs(math.sqrt(5) * beta(f(r, 'e')) / f(r, 'alpha') - 1) < 1e-13 for r in rows) else 1)"
for law in linear tsuji kuwabara-kono; do
  for end in overlap force; do
    run invert --damping "$law" --end "$end" --e 0.2,0.7 --tc 1e-5 --mass 2e-6 --velocity 0.05,3 --format csv
    cp "$OUT" "$OUT.inv"
    ok=1
    while IFS=, read -r e tc u k d; do
      run forward --damping "$law" --end "$end" --k "$k" --d "$d" --mass 2e-6 --velocity "$u" --format csv
      python3 -c "
import csv, sys
r = list(csv.DictReader(l for l in open('$OUT') if not l.startswith('#')))[0]
sys.exit(0 if r['status'] == 'ok' and abs(float(r['e']) / $e - 1) < 1e-10 and abs(float(r['t_c']) / $tc - 1) < 1e-10 else 1)" || ok=0
    done < <(python3 -c "
import csv
for r in csv.DictReader(l for l in open('$OUT.inv') if not l.startswith('#')):
    print(','.join(r[k] for k in ('e', 'tc', 'velocity', 'k', 'd')))")
    check "invert -> forward (rk45) round trip, $law, $end end: e and T_c to 1e-10" test "$ok" -eq 1
  done
done
rm -f "$OUT.inv"

# forward at fixed k, d over speeds: e rises (linear), stays (tsuji), falls (kuwabara-kono)
for law in linear tsuji kuwabara-kono; do
  run forward --damping "$law" --k 1e9 --d 0.05 --mass 2e-6 --velocity 0.01,0.1,1,10 --format csv
  check "forward $law: exit 0" test "$RC" -eq 0
  case $law in
    linear) cond='all(b > a for a, b in zip(es, es[1:]))'; p=-0.2 ;;
    tsuji) cond='all(abs(b / a - 1) < 1e-12 for a, b in zip(es, es[1:]))'; p=0 ;;
    kuwabara-kono) cond='all(b < a for a, b in zip(es, es[1:]))'; p=0.2 ;;
  esac
  pycheck "forward $law: e against speed ($cond), alpha ~ u^($p)" "
es = [f(r, 'e') for r in rows]; al = [f(r, 'alpha') for r in rows]; us = [f(r, 'velocity') for r in rows]
ok = $cond and all(abs(math.log(al[i] / al[0]) - ($p) * math.log(us[i] / us[0])) < 1e-12 for i in range(4))
raise SystemExit(0 if ok else 1)"
done

# constants of each law
run constants --damping tsuji --format csv
pycheck "constants tsuji: alpha_c = sqrt(5), e1 = pi/sqrt(5)" "
v = {r['name']: r['value'] for r in rows}
raise SystemExit(0 if abs(float(v['alpha_c']) / math.sqrt(5) - 1) < 1e-10 and abs(float(v['e1']) * math.sqrt(5) / math.pi - 1) < 1e-12 else 1)"
run constants --damping kuwabara-kono --format csv
pycheck "constants kuwabara-kono: no alpha_c (empty)" "
v = {r['name']: r['value'] for r in rows}
raise SystemExit(0 if v['alpha_c'] == '' else 1)"

# timestep with a law: the shortest contact is tau_c t* of that law (tsuji: alpha fixed)
run timestep --damping tsuji --e 0.5 --velocity 0.1,1 --mass 2e-6 --k-phys 1e9 --format csv
check "timestep tsuji: exit 0" test "$RC" -eq 0

# refusals name --damping or the method
expect_fail 2 "unknown law" table --damping viscous
check "unknown law: the message names --damping" grep -q -- '--damping' "$ERR"
expect_fail 2 "series with tsuji" table --damping tsuji --method series
check "series with tsuji: says linear only" grep -q 'linear only' "$ERR"
expect_fail 2 "compact invert with kuwabara-kono" invert --damping kuwabara-kono --method compact --e 0.5 --tc 1e-5 \
  --mass 1e-3 --velocity 1

# issue 21: a row beyond every method says what happened, with its alpha (before:
# "alpha = 0: integrator reached its maximum number of steps")
expect_fail 4 "forward kuwabara-kono, alpha = 5.2e4, rk45" forward --damping kuwabara-kono --k 1 --d 5.2e4 \
  --mass 1 --velocity 1 --method rk45
check "... names alpha = 52000 and the step limit before the contact ended" \
  grep -q 'alpha = 52000: the reference integrator reached its limit of 100000 steps before the contact ended' "$ERR"
expect_fail 3 "forward kuwabara-kono, alpha = 5.2e4, fit" forward --damping kuwabara-kono --k 1 --d 5.2e4 \
  --mass 1 --velocity 1 --method fit
check "... names alpha = 52000 (not 0) outside the fit" grep -q 'alpha = 52000 is outside the range of --method fit' "$ERR"
finish

#!/usr/bin/env bash
# CLI checks of `hertzdamp invert` (and table/forward with --method fit|compact).
bin=${HERTZDAMP_BIN:?set HERTZDAMP_BIN}
p=0; f=0
ok() { p=$((p + 1)); }
ko() { echo "FAIL cli_invert: $1"; f=$((f + 1)); }
out=$(mktemp); err=$(mktemp); trap 'rm -f "$out" "$err"' EXIT
run() { "$bin" "$@" >"$out" 2>"$err"; echo $?; }

rc=$(run invert --e 0.5,0.9 --tc 1e-4 --mass 1e-3 --velocity 1 --format csv)
[ "$rc" = 0 ] && ok || ko "csv exit $rc"
[ "$(head -n 1 "$out")" = "e,tc,mass,velocity,alpha,tau_c,t_star,k,d,bound_active,status" ] && ok || ko "csv header"
[ "$(wc -l <"$out")" = 3 ] && ok || ko "csv rows"
# 16 significant digits
grep -q '^5.000000000000000E-001,1.000000000000000E-004' "$out" && ok || ko "csv digits"
[ "$(sed -n 2p "$out" | cut -d, -f10,11)" = "false,ok" ] && ok || ko "bound/status columns"
# --dt --steps equals --tc
a=$("$bin" invert --e 0.5 --tc 1e-4 --mass 1e-3 --velocity 1 --format csv | tail -n 1)
b=$("$bin" invert --e 0.5 --dt 1e-5 --steps 10 --mass 1e-3 --velocity 1 --format csv | tail -n 1)
[ -n "$a" ] && [ "$a" = "$b" ] && ok || ko "--dt --steps vs --tc"
# methods agree (fit vs iterative to ~1e-10, compact to ~1e-5)
kf=$(echo "$a" | cut -d, -f8)
ki=$("$bin" invert --e 0.5 --tc 1e-4 --mass 1e-3 --velocity 1 --method iterative --format csv | tail -n 1 | cut -d, -f8)
kc=$("$bin" invert --e 0.5 --tc 1e-4 --mass 1e-3 --velocity 1 --method compact --format csv | tail -n 1 | cut -d, -f8)
python3 -c "import sys; a,b,c=map(float,sys.argv[1:]); sys.exit(0 if abs(a/b-1)<1e-9 and abs(a/c-1)<3e-5 else 1)" "$kf" "$ki" "$kc" && ok || ko "methods agree ($kf $ki $kc)"
# k-phys bound
rc=$(run invert --e 0.5 --tc 1e-4 --mass 1e-3 --velocity 1 --k-phys 1e6 --format csv)
[ "$rc" = 0 ] && [ "$(tail -n 1 "$out" | cut -d, -f8,10)" = "1.000000000000000E+006,true" ] && ok || ko "k-phys bound"
# json and text
rc=$(run invert --e 0.5 --tc 1e-4 --mass 1e-3 --velocity 1 --format json)
[ "$rc" = 0 ] && grep -q '"bound_active": "false"' "$out" && ok || ko "json"
rc=$(run invert --e 0.5 --tc 1e-4 --mass 1e-3 --velocity 1 --end force)
[ "$rc" = 0 ] && grep -q '^# end: force' "$out" && ok || ko "text, force"
# errors: one line on stderr, nothing on stdout
check_err() {  # expected-exit args...
  local want=$1; shift
  local rc; rc=$(run "$@")
  if [ "$rc" = "$want" ] && [ ! -s "$out" ] && [ "$(wc -l <"$err")" = 1 ]; then ok; else ko "exit $rc (want $want) for: $*"; fi
}
check_err 3 invert --e 5e-4 --tc 1e-4 --mass 1e-3 --velocity 1
check_err 3 invert --e 0 --tc 1e-4 --mass 1e-3 --velocity 1
check_err 3 invert --e 1.5 --tc 1e-4 --mass 1e-3 --velocity 1
check_err 3 invert --e 0.5,5e-5 --tc 1e-4 --mass 1e-3 --velocity 1 --end force
check_err 2 invert --e 0.5 --tc -1 --mass 1e-3 --velocity 1
check_err 2 invert --e 0.5 --tc 1e-4 --mass 0 --velocity 1
check_err 2 invert --e 0.5 --tc 1e-4 --mass 1e-3 --velocity -1
check_err 2 invert --e 0.5 --tc 1e-4 --mass 1e-3 --velocity 1 --k-phys 0
check_err 2 invert --e 0.5 --tc 1e-4 --mass 1e-3
check_err 2 invert --e 0.5 --mass 1e-3 --velocity 1
check_err 2 invert --e 0.5 --tc 1e-4 --dt 1e-5 --steps 10 --mass 1e-3 --velocity 1
check_err 2 invert --e 0.5 --tc 1e-4 --mass 1e-3 --velocity 1 --method series --end force
check_err 3 invert --e 0.05 --tc 1e-4 --mass 1e-3 --velocity 1 --method pade
check_err 2 invert --e abc --tc 1e-4 --mass 1e-3 --velocity 1
check_err 2 invert --e 0.5 --tc 1e-4 --mass 1e-3 --velocity 1 --tol 1e-12
rc=$(run invert --help); [ "$rc" = 0 ] && grep -q 'N m^-3/2' "$out" && ok || ko "help"
# table/forward through the fit and compact methods
rc=$(run table --method fit --alpha 0,0.5,1.2 --format csv)
[ "$rc" = 0 ] && [ "$(tail -n 1 "$out" | cut -d, -f6)" = "no-rebound" ] && ok || ko "table --method fit"
e_fit=$("$bin" table --method fit --alpha 0.5 --format csv | tail -n 1 | cut -d, -f2)
e_rk=$("$bin" table --alpha 0.5 --format csv | tail -n 1 | cut -d, -f2)
e_cp=$("$bin" table --method compact --alpha 0.5 --format csv | tail -n 1 | cut -d, -f2)
python3 -c "import sys; a,b,c=map(float,sys.argv[1:]); sys.exit(0 if abs(a/b-1)<1e-11 and abs(c/b-1)<3e-5 else 1)" "$e_fit" "$e_rk" "$e_cp" && ok || ko "table fit/compact vs rk45"
rc=$(run forward --method fit --k 1e8 --d 10 --mass 1e-3 --velocity 1 --end force --format csv)
[ "$rc" = 0 ] && ok || ko "forward --method fit"
echo "cli_invert: $p passed, $f failed"
[ "$f" -eq 0 ]

#!/usr/bin/env bash
# Per-row statuses and the exit codes they decide (app/hertzdamp_cli_rows.f90), for every
# status word: a small driver program is compiled with the real CLI modules and emits
# tables of rows of chosen kinds.  Then each status word is checked once more through
# the program itself where an input produces it (`failed`: kuwabara-kono at alpha =
# 5.2e4, beyond the integrator's step limit), and the exit code of a partial table
# with a failed row (4, issue 21) in the program, its help, the man page and the README.
SUITE=cli_rows
source "$(dirname "$0")/cli_common.bash"
cd "$(dirname "$0")/../.."
W=$(mktemp -d); trap 'rm -rf "$W" "$OUT" "$ERR"' EXIT
cat >"$W/driver.f90" <<'F90'
program driver
    use hertzdamp_cli_output, only: out_table, FORMAT_CSV
    use hertzdamp_cli_rows, only: row_log, row_word, row_has_result, ROW_OK, ROW_FAILED
    implicit none
    type(out_table) :: t
    type(row_log) :: rows
    character(len=32) :: a
    integer :: i, k
    call t%set_columns('row,status')
    do i = 1, command_argument_count()
        call get_command_argument(i, a)
        do k = ROW_OK, ROW_FAILED
            if (row_word(k) == trim(a)) exit
        end do
        call t%num(real(i, kind(1.0d0)))
        call t%str(row_word(k))
        if (row_has_result(k)) then
            call rows%add(k, '')
        else
            call rows%add(k, 'row ' // trim(a) // ' has none')
        end if
    end do
    call rows%emit(t, FORMAT_CSV)
end program driver
F90
# the CLI modules use the umbrella `hertzdamp`; for these few the kinds and the registry
# stand in for it (the whole core is not needed to print rows)
cat >"$W/umbrella.f90" <<'F90'
module hertzdamp
    use hertzdamp_kinds
    use hertzdamp_registry
end module hertzdamp
F90
if ! gfortran -std=f2018 -Wall -Werror -J "$W" -o "$W/driver" src/hertzdamp_kinds.f90 src/hertzdamp_registry.f90 \
     "$W/umbrella.f90" packages/text/src/hertzdamp_text_format.f90 \
     app/hertzdamp_cli_text.f90 app/hertzdamp_cli.f90 app/hertzdamp_cli_output.f90 app/hertzdamp_cli_rows.f90 \
     "$W/driver.f90" >"$W/build.log" 2>&1; then
  cat "$W/build.log"; check "driver builds" false; finish; exit 1
fi
drive() { "$W/driver" "$@" >"$OUT" 2>"$ERR"; RC=$?; }
# expected exit code, number of stdout lines (0: nothing), kinds...
expect() {
  local code=$1 lines=$2; shift 2
  drive "$@"
  check "rows $*: exit $code (got $RC)" test "$RC" -eq "$code"
  check "rows $*: $lines lines on stdout" test "$(wc -l <"$OUT")" -eq "$lines"
  if [ "$code" -eq 0 ]; then check "rows $*: stderr empty" test ! -s "$ERR"
  else check "rows $*: one line on stderr" test "$(wc -l <"$ERR")" -eq 1; fi
}
expect 0 3 ok no-rebound            # results only
expect 3 4 ok outside-validity bad-input   # partial: the table, exit 3
expect 3 3 no-rebound inaccurate
expect 3 3 ok out-of-range
expect 4 3 ok failed                 # partial with a failed computation: 4
expect 2 0 bad-input                 # nothing has a result: no stdout
expect 2 0 bad-input bad-input
expect 3 0 outside-validity bad-input
expect 3 0 inaccurate
expect 3 0 out-of-range
expect 4 0 failed
expect 4 0 failed bad-input out-of-range
drive ok failed bad-input
check "partial: the line counts and names the kinds" grep -q '^hertzdamp: 2 of 3 rows have no result (1 bad-input, 1 failed); first: row failed has none$' "$ERR"
check "partial: every row printed with its status" test "$(cut -d, -f2 "$OUT" | tr '\n' ' ')" = "status ok failed bad-input "
drive failed
check "a single row: its own message" grep -q '^hertzdamp: row failed has none$' "$ERR"

# every status word the program prints, produced by a real input
word() {  # word, args...
  local w=$1; shift
  run "$@" --format csv
  check "status word $w from: $*" grep -q ",$w\$" "$OUT"
}
word ok table --alpha 0.5
word no-rebound table --alpha 1.2
word bad-input forward --k 1e9 --d 1 --mass 1 --velocity 1,-1
word outside-validity table --method pade --alpha 0.5,0.9
word inaccurate table --method series --alpha 0.1,0.99
word out-of-range invert --e 0.5 --tc 1e-4,1e-300 --mass 1e10 --velocity 1
word failed forward --damping kuwabara-kono --k 1 --d 1,5.2e4 --mass 1 --velocity 1 --method rk45

# a partial table with a failed row: every row printed, exit 4 (not 3: a failed
# computation is never "no solution"), one line on stderr; said so in every document
run forward --damping kuwabara-kono --k 1 --d 1,5.2e4 --mass 1 --velocity 1 --method rk45 --format csv
check "partial with a failed row: exit 4 (got $RC)" test "$RC" -eq 4
check "partial with a failed row: both rows printed" test "$(cut -d, -f12 "$OUT" | tr '\n' ' ')" = "status ok failed "
check "partial with a failed row: one line on stderr naming it" \
  grep -q '^hertzdamp: 1 of 2 rows have no result (1 failed); first: ' "$ERR"
run forward --help
check "forward --help: 4 when a computation of one of the rows failed" \
  bash -c "tr '\n' ' ' <'$OUT' | grep -q '4 if a computation of one of them failed'"
check "README: 4 instead of 3 when a row's computation failed" \
  bash -c "tr '\n' ' ' <README.md | grep -q '4 instead of 3 when the computation of one of those rows failed'"
check "man page: 4 also when other rows have a result" \
  bash -c "tr '\n' ' ' <doc/hertzdamp.1 | grep -q 'a computation failed (also when other rows of the table have a result'"
finish

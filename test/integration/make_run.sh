#!/usr/bin/env bash
# `make run` as the README's quick start promises (issue 25 item 1): it prints k and d
# for the quick-start glass beads (the README's first example, line for line), installs
# the program and its man page into build/prefix, and ends with the absolute path of
# the program and the one line that puts it on PATH, which then works.  The program
# needs fpm only: `make run` does not depend on fortitude or ford (the lint and docs
# tools).  (Run inside `make test`, the release build is there: nothing is rebuilt.)
cd "$(dirname "$0")/../.."
root=$PWD
p=0; f=0
check() { local l=$1; shift; if "$@"; then p=$((p + 1)); else f=$((f + 1)); echo "FAIL make_run: $l"; fi; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

make --no-print-directory run >"$tmp/out" 2>"$tmp/err"
rc=$?
check "make run: exit 0 (got $rc: $(tail -n 3 "$tmp/err" | tr '\n' ' '))" test "$rc" -eq 0
last=$(tail -n 1 "$tmp/out")
check "the last line puts build/prefix/bin on PATH ($last)" \
  test "${last%%    #*}" = "export PATH=\"$root/build/prefix/bin:\$PATH\""
check "the line before names the installed program by its absolute path" \
  grep -q "^installed: $root/build/prefix/bin/hertzdamp " <<<"$(tail -n 2 "$tmp/out" | head -n 1)"
check "the program is installed and runs" bash -c "\"$root/build/prefix/bin/hertzdamp\" --version >/dev/null"
check "the man page is installed" test -s "$root/build/prefix/share/man/man1/hertzdamp.1"
check "the export line works: hertzdamp is the installed one" \
  bash -c "cd /; eval '$last'; [ \"\$(command -v hertzdamp)\" = '$root/build/prefix/bin/hertzdamp' ] && hertzdamp --version >/dev/null"
# the glass beads: the README's first example, command and output, line for line
python3 - README.md "$tmp/out" <<'PY' >"$tmp/cmp" 2>&1
import sys
readme = open(sys.argv[1], encoding="utf-8").read().splitlines()
out = open(sys.argv[2], encoding="utf-8").read().splitlines()
i = next(i for i, l in enumerate(readme) if l.startswith("    $ hertzdamp invert --radius 1e-3"))
want = [readme[i][4:]]
for l in readme[i + 1:]:
    if not l.startswith("    ") or l.startswith("    $ "):
        break
    want.append(l[4:])
j = out.index(want[0])
got = out[j:j + len(want)]
if got != want:
    print("\n".join(a + "  |  " + b for a, b in zip(got, want) if a != b)[:500])
    sys.exit(1)
PY
check "it prints the README's first example (the glass beads), line for line $(head -c 200 "$tmp/cmp")" test ! -s "$tmp/cmp"
check "the README's quick start says what make run prints" grep -q '^    make run .*prints k and d for the glass beads' README.md
deps=$(make -pn run 2>/dev/null | grep -E '^(run|build): ')
check "make run needs the Debian packages and fpm only ($(tr '\n' ' ' <<<"$deps"))" \
  bash -c "grep -q '^build: .deps-apt .venv/bin/fpm$' <<<'$deps' && ! grep -qE 'fortitude|ford' <<<'$deps'"
echo "make_run: $p passed, $f failed"
[ "$f" -eq 0 ]

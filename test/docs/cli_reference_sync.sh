#!/usr/bin/env bash
# One source for the command-line reference: the help texts (app/hertzdamp_cli_help.f90).
# The reference part of doc/cli.md (between its `cli reference` markers) is exactly what
# gen/cli_reference.py makes of `hertzdamp --help` and `hertzdamp COMMAND --help`
# today, so a changed help text fails here until `python3 gen/cli_reference.py BIN`
# is rerun.  The man page (doc/hertzdamp.1), written by hand, agrees with the help
# texts both ways: the same commands (SYNOPSIS and COMMANDS) and the same options
# (test/docs/cli_docs.sh checks help -> man; this checks man -> help too), and each
# command's SYNOPSIS names only options of that command's help.
SUITE=cli_reference_sync
source "$(dirname "$0")/../cli/cli_common.bash"
cd "$(dirname "$0")/../.."
tmp=$(mktemp -d); trap 'rm -rf "$tmp" "$OUT" "$ERR"' EXIT

# the generated block, regenerated and compared
cp doc/cli.md "$tmp/cli.md"
check "gen/cli_reference.py runs" python3 gen/cli_reference.py "$BIN" "$tmp/cli.md"
check "doc/cli.md's reference is what gen/cli_reference.py makes of the help texts (rerun it)" \
  cmp -s "$tmp/cli.md" doc/cli.md
python3 gen/cli_reference.py "$BIN" - >"$tmp/a"; python3 gen/cli_reference.py "$BIN" - >"$tmp/b"
check "gen/cli_reference.py is deterministic" cmp -s "$tmp/a" "$tmp/b"
check "gen/cli_reference.py - prints the block that doc/cli.md holds" \
  bash -c "sed -n '/^<!-- BEGIN cli reference -->\$/,/^<!-- END cli reference -->\$/p' doc/cli.md | cmp -s - '$tmp/a'"

# every command of the top help has its table row and its help text in doc/cli.md
cmds=$("$BIN" --help | sed -n '/^Commands:/,/^$/p' | awk 'NF > 1 && $1 != "Commands:" {print $1}')
check "the top help lists commands ($(echo $cmds))" test "$(wc -w <<<"$cmds")" -ge 7
for c in $cmds; do
  check "doc/cli.md has the row of $c" grep -q "^| \[\`$c\`\](#hertzdamp-$c) | " doc/cli.md
  "$BIN" "$c" --help | sed 's/^/    /; s/ *$//' >"$tmp/help"
  check "doc/cli.md holds the help text of $c, verbatim" python3 -c '
import sys
doc = open("doc/cli.md", encoding="utf-8").read()
sys.exit(0 if open(sys.argv[1], encoding="utf-8").read() in doc else 1)' "$tmp/help"
done

# the man page: the same commands and options as the help texts, both ways
man_text=$(sed 's/\\-/-/g; s/\\f[BIRP]//g' doc/hertzdamp.1)
man_syn=$(sed -n '/^\.SH SYNOPSIS/,/^\.SH /p' <<<"$man_text" | sed -nE 's/^\.B hertzdamp ([a-z]+).*/\1/p' | sort -u)
man_cmd=$(sed -n '/^\.SH COMMANDS/,/^\.SH /p' <<<"$man_text" | sed -nE 's/^\.B ([a-z]+)$/\1/p' | sort -u)
help_cmd=$(tr ' ' '\n' <<<"$cmds" | sed '/^$/d' | sort -u)
check "man page SYNOPSIS names exactly the commands of --help ($(echo $man_syn))" test "$man_syn" = "$help_cmd"
check "man page COMMANDS describes exactly the commands of --help ($(echo $man_cmd))" test "$man_cmd" = "$help_cmd"
help_opts=$(for c in "" $cmds; do "$BIN" $c --help; done | grep -oE -- '--[a-z0-9][a-z0-9-]*' | sort -u)
man_opts=$(grep -oE -- '(^|[^a-z0-9-])--[a-z0-9][a-z0-9-]*' <<<"$man_text" | grep -oE -- '--[a-z0-9-]+' | sort -u)
extra=$(comm -23 <(echo "$man_opts") <(echo "$help_opts") | tr '\n' ' ')
check "man page names no option the help texts lack${extra:+: $extra}" test -z "$extra"
check "man page and help texts name the same options ($(wc -w <<<"$man_opts") and $(wc -w <<<"$help_opts"))" \
  test "$man_opts" = "$help_opts"
# each command's SYNOPSIS in the man page names only options that its own help names
for c in $cmds; do
  syn=$(sed -n '/^\.SH SYNOPSIS/,/^\.SH /p' <<<"$man_text" | awk -v c="$c" '
    /^\.br$/ { on = 0 } $0 ~ "^\\.B hertzdamp " c "( |$)" { on = 1 } on' | grep -oE -- '--[a-z0-9][a-z0-9-]*' | sort -u)
  own=$("$BIN" "$c" --help | grep -oE -- '--[a-z0-9][a-z0-9-]*' | sort -u)
  extra=$(comm -23 <(echo "$syn") <(echo "$own") | tr '\n' ' ')
  check "man page SYNOPSIS of $c: only options of hertzdamp $c --help ($(wc -w <<<"$syn"))${extra:+; not in its help: $extra}" \
    test -n "$syn" -a -z "$extra"
done
finish

#!/usr/bin/env bash
# The API documentation builds (make docs: FORD over src/, settings in ford.md) without
# a warning, and documents every public module of the core.
cd "$(dirname "$0")/../.."
p=0; f=0
ok() { if "$@"; then p=$((p + 1)); else f=$((f + 1)); echo "FAIL docs: $label"; fi; }
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
log=$(.venv/bin/ford ford.md --output_dir "$out/docs" 2>&1)
label="ford runs"; ok test $? -eq 0
label="ford prints no warning"; ok bash -c "! grep -qi 'warning' <<<'$(tr -d "'" <<<"$log")'"
for m in $(grep -hioE '^ *module +hertzdamp[a-z0-9_]*' src/*.f90 | awk '{print tolower($2)}'); do
  case $m in *_data) continue ;; esac
  label="module $m documented"; ok test -s "$out/docs/module/$m.html"
done
echo "docs: $p passed, $f failed"
[ "$f" -eq 0 ]

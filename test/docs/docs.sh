#!/usr/bin/env bash
# The API documentation builds (make docs: FORD over src/, settings in ford.md) without
# a warning, documents every public module of the core, and carries the README and
# every guide of doc/ as pages (gen/ford_pages.py makes the page tree), with no broken
# link between the pages: every relative href of a page names a file of the output,
# and every #fragment an id of the page it points to.
cd "$(dirname "$0")/../.."
p=0; f=0
ok() { if "$@"; then p=$((p + 1)); else f=$((f + 1)); echo "FAIL docs: $label"; fi; }
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
label="gen/ford_pages.py makes the page tree"; ok python3 gen/ford_pages.py "$out/pages"
log=$(.venv/bin/ford ford.md --page_dir "$out/pages" --output_dir "$out/docs" 2>&1)
label="ford runs"; ok test $? -eq 0
label="ford prints no warning"; ok bash -c "! grep -qi 'warning' <<<'$(tr -d "'" <<<"$log")'"
for m in $(grep -hioE '^ *module +hertzdamp[a-z0-9_]*' src/*.f90 | awk '{print tolower($2)}'); do
  case $m in *_data) continue ;; esac
  label="module $m documented"; ok test -s "$out/docs/module/$m.html"
done
for md in README.md doc/*.md; do
  name=$(basename "$md" .md); [ "$md" = README.md ] && name=readme
  label="page of $md"; ok test -s "$out/docs/page/$name.html"
done
links=$(python3 - "$out/docs/page" <<'PY'
import os, re, sys
from html.parser import HTMLParser
class Page(HTMLParser):
    def __init__(self):
        super().__init__(); self.ids = set(); self.hrefs = []
    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if a.get("id"): self.ids.add(a["id"])
        if tag == "a" and a.get("href"): self.hrefs.append(a["href"])
        if tag == "img" and a.get("src"): self.hrefs.append(a["src"])
d = sys.argv[1]; pages = {}
for f in os.listdir(d):
    if f.endswith(".html"):
        p = Page(); p.feed(open(os.path.join(d, f), encoding="utf-8").read()); pages[f] = p
n = bad = 0
for f, p in sorted(pages.items()):
    for h in p.hrefs:
        if re.match(r"^[a-z]+:", h) or h.startswith("//"):
            continue
        n += 1
        path, _, frag = h.partition("#")
        target = os.path.normpath(os.path.join(d, path)) if path else os.path.join(d, f)
        if not os.path.exists(target):
            print(f"{f}: {h}: no such file"); bad += 1
        elif frag and os.path.dirname(target) == os.path.normpath(d) and target.endswith(".html") \
                and frag not in pages[os.path.basename(target)].ids:
            print(f"{f}: {h}: no such id"); bad += 1
print(f"links: {n} checked, {bad} broken")
PY
)
label="no broken link between the pages ($(tail -n 1 <<<"$links"))"
ok bash -c "grep -q '^links: [1-9][0-9]* checked, 0 broken$' <<<'$(tail -n 1 <<<"$links")'"
grep -v '^links:' <<<"$links" | head -n 10
echo "docs: $p passed, $f failed"
[ "$f" -eq 0 ]

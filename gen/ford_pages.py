#!/usr/bin/env python3
"""The README and the guides of doc/ as FORD pages.

    python3 gen/ford_pages.py OUTDIR

writes into OUTDIR (made anew; `make docs` uses build/ford-pages, the page_dir of
ford.md) the page tree that FORD renders beside the API documentation:
doc/ford/index.md (the top page, with the guides as its subpages, in the order of
GUIDES below), README.md as readme.md and every doc/*.md.  The markdown stays as
written; only what FORD needs changes:

- a `title:` line (the first `# ` heading, which is then dropped: FORD prints the
  title itself);
- every heading gets the id GitHub gives it (`## 6. The inverse rule` ->
  `{#6-the-inverse-rule}`), so that the `#fragment` links of the guides keep working;
- a link to a guide (`theory.md#6-...`, `doc/cli.md`, `../README.md`) points to its
  page (`theory.html#6-...`); a link to a repository file that is no page (a source
  file, the man page, the LAMMPS plugin's README) becomes its path in code font; an
  image is copied into OUTDIR (FORD copies it beside the pages) and shown from there.

test/docs/docs.sh builds the pages with FORD and checks that no link between them is
broken.
"""
import os
import re
import shutil
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
DOC = os.path.join(ROOT, "doc")
# the order of the subpages under doc/ford/index.md: the README first, then the guides
# of a DEM user, then the notes on the model; any other doc/*.md after them
GUIDES = ["readme", "cli", "dem-users", "library", "checking-decks", "calibration", "scenes",
          "accuracy", "performance", "host-schemes", "theory", "damping-laws", "series",
          "compact", "peers", "testing"]


def slug(heading):
    """The id GitHub gives a heading (the rule test/docs/readme_sync.sh checks links by)."""
    h = heading.strip().lower()
    h = re.sub(r"[^\w\- ]", "", h)
    return h.replace(" ", "-")


def sources():
    """(page name, path of its markdown) of every page but the index."""
    pages = {"readme": os.path.join(ROOT, "README.md")}
    for f in sorted(os.listdir(DOC)):
        if f.endswith(".md"):
            pages[f[:-3]] = os.path.join(DOC, f)
    order = [g for g in GUIDES if g in pages] + sorted(p for p in pages if p not in GUIDES)
    return [(p, pages[p]) for p in order]


def convert(text, src, pages, outdir):
    """The page of one markdown file: title line, heading ids, links rewritten."""
    lines = text.split("\n")
    title = next(l[2:].strip() for l in lines if l.startswith("# "))
    body, in_code = [], False
    dropped_title = False
    for line in lines:
        if line.startswith("```"):
            in_code = not in_code
        if not in_code and not line.startswith("    "):
            if line.startswith("# ") and not dropped_title:
                dropped_title = True
                continue
            m = re.match(r"^(#{2,6}) +(.*?) *$", line)
            if m:
                line = f"{m.group(1)} {m.group(2)} {{#{slug(m.group(2))}}}"
            else:
                line = re.sub(r"(!?)\[([^\]]*)\]\(([^)\s]+)\)",
                              lambda mm: link(mm, src, pages, outdir), line)
        body.append(line)
    return f"title: {title}\n\n" + "\n".join(body).strip("\n") + "\n"


def link(m, src, pages, outdir):
    """A markdown link or image of file src, as the page tree needs it."""
    bang, label, target = m.groups()
    if re.match(r"^[a-z]+:", target) or target.startswith("#"):
        return m.group(0)
    path, _, frag = target.partition("#")
    full = os.path.normpath(os.path.join(os.path.dirname(src), path))
    if bang:
        shutil.copyfile(full, os.path.join(outdir, os.path.basename(full)))
        return f"![{label}]({os.path.basename(full)})"
    for name, page_src in pages:
        if os.path.normpath(page_src) == full:
            return f"[{label}]({name}.html{'#' + frag if frag else ''})"
    rel = os.path.relpath(full, ROOT)
    if label.strip("`") in (rel, os.path.basename(rel), target):
        return f"`{rel}`"
    return f"{label} (`{rel}`)"


def main(argv):
    if len(argv) != 2:
        sys.stderr.write("usage: ford_pages.py OUTDIR\n")
        return 2
    outdir = argv[1]
    shutil.rmtree(outdir, ignore_errors=True)
    os.makedirs(outdir)
    pages = sources()
    index = open(os.path.join(DOC, "ford", "index.md"), encoding="utf-8").read()
    meta, _, rest = index.partition("\n\n")
    meta += "\nordered_subpage: " + "\n                 ".join(f"{p}.md" for p, _ in pages)
    with open(os.path.join(outdir, "index.md"), "w", encoding="utf-8") as f:
        f.write(meta + "\n\n" + rest)
    for name, src in pages:
        text = open(src, encoding="utf-8").read()
        with open(os.path.join(outdir, name + ".md"), "w", encoding="utf-8") as f:
            f.write(convert(text, src, pages, outdir))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env bash
# The core behind its umbrella (issue 31): app/ and packages/ import the core only
# through `hertzdamp` (and the C binding `hertzdamp_capi`), never a core-internal module
# of src/; outside src/ at most 10 imports of core-internal modules are left in all (the
# white-box unit tests of internals the umbrella keeps private).  Counts every `use`
# statement of a module defined in src/ other than those two, in app/, packages/,
# test/ and example/.
SUITE=umbrella_only
cd "$(dirname "$0")/../.."
python3 - <<'PY'
import glob, re, sys
p = f = 0
mods = set()
for path in glob.glob("src/*.f90"):
    mods |= {m.lower() for m in re.findall(r"(?im)^\s*module\s+(?!procedure\b)(\w+)", open(path).read())}
internal = mods - {"hertzdamp", "hertzdamp_capi"}
def count(dirs):
    hits = []
    for d in dirs:
        for path in sorted(glob.glob(d + "/**/*.f*", recursive=True)):
            for n, line in enumerate(open(path, errors="replace"), 1):
                m = re.match(r"\s*use\s*(?:,\s*\w+\s*::\s*)?(\w+)", line, re.I)
                if m and m.group(1).lower() in internal:
                    hits.append("%s:%d: %s" % (path, n, m.group(1)))
    return hits
def check(ok, what, hits):
    global p, f
    if ok:
        p += 1
    else:
        f += 1
        print("FAIL umbrella_only: " + what)
        for h in hits[:20]:
            print("  " + h)
if len(internal) < 10:
    check(False, "found only %d core modules in src/: the scan is broken" % len(internal), [])
apps = count(["app", "packages"])
check(not apps, "app/ and packages/ import %d core-internal modules (use hertzdamp)" % len(apps), apps)
every = count(["app", "packages", "test", "example"])
check(len(every) <= 10, "%d imports of core-internal modules outside src/ (at most 10)" % len(every), every)
print("umbrella_only: %d passed, %d failed" % (p, f))
sys.exit(1 if f else 0)
PY

#!/usr/bin/env python3
"""Files that name each enumeration value (laws with aliases, ends, hosts, methods of
data/registry.toml) inside string literals of code: src/, app/, packages/ and include/,
comments and generated files (the registry, the fit and series data) left out.  The
metric of issue 31 ("no enumeration value named in more than 4 hand-written files").
  python3 tools/enum_names.py [ROOT] [-v]   (-v: the files too)"""
import re, glob, tomllib, sys, os
root = sys.argv[1] if len(sys.argv) > 1 else '.'
reg = tomllib.load(open(os.path.join(root, 'data/registry.toml'), 'rb'))
names = {}
for kind in ('law', 'end', 'host', 'method'):
    for r in reg[kind]:
        for n in [r['name']] + r.get('aliases', []):
            names[n] = kind
generated = {'src/hertzdamp_registry.f90', 'src/hertzdamp_fit_kernels.f90', 'src/hertzdamp_fit_data.f90',
             'src/hertzdamp_series_data.f90', 'src/hertzdamp_pade_data.f90'}
files = [p for d in ('src', 'app', 'packages', 'include') for p in glob.glob(os.path.join(root, d, '**/*'), recursive=True)
         if os.path.isfile(p) and p.endswith(('.f90', '.h', '.fi', '.inc', '.c', '.cpp', '.F90'))]
def strip_comments(text, path):
    out = []
    if path.endswith(('.h', '.c', '.cpp')):
        text = re.sub(r'/\*.*?\*/', ' ', text, flags=re.S)
        return re.sub(r'//[^\n]*', '', text)
    for line in text.split('\n'):
        q = None; cut = len(line)
        for i, ch in enumerate(line):
            if q:
                if ch == q: q = None
            elif ch in '"\'': q = ch
            elif ch == '!': cut = i; break
        out.append(line[:cut])
    return '\n'.join(out)
def strip_generated(text):
    return re.sub(r'(!|/\*) BEGIN [^\n]*gen/registry.py.*?(!|/\*) END [^\n]*', '', text, flags=re.S)
res = {}
for n, kind in names.items():
    pat = re.compile(r'(?<![\w-])' + re.escape(n) + r'(?![\w-])')
    hits = []
    for p in files:
        rel = os.path.relpath(p, root)
        if rel in generated: continue
        t = strip_comments(strip_generated(open(p, errors='replace').read()), p)
        # the names inside string literals only (code, not identifiers like `linear`)
        t = ' '.join(m.group(0) for m in re.finditer(r'"[^"\n]*"|\'[^\'\n]*\'', t))
        if pat.search(t): hits.append(rel)
    res[n] = hits
for n, hits in sorted(res.items(), key=lambda x: -len(x[1])):
    print(len(hits), names[n], n, ' '.join(hits) if '-v' in sys.argv else '')

#!/usr/bin/env python3
"""The longest hand-written procedures of src/, app/ and packages/ (generated modules left
out): each procedure's own lines, from its first to its end statement, its contained
procedures counted apart.  The metric of issue 31 ("no hand-written procedure over 120
lines").
  python3 tools/long_procedures.py [N]   (N rows, default 12)"""
import re, glob, sys
gen = ('hertzdamp_fit_kernels', 'hertzdamp_fit_data', 'hertzdamp_series_data', 'hertzdamp_pade_data', 'hertzdamp_registry')
out = []
for p in sorted(glob.glob('src/*.f90') + glob.glob('app/*.f90') + glob.glob('packages/*/src/*.f90')):
    if any(g in p for g in gen): continue
    stack = []
    for n, line in enumerate(open(p), 1):
        s = line.split('!')[0].strip().lower()
        m = re.match(r'(?:(?:pure|elemental|impure|recursive|module|integer|real|logical|character|type)\b[^:]*?\s+)*(subroutine|function)\s+(\w+)', s)
        if m and not s.startswith('end') and 'procedure' not in s.split('(')[0]:
            stack.append([m.group(2), n, 0])
        elif re.match(r'end\s*(subroutine|function)\b', s) and stack:
            name, a, inner = stack.pop()
            out.append((n - a + 1 - inner, p, name))
            if stack: stack[-1][2] += n - a + 1
for L, p, name in sorted(out, reverse=True)[:int(sys.argv[1]) if len(sys.argv) > 1 else 12]:
    print(L, p, name)

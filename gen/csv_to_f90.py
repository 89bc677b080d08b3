#!/usr/bin/env python3
"""Convert a generated CSV table into a Fortran module of named constants.

Usage:  python3 gen/csv_to_f90.py IN.csv OUT.f90 MODULE_NAME PREFIX

IN.csv: leading '#' comment lines, one header row of column names, then data
rows.  OUT.f90 gets one public parameter array per column, named
PREFIX_<column>, indexed 0..nrows-1 by row.  A column whose entries are all
integer literals becomes an integer array, every other column a
real(hertzdamp_rk) array whose literals are copied digit for digit from the
CSV (kind suffix _hertzdamp_rk).  The CSV comment lines are copied as Fortran
comments.  The output depends on the CSV only (no dates, no paths other than
the arguments), so CI can regenerate and `diff` to check that the Fortran
source is in sync with the table.  Python standard library only.
"""
import csv
import re
import sys
import textwrap

INT_RE = re.compile(r"^[+-]?\d+$")
REAL_RE = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eEdD][+-]?\d+)?$")
NAME_RE = re.compile(r"^[A-Za-z][A-Za-z0-9_]*$")


def fail(msg):
    sys.stderr.write("csv_to_f90.py: " + msg + "\n")
    sys.exit(1)


def comment_lines(text, width=96):
    """Fortran comment lines for one CSV comment, wrapped below 132 columns."""
    body = text.rstrip()
    if not body:
        return ["!"]
    if len(body) <= width:
        return ["! " + body]
    parts = textwrap.wrap(body, width=width, break_long_words=True,
                          break_on_hyphens=False, drop_whitespace=False)
    return ["! " + p.rstrip() for p in parts]


def main(argv):
    if len(argv) != 5:
        fail("usage: python3 gen/csv_to_f90.py IN.csv OUT.f90 MODULE_NAME PREFIX")
    in_csv, out_f90, module, prefix = argv[1:5]
    for what, name in (("module name", module), ("prefix", prefix)):
        if not NAME_RE.match(name):
            fail("invalid Fortran %s: %r" % (what, name))
    with open(in_csv, newline="", encoding="utf-8") as f:
        lines = f.read().splitlines()
    comments = []
    i = 0
    while i < len(lines) and lines[i].startswith("#"):
        c = lines[i][1:]
        comments.append(c[1:] if c.startswith(" ") else c)
        i += 1
    rows = [r for r in csv.reader(lines[i:]) if r and any(c.strip() for c in r)]
    if not rows:
        fail("no header row in " + in_csv)
    header = [h.strip() for h in rows[0]]
    data = [[c.strip() for c in r] for r in rows[1:]]
    if not data:
        fail("no data rows in " + in_csv)
    for k, r in enumerate(data):
        if len(r) != len(header):
            fail("row %d has %d fields, header has %d" % (k + 1, len(r), len(header)))
    nrow = len(data)

    out = []
    out.append("!> Constants generated from %s." % in_csv)
    out.append("!>")
    out.append("!> Generated from %s by" % in_csv)
    out.append("!>   python3 gen/csv_to_f90.py %s %s \\" % (in_csv, out_f90))
    out.append("!>       %s %s" % (module, prefix))
    out.append("!> Do not edit by hand: regenerate the CSV, then rerun the command above.")
    out.append("!> Each array holds one column; element i (0-based) is data row i.")
    out.append("!>")
    out.append("!> Header of the CSV:")
    for c in comments:
        out.extend(comment_lines(c))
    out.append("module %s" % module)
    out.append("    use hertzdamp_kinds, only: hertzdamp_rk")
    out.append("    implicit none (type, external)")
    out.append("    private")
    out.append("")
    out.append("    !> Number of rows of the table (arrays are indexed 0..%d)." % (nrow - 1))
    out.append("    integer, parameter, public :: %s_nrows = %d" % (prefix, nrow))
    for j, name in enumerate(header):
        if not NAME_RE.match(name):
            fail("column name %r is not a Fortran name" % name)
        col = [r[j] for r in data]
        if all(INT_RE.match(v) for v in col):
            decl = "integer, parameter, public :: %s_%s(0:%d) = [ &" % (prefix, name, nrow - 1)
            vals = [str(int(v)) for v in col]
        else:
            for v in col:
                if not REAL_RE.match(v):
                    fail("column %s: %r is not a number" % (name, v))
            decl = "real(hertzdamp_rk), parameter, public :: %s_%s(0:%d) = [ &" % (prefix, name, nrow - 1)
            vals = [v.replace("d", "e").replace("D", "E") + "_hertzdamp_rk" for v in col]
        out.append("")
        out.append("    !> Column `%s` of %s." % (name, in_csv))
        out.append("    " + decl)
        for k, v in enumerate(vals):
            sep = ", &" if k < nrow - 1 else "]"
            out.append("        " + v + sep)
    out.append("")
    out.append("end module %s" % module)
    text = "\n".join(out) + "\n"
    for ln in text.splitlines():
        if len(ln) > 132:   # Fortran free-form limit (source lines are kept below 100)
            fail("generated line longer than 132 characters: " + ln[:60])
    with open(out_f90, "w", encoding="utf-8", newline="\n") as f:
        f.write(text)


if __name__ == "__main__":
    main(sys.argv)

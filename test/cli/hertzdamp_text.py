"""Reads the text output of hertzdamp back, for the tests (app/hertzdamp_cli_output.f90
writes it): metadata lines `# key: value`; a column that never changes as
`# name [unit] = value` above its table; the table, its header `name [unit] ...`
right-aligned; a table of one row as `name [unit] = value` lines.

tables(text) -> list of Table (meta, units, rows: each a dict name -> cell text, the
constant columns included); Table.num(row, name) reads a cell as a float ("inf" too).
Written against the format, independently of the program.
"""
import re

CONST = re.compile(r"^(?:# )?([A-Za-z_][\w./-]*)(?: \[([^\]]*)\])? += (.*)$")
META = re.compile(r"^# ([^:=]+?): (.*)$")
HEAD = re.compile(r"(\S+)(?: \[([^\]]*)\])?")


class Table:
    def __init__(self):
        self.meta, self.units, self.const, self.header, self.rows = {}, {}, {}, None, []
        self.listed = False          # a table of one row, written as a list

    def started(self):
        return self.header is not None or self.listed

    def num(self, row, name):
        return float(row[name].split()[0])


def tables(text):
    out, t = [], Table()

    def close():
        nonlocal t
        if t.started() or t.meta or t.const:
            if t.listed:
                t.rows = [dict(t.const)]
            else:
                t.rows = [dict(t.const, **r) for r in t.rows]
            out.append(t)
        t = Table()

    for line in text.splitlines():
        if not line.strip():
            close()
            continue
        m = CONST.match(line)
        if m and (line.startswith("# ") or not t.header):
            if t.header is not None or (t.listed and line.startswith("# ")):
                close()
            t.const[m.group(1)] = m.group(3)
            if m.group(2) is not None:
                t.units[m.group(1)] = m.group(2)
            if not line.startswith("# "):
                t.listed = True
            continue
        if line.startswith("#"):
            if t.started():
                close()
            m = META.match(line)
            if m:
                t.meta[m.group(1)] = m.group(2)
            continue
        if t.header is None:
            t.header = []
            for name, unit in HEAD.findall(line):
                t.header.append(name)
                if unit:
                    t.units[name] = unit
        else:
            t.rows.append(dict(zip(t.header, line.split())))
    close()
    return out


def rows(text):
    """The rows of the first table with rows."""
    for t in tables(text):
        if t.rows:
            return t.rows
    return []

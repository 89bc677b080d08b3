#!/usr/bin/env python3
"""The command-line reference of doc/cli.md, made from the program's help texts.

    python3 gen/cli_reference.py BIN [FILE]

BIN is the `hertzdamp` program; its help texts (app/hertzdamp_cli_help.f90) are the one
source of the reference.  The script runs `BIN --help` for the list of commands and
`BIN COMMAND --help` for each, and writes, between the lines
`<!-- BEGIN cli reference -->` and `<!-- END cli reference -->` of FILE (default
doc/cli.md), a table of the commands with their options and then the help text of
each command, verbatim (under the command line that prints it, without the `$ ` of
the worked examples: test/docs/readme_sync.sh runs those).  FILE `-` prints the block to stdout instead.  The output
depends on the help texts only (no date, no path): test/docs/cli_reference_sync.sh
regenerates it and fails when doc/cli.md differs.
"""
import re
import subprocess
import sys

BEGIN = "<!-- BEGIN cli reference -->"
END = "<!-- END cli reference -->"


def help_text(binary, *args):
    """The help text that `binary args... --help` prints (exit 0 required)."""
    run = subprocess.run([binary, *args, "--help"], capture_output=True, text=True, check=True)
    return run.stdout.rstrip("\n")


def commands(top):
    """(name, summary) of every command of the top-level help's `Commands:` block."""
    block = top.split("\nCommands:\n", 1)[1].split("\n\n", 1)[0]
    out = []
    for line in block.splitlines():
        m = re.match(r"^  ([a-z][a-z0-9-]*) +(.*)$", line)
        if m:
            out.append((m.group(1), m.group(2).strip()))
    return out


def options(text):
    """The options a help text names, in order of first appearance, without repeats."""
    seen = []
    for opt in re.findall(r"(?<![A-Za-z0-9-])--[a-z0-9][a-z0-9-]*", text):
        if opt not in seen:
            seen.append(opt)
    return seen


def block(binary):
    """The generated reference: the table, then every help text in a code block."""
    top = help_text(binary)
    cmds = commands(top)
    lines = [BEGIN, "", "| command | what it does | options (`hertzdamp COMMAND --help` explains each) |",
             "|---|---|---|"]
    texts = {}
    for name, summary in cmds:
        texts[name] = help_text(binary, name)
        opts = ", ".join(f"`{o}`" for o in options(texts[name]) if o != "--help")
        lines.append(f"| [`{name}`](#hertzdamp-{name}) | {summary} | {opts} |")
    lines.append("")
    sections = [("hertzdamp --help", top)] + [(f"hertzdamp {n} --help", texts[n]) for n, _ in cmds]
    for title, text in sections:
        anchor = title.replace(" --help", "")
        lines.append(f"### {anchor}")
        lines.append("")
        lines.append(f"    {title}")
        lines.extend(("    " + t).rstrip() for t in text.splitlines())
        lines.append("")
    lines.append(END)
    return "\n".join(lines) + "\n"


def main(argv):
    if len(argv) not in (2, 3):
        sys.stderr.write("usage: cli_reference.py BIN [FILE|-]\n")
        return 2
    binary = argv[1]
    target = argv[2] if len(argv) == 3 else "doc/cli.md"
    new = block(binary)
    if target == "-":
        sys.stdout.write(new)
        return 0
    with open(target, encoding="utf-8") as f:
        doc = f.read()
    if doc.count(BEGIN) != 1 or doc.count(END) != 1:
        sys.stderr.write(f"cli_reference.py: {target} needs one {BEGIN} and one {END} line\n")
        return 1
    head, rest = doc.split(BEGIN, 1)
    tail = rest.split(END, 1)[1]
    with open(target, "w", encoding="utf-8") as f:
        f.write(head + new.rstrip("\n") + tail)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

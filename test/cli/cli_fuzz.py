"""Drive the hertzdamp CLI with random argument lists (fixed seed, so a failure
reproduces) and assert the output contract:

- the exit code is 0, 2, 3 or 4; nothing crashes or hangs;
- warnings (implausible magnitudes, app/hertzdamp_cli_plausible.f90) are whole lines
  "hertzdamp: warning: ... (--quiet silences this)" and come first; the rules below
  hold for the rest of stderr;
- exit 0: stderr empty (unless --progress was asked for), stdout not empty, no NaN
  anywhere in it, every row's status a result (ok, no-rebound);
- exit 2: stdout empty;
- exit 3 or 4: stdout empty, or (per-row partial output) a table in which some rows
  have a result and some have none, with the stderr line "N of M rows have no result";
- on failure exactly one line on stderr, starting "hertzdamp: ";
- stdout and stderr are valid UTF-8 whatever bytes the arguments hold.

Prints `cli_fuzz: P passed, F failed`."""
import json
import os
import hertzdamp_text
import random
import re
import subprocess
import sys

BIN = os.environ["HERTZDAMP_BIN"]
N = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
rng = random.Random(20261122)

COMMANDS = ["table", "forward", "constants", "invert", "timestep", "bench", "scene", "coefficients",
            "frob", "", "--version", "--help"]
OPTIONS = ["--alpha", "--alpha-range", "--end", "--method", "--tol", "--format", "--order", "--accuracy",
           "--k", "--d", "--mass", "--velocity", "--e", "--tc", "--dt", "--steps", "--k-phys",
           "--radius", "--density", "--youngs-modulus", "--poisson-ratio", "--radius2", "--density2",
           "--youngs-modulus2", "--poisson-ratio2", "--wall", "--progress",
           "--plot", "--quick", "--help", "--frob", "-x", "--", "--quiet"]
WORDS = ["overlap", "force", "rk45", "series", "pade", "compact", "fit", "iterative", "text",
         "csv", "json", "xml", "", " ", "1e", "abc", "1,,2", "0x10", "nan", "inf", "-inf",
         "1e999", "-1e999", "1e-400", "0", "-0", "1", "-1", "0.5", "1.2", "1e-300", "1e300",
         "0:1:5", "0:1:0", "0:1:-3", "1:0:3", "0:1", "::", "0.1,0.2,0.3", "1,", ",1",
         "0.01:5:log4", "0:1:log3", "1e-3:1:log5", "0.9,0.0005,1.5", "0.5,-1,2", "1e200", "2.2e-308",
         "0.24", "0.5", "0.6", "63e9", "2500", "1e-3", "1e9", "1e10", "1e-6", "10", "0.99",
         "/nonexistent/dir/x.png", "12345678901234567890", "5", "20", "1e-13", "1e-2", "1e-10",
         "1\n2", "x\x1by", "caf\xe9", "\u00e9", "1:2:log0", "1:1e300:log10000"]
SAFE_COMMANDS = {"table", "forward", "constants", "invert", "timestep"}
RESULT = {"ok", "no-rebound"}
FAILURE = {"bad-input", "outside-validity", "inaccurate", "out-of-range", "failed"}


def word():
    w = rng.choice(WORDS) if rng.random() < 0.7 else repr(rng.uniform(-2, 60))
    return w.encode("latin-1") if "\xe9" in w and rng.random() < 0.5 else w.encode("utf-8")


def random_args():
    cmd = rng.choice(COMMANDS)
    args = [cmd.encode()] if cmd else []
    # half the time, a mostly valid command line with swept values, some of them bad,
    # to reach the computations and the per-row statuses
    if cmd in ("invert", "forward", "timestep", "table") and rng.random() < 0.6:
        sweep = lambda good: rng.choice([good, good, "0.9,0.0005,1.5", "0.5,-1,2", "0.01:5:log4", "1e-300,1",
                                         "0,1e300", "1e-3:1:log5", "0.99,0.1", "1.2,0.5"])
        base = {"invert": ["--e", sweep("0.5"), "--tc", sweep("1e-5"), "--velocity", sweep("1")],
                "forward": ["--k", sweep("1e9"), "--d", sweep("0.5"), "--velocity", sweep("1")],
                "timestep": ["--e", sweep("0.9"), "--velocity", "0.1:5:log3"],
                "table": ["--alpha", sweep("0.5")]}[cmd]
        args += [b.encode() for b in base]
        if cmd != "table":
            args += [b.encode() for b in rng.choice([["--mass", "1e-3", "--k-phys", "1e9"],
                                                     ["--radius", "1e-3", "--density", "2500", "--youngs-modulus",
                                                      "63e9", "--poisson-ratio", "0.24"]])]
        for _ in range(rng.randint(0, 2)):
            opt, vals = rng.choice([("--format", ["csv", "json", "text"]), ("--end", ["overlap", "force"]),
                                    ("--method", ["fit", "compact", "series", "pade", "rk45", "iterative"]),
                                    ("--accuracy", ["1e-3", "1e-12"]), ("--wall", [None])])
            if opt.encode() in args:
                continue
            args.append(opt.encode())
            if vals[0] is not None:
                args.append(rng.choice(vals).encode())
        return args
    if cmd in ("bench", "scene") and b"--help" not in args:
        args.append(b"--frob")  # keep runs short: they must fail at parse time
    return args


passed = failed = 0


def check(ok, label):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print(f"FAIL cli_fuzz: {label}")


def statuses(out, fmt):
    """The status column of a table in any format, or None if it is not a table."""
    try:
        if fmt == "json":
            return [r["status"] for r in json.loads(out)["rows"]]
        lines = [l for l in out.splitlines() if l and not l.startswith("#")]
        if fmt == "csv":
            head = lines[0].split(",")
            k = head.index("status")
            return [l.split(",")[k] for l in lines[1:]]
        return [r["status"] for r in hertzdamp_text.rows(out)]
    except (ValueError, KeyError, IndexError, TypeError):
        return None


for i in range(N):
    args = random_args()
    try:
        p = subprocess.run([BIN.encode()] + args, capture_output=True, timeout=60)
    except subprocess.TimeoutExpired:
        check(False, f"hang: {args!r}")
        continue
    rc = p.returncode
    try:
        out, err = p.stdout.decode("utf-8"), p.stderr.decode("utf-8")
    except UnicodeDecodeError:
        check(False, f"output not UTF-8 for {args!r}")
        continue
    fmt = "text"
    for j, a in enumerate(args[:-1]):
        if a == b"--format":
            fmt = args[j + 1].decode("utf-8", "replace")
    check(rc in (0, 2, 3, 4), f"exit code {rc} for {args!r}: {err.strip()[:200]}")
    lines = err.splitlines(keepends=True)
    nwarn = 0
    while nwarn < len(lines) and lines[nwarn].startswith("hertzdamp: warning: "):
        nwarn += 1
    check(all(l.endswith(" (--quiet silences this)\n") for l in lines[:nwarn]),
          f"a warning that is not one line ending in the --quiet hint for {args!r}: {err[:200]!r}")
    check(nwarn == 0 or b"--quiet" not in args, f"a warning despite --quiet for {args!r}: {err[:200]!r}")
    err = "".join(lines[nwarn:])
    if rc == 0:
        if b"--progress" not in args:
            check(err == "", f"stderr not empty on success for {args!r}: {err[:200]!r}")
        check(out != "", f"empty stdout on success for {args!r}")
        check(not re.search(r"\bnan\b", out, re.I), f"NaN in the output with exit 0 for {args!r}")
        st = statuses(out, fmt) if args and args[0] in (b"table", b"forward", b"invert", b"timestep") else None
        if st is not None and b"--help" not in args:
            check(all(s in RESULT for s in st), f"exit 0 with a row without result for {args!r}: {st[:5]}")
        continue
    check(err.count("\n") == 1 and err.startswith("hertzdamp: "), f"stderr not one line for {args!r}: {err[:200]!r}")
    if rc == 2 or out == "":
        check(out == "", f"stdout not empty on exit {rc} for {args!r}")
        continue
    # partial output: some rows with a result, some without, and the count on stderr
    st = statuses(out, fmt)
    check(st is not None and any(s in RESULT for s in st) and any(s in FAILURE for s in st)
          and all(s in RESULT | FAILURE for s in st),
          f"exit {rc} with output that is not a partial table for {args!r}: {out[:200]!r}")
    m = re.match(r"hertzdamp: (\d+) of (\d+) rows have no result", err)
    check(m is not None and st is not None and int(m.group(2)) == len(st)
          and int(m.group(1)) == sum(s in FAILURE for s in st),
          f"partial output without the right count on stderr for {args!r}: {err[:200]!r}")
    check(not re.search(r"\bnan\b", out, re.I), f"NaN in partial output for {args!r}")

print(f"cli_fuzz: {passed} passed, {failed} failed")
sys.exit(1 if failed else 0)

"""Drive the hertzdamp CLI with random argument lists (fixed seed, so a failure
reproduces) and assert: the exit code is 0, 2 or 3; on failure stdout is empty and
stderr is exactly one line; on success stderr is empty; nothing crashes or hangs.
Prints `cli_fuzz: P passed, F failed`."""
import os
import random
import subprocess
import sys

BIN = os.environ["HERTZDAMP_BIN"]
N = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
rng = random.Random(20261122)

COMMANDS = ["table", "forward", "constants", "invert", "bench", "scene", "coefficients", "frob", ""]
OPTIONS = ["--alpha", "--alpha-range", "--end", "--method", "--tol", "--format", "--order",
           "--k", "--d", "--mass", "--velocity", "--e", "--tc", "--dt", "--steps", "--k-phys",
           "--plot", "--quick", "--help", "--frob", "-x", "--"]
WORDS = ["overlap", "force", "rk45", "series", "pade", "compact", "fit", "iterative", "text",
         "csv", "json", "xml", "", " ", "1e", "abc", "1,,2", "0x10", "nan", "inf", "-inf",
         "1e999", "-1e999", "1e-400", "0", "-0", "1", "-1", "0.5", "1.2", "1e-300", "1e300",
         "0:1:5", "0:1:0", "0:1:-3", "1:0:3", "0:1", "::", "0.1,0.2,0.3", "1,", ",1",
         "/nonexistent/dir/x.png", "12345678901234567890", "5", "20", "1e-13", "1e-2"]
SAFE_COMMANDS = {"table", "forward", "constants", "invert"}  # bench/scene may be slow: no bare runs


def random_args():
    cmd = rng.choice(COMMANDS)
    args = [cmd] if cmd else []
    for _ in range(rng.randint(0, 6)):
        r = rng.random()
        if r < 0.55:
            args.append(rng.choice(OPTIONS))
            if rng.random() < 0.85:
                args.append(rng.choice(WORDS) if rng.random() < 0.7 else repr(rng.uniform(-2, 60)))
        elif r < 0.8:
            args.append(rng.choice(WORDS))
        else:
            args.append("".join(rng.choice("-,:.e0123456789xa ") for _ in range(rng.randint(0, 8))))
    if cmd in ("bench", "scene") and "--help" not in args:
        args.append("--frob")  # keep runs short: they must fail at parse time
    return args


passed = failed = 0


def check(ok, label):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print(f"FAIL cli_fuzz: {label}")


for i in range(N):
    args = random_args()
    try:
        p = subprocess.run([BIN] + args, capture_output=True, text=True, timeout=60)
    except subprocess.TimeoutExpired:
        check(False, f"hang: {args!r}")
        continue
    rc = p.returncode
    check(rc in (0, 2, 3), f"exit code {rc} for {args!r}: {p.stderr.strip()[:200]}")
    if rc != 0:
        check(p.stdout == "", f"stdout not empty on failure for {args!r}")
        check(p.stderr.count("\n") == 1 and p.stderr.startswith("hertzdamp: "),
              f"stderr not one line for {args!r}: {p.stderr[:200]!r}")
    else:
        check(p.stderr == "", f"stderr not empty on success for {args!r}: {p.stderr[:200]!r}")
        check(p.stdout != "", f"empty stdout on success for {args!r}")

print(f"cli_fuzz: {passed} passed, {failed} failed")
sys.exit(1 if failed else 0)

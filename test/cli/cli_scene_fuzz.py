"""Mutated scenes through `hertzdamp scene` (fixed seed, so a failure reproduces).
Each scene is a shipped or small scene with one to three numbers replaced by an
extreme value (0, subnormal, huge, +-1e150 edges, -huge, ...).  Asserted for every
run: the exit code is 0, 2, 3, 4 or 5; no NaN or Inf in the report; exit 0 only when
no check failed (JSON output parses); exit 5 only with a FAIL in the printed report;
exits 2, 3 and 4 leave stdout empty; every non-zero exit prints exactly one line on
stderr.  Prints `cli_scene_fuzz: P passed, F failed`."""
import json
import os
import random
import re
import subprocess
import sys
import tempfile

BIN = os.environ["HERTZDAMP_BIN"]
N = int(sys.argv[1]) if len(sys.argv) > 1 else 400
rng = random.Random(20261122)
SMALL = """&scene dt = 1e-6, steps_per_contact = 10, end_time = 5e-5 /
&material name = 's', density = 7800, youngs_modulus = 2e11, poisson_ratio = 0.3, restitution = 0.9 /
&material name = 'g', density = 2500, youngs_modulus = 6e10, poisson_ratio = 0.2, restitution = 0.7 /
&wall material = 'g', point = 0, 0, -0.01, normal = 0, 0, 1 /
&particle material = 's', radius = 1e-3, position = -1.01e-3,0,0, velocity = 1,0,0 /
&particle material = 'g', radius = 2e-3, position = 2.02e-3,0,0, velocity = -1,0,-1 /
&particle material = 's', radius = 1e-3, position = 0,0,-0.008, velocity = 0,0,-1 /
"""
SMALL_FORCE = """&scene dt = 1e-6, end_time = 5e-5, gravity = .true., g = 0,0,-9.81, report = 'restitution',
  contact_end = 'force', domain_lo = -1,-1,-1, domain_hi = 1,1,1, rest_speed = 1e-3, samples = 100, accuracy = 1e-3 /
&material name = 's', density = 7800, youngs_modulus = 2e11, poisson_ratio = 0.3, restitution = 0.5 /
&wall material = 's', point = 0, 0, 0, normal = 0, 0, 1 /
&particle material = 's', radius = 1e-3, position = 0,0,1.001e-3, velocity = 0,0,-1, count = 2, spacing = 0,0,2.1e-3 /
"""
BASES = [SMALL, SMALL_FORCE] + [open(f"data/scenes/{s}.nml").read() for s in ("binary", "drop", "chain")]
VALUES = ["0", "-0", "1e-308", "2.2e-308", "4.9e-324", "1e308", "-1e308", "1.7976931348623157e308",
          "-1.7976931348623157e308", "-9e307", "1e200", "-1e200", "1e-200", "1e150", "1e-150", "1e151",
          "1e-151", "1e100", "1e-100", "1e50", "1e-50", "-1", "1", "0.5", "2", "3", "10", "1e-3", "1e3",
          "1e9", "1e-12", "1e12", "0.999999", "1.0000001", "2147483647", "-2147483647"]
NUMBER = re.compile(r"(?<![A-Za-z_'\d.])[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?(?![A-Za-z_'\d])")
NONFINITE = re.compile(r"(?i)\bnan\b|\binf(inity)?\b")

passed = failed = 0


def check(ok, label):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print(f"FAIL cli_scene_fuzz: {label}")


with tempfile.TemporaryDirectory() as tmp:
    for i in range(N):
        text = "\n".join(l for l in rng.choice(BASES).split("\n") if not l.strip().startswith("!"))
        spots = list(NUMBER.finditer(text))
        for m in sorted(rng.sample(spots, rng.randint(1, 3)), key=lambda m: -m.start()):
            text = text[:m.start()] + rng.choice(VALUES) + text[m.end():]
        path = os.path.join(tmp, f"s{i}.nml")
        with open(path, "w") as f:
            f.write(text)
        fmt = rng.choice(["text", "csv", "json"])
        try:
            p = subprocess.run([BIN, "scene", path, "--no-compare", "--format", fmt],
                               capture_output=True, text=True, timeout=120)
        except subprocess.TimeoutExpired:
            check(False, f"scene {i}: hang\n{text}")
            continue
        rc, out, err = p.returncode, p.stdout, p.stderr
        label = f"scene {i} (exit {rc}, {fmt}): {err.strip()[:200]}\n{text}"
        check(rc in (0, 2, 3, 4, 5), f"exit code: {label}")
        check(not NONFINITE.search(out), f"NaN or Inf in the report: {label}")
        if rc == 0:
            check(err == "" and "FAIL" not in out, f"exit 0 with a FAIL or stderr: {label}")
            if fmt == "json":
                try:
                    json.loads(out)
                    check(True, "")
                except ValueError:
                    check(False, f"JSON does not parse: {label}")
        elif rc == 5:
            check("FAIL" in out and err.count("\n") == 1, f"exit 5 without a FAIL or one stderr line: {label}")
        else:
            check(out == "" and err.count("\n") == 1 and err.startswith("hertzdamp: "),
                  f"failure not one line, or stdout written: {label}")

print(f"cli_scene_fuzz: {passed} passed, {failed} failed")
sys.exit(1 if failed else 0)

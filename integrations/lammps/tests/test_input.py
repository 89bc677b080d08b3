"""Bad input to pair_style granular/hertzdamp, pair_coeff and fix hertzdamp/wall stops
LAMMPS with an ERROR line that names the keyword, on each LAMMPS version; borderline
good input (poisson 0.5, numbers as LAMMPS writes them) runs.  Numbers are read as
LAMMPS's utils::numeric()/is_double() read them: `1e5`, `.5`, `5.` are numbers, `0x10`,
`1e5x`, `nan` are not; N may be written as any such number whose value is whole (`20`,
`2e1`, `20.`, `1e5`; `10.5` and `1.05e1` are refused: a clear message, issue 30 item 10).
"""
import atexit
import os
import shutil
import sys
import tempfile

sys.dont_write_bytecode = True

import hdlmp

NAME = "lammps_input"

HEAD = """include ${load}
units si
atom_style sphere
atom_modify map array
boundary p p f
comm_modify vel yes
region b block 0 0.01 0 0.01 0 0.01
create_box 1 b
create_atoms 1 single 0.005 0.005 0.005
set type 1 diameter 0.002
set type 1 density 7800
fix integrate all nve/sphere
timestep 1e-7
"""
PAIR = "pair_style granular/hertzdamp steps 20\npair_coeff * * e 0.5\n"
P = "pair_style granular/hertzdamp"
C = "pair_coeff granular/hertzdamp"
W = "fix hertzdamp/wall"

# (input lines after HEAD, expected text after "ERROR: " or None for a clean run)
CASES = [
    ("pair_style granular/hertzdamp steps 2.5\n", P + ": steps N must be a whole number of time steps, not 2.5"),
    ("pair_style granular/hertzdamp steps 10.5\n", P + ": steps N must be a whole number of time steps, not 10.5"),
    ("pair_style granular/hertzdamp steps 1.05e1\n", P + ": steps N must be a whole number of time steps, not 1.05e1"),
    ("pair_style granular/hertzdamp steps 0.5\n", P + ": steps N must be a whole number of time steps, not 0.5"),
    ("pair_style granular/hertzdamp steps 0\n", P + ": steps must be >= 1, not 0"),
    ("pair_style granular/hertzdamp steps 3\npair_coeff * * e 0.1\nrun 0\n",
     P + " (types 1 1): steps 3: N = 3 steps cannot reach e = 0.1 with lammps-phase; N >= 4 can"),
    ("pair_style granular/hertzdamp steps 20 host exact\n", P + ": host must be lammps or none, not 'exact'"),
    ("pair_style granular/hertzdamp steps 200000\npair_coeff * * e 0.5\nrun 0\n",
     P + " (types 1 1): e 0.5, steps 200000, host lammps-phase: invalid steps per contact: must be finite with "
     "2 <= N <= 1e5"),
    ("pair_style granular/hertzdamp steps abc\n", P + ": steps needs a number, not 'abc'"),
    ("pair_style granular/hertzdamp steps 0x10\n", P + ": steps needs a number, not '0x10'"),
    ("pair_style granular/hertzdamp tc 1e-6x\n", P + ": tc needs a number, not '1e-6x'"),
    ("pair_style granular/hertzdamp tc nan\n", P + ": tc needs a number, not 'nan'"),
    ("pair_style granular/hertzdamp tc 3e-7\npair_coeff * * e 0.1\nrun 1\n",
     P + " (types 1 1): tc 2.9999999999999999e-07 (3 time steps of 9.9999999999999995e-08): N = 3 steps cannot "
     "reach e = 0.1 with lammps-phase; N >= 4 can"),
    ("pair_style granular/hertzdamp steps 20 vmin -1\n", P + ": vmin must be >= 0"),
    ("pair_style granular/hertzdamp steps 20 phase maybe\n", P + ": phase must be yes, no or exact"),
    ("pair_style granular/hertzdamp steps 20 tangential_stiffness scaled\n",
     P + ": tangential_stiffness must be adapted or physical"),
    ("pair_style granular/hertzdamp steps 20 normal_correction on\n", P + ": normal_correction must be yes or no"),
    ("pair_style granular/hertzdamp steps 20 normal_correction\n", P + ": keyword 'normal_correction' needs 1 value(s)"),
    ("pair_style granular/hertzdamp steps 20 log /dev/full\n", "hertzdamp: log /dev/full: cannot write"),
    ("pair_style granular/hertzdamp steps 20\npair_coeff * * e 1.5\n", C + ": e must be in (0, 1]"),
    ("pair_style granular/hertzdamp steps 20\npair_coeff * * e 0.5 youngs 1e9 poisson 0.6\n",
     C + ": poisson must be in (-1, 0.5], not 0.59999999999999998"),
    ("pair_style granular/hertzdamp steps 20\npair_coeff * * e 0.5 youngs 1e9 poisson -1\n",
     C + ": poisson must be in (-1, 0.5], not -1"),
    ("pair_style granular/hertzdamp steps 20\npair_coeff * * e 0.5 youngs 1e9\n",
     C + ": give youngs Y and poisson NU together"),
    ("pair_style granular/hertzdamp steps 20\npair_coeff * * e 0.5 tangential coulomb 1 2 3\n",
     C + ": tangential model must be linear_history or mindlin, not 'coulomb'"),
    ("pair_style granular/hertzdamp steps 20\npair_coeff * * e 0.5 tangential linear_history 1e5 0.5\n",
     C + ": 'tangential linear_history' needs 3 values"),
    ("pair_style granular/hertzdamp steps 20\npair_coeff * * e 0.5 tangential linear_history 1e5 0.5 mu\n",
     C + ": tangential linear_history mu needs a number, not 'mu'"),
    ("pair_style granular/hertzdamp steps 20\npair_coeff * * e 0.5 tangential mindlin NULL 0.5 0.3\n",
     C + ": tangential mindlin NULL needs youngs Y poisson NU (the shear modulus)"),
    ("pair_style granular/hertzdamp steps 20\npair_coeff * * e 0.5 rolling sds 1 1 0.1\n",
     C + ": rolling and twisting need a tangential model"),
    ("pair_style granular/hertzdamp steps 20\npair_coeff * * e 0.5 tangential linear_history 1e5 0.5 -0.3\n",
     C + ": tangential linear_history mu must be >= 0"),
    (PAIR + "fix w all hertzdamp/wall steps 20 e 0.5 xplane 0 NULL zplane 0 NULL\n",
     W + ": one wall per fix (xplane and zplane): define a second fix for the second wall"),
    (PAIR + "fix w all hertzdamp/wall steps 20 e 0.5 poisson 0.7 youngs 1e9 zplane 0 NULL\n",
     W + ": poisson must be in (-1, 0.5], not 0.69999999999999996"),
    (PAIR + "fix w all hertzdamp/wall steps 7.5 e 0.5 zplane 0 NULL\n",
     W + ": steps N must be a whole number of time steps, not 7.5"),
    (PAIR + "fix w all hertzdamp/wall steps 20 e 0.5 zplane 0 NULL log /dev/full\n",
     "hertzdamp: log /dev/full: cannot write"),
    # good input (RUNS: a clean run whose screen output has the text)
    ("pair_style granular/hertzdamp steps 1e5\n", "RUNS:"),
    ("pair_style granular/hertzdamp steps 2e1\npair_coeff * * e 0.5\nfix w all hertzdamp/wall steps 20.0 e 0.5 "
     "zplane 0 NULL\nrun 0\n", "RUNS:granular/hertzdamp: contact time 20 steps,"),
    ("pair_style granular/hertzdamp steps 20.\npair_coeff * * e 0.5\nfix w all hertzdamp/wall steps 2.0e1 e 0.5 "
     "zplane 0 NULL\nrun 0\n", "RUNS:fix hertzdamp/wall w: contact time 20 steps,"),
    ("pair_style granular/hertzdamp steps 20 vmin .5 tc 2e-6\n", P + ": give only one of steps N, tc T, fixed K D"),
    ("pair_style granular/hertzdamp tc 2.e-6 vmin .5\npair_coeff * * e 5e-1 youngs 1e9 poisson 0.5 "
     "tangential mindlin NULL 0.5 0.3\nfix w all hertzdamp/wall steps 20 e 0.5 youngs 1e9 poisson 0.5 "
     "tangential mindlin NULL 0.5 0.3 zplane 0 NULL\nrun 10\n", None),
]


def run(c):
    tmp = tempfile.mkdtemp(prefix="hd_lmp_input_")
    atexit.register(shutil.rmtree, tmp, True)
    for k, (lines, msg) in enumerate(CASES):
        path = os.path.join(tmp, "in.%d" % k)
        with open(path, "w") as f:
            f.write(HEAD + lines)
        out = hdlmp.lmp(path, {}, tmp, check=False)
        first = lines.strip().split("\n")[-1] if msg is None else lines.strip().split("\n")[-1]
        if msg is None:
            c.check("good input runs: " + first, "ERROR" not in out and "Loop time" in out, out[-400:])
        elif msg.startswith("RUNS:"):
            c.check("good input runs: " + lines.strip().split("\n")[0], "ERROR" not in out and msg[5:] in out,
                    "want '%s' in: %s" % (msg[5:], out[-400:]))
        else:
            c.check("bad input: " + first, ("ERROR: " + msg) in out, "want '%s' in: %s" % (msg, out[-400:]))


if __name__ == "__main__":
    hdlmp.main_each_flavor(NAME, run)

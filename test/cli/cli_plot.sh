#!/usr/bin/env bash
# Plots written safely (app/hertzdamp_cli_plot.f90, used by `scene --plot`,
# `calibrate --plot` and `bench --plot`): special files refused before any work and
# never opened (a device node made with mknod, a FIFO under a timeout, a socket, a
# directory), and so is the command's own input file under any name; a full disk (a
# small tmpfs) or a file size limit (ulimit -f) gives exit 4 and leaves nothing behind,
# also for a path with a newline and when gnuplot's own scratch directory is full; a
# complete PNG otherwise; SIGTERM and SIGINT while gnuplot draws leave nothing behind
# and stop gnuplot.
# Tests that need mount or mknod print SKIPPED (not counted) where they cannot run.
SUITE=cli_plot
source "$(dirname "$0")/cli_common.bash"
cd "$(dirname "$0")/../.."
command -v gnuplot >/dev/null 2>&1 || { echo "SKIPPED cli_plot: gnuplot missing"; echo "$SUITE: 0 passed, 0 failed"; exit 0; }
T=$(mktemp -d)
FULL=$T/full
cleanup() { mountpoint -q "$FULL" 2>/dev/null && umount "$FULL"; rm -rf "$T" "$OUT" "$ERR"; }
trap cleanup EXIT
SCENE=data/scenes/drop.nml
export TMPDIR=$T/scratch
mkdir -p "$TMPDIR"
skipped=0
skip() { echo "SKIPPED $SUITE: $1"; skipped=$((skipped + 1)); }
complete_png() {  # PNG signature at the start, IEND chunk at the end
  python3 -c '
import sys
b = open(sys.argv[1], "rb").read()
sys.exit(0 if b[:8] == b"\x89PNG\r\n\x1a\n" and b[-12:] == b"\0\0\0\0IEND\xaeB`\x82" else 1)' "$1"
}
no_scratch_left() { test -z "$(ls -A "$TMPDIR")"; }

# a complete PNG, nothing else left
run scene $SCENE --plot "$T/ok.png"
check "plot: exit 0 (got $RC: $(head -c 200 "$ERR"))" test "$RC" -eq 0
check "plot: a complete PNG" complete_png "$T/ok.png"
check "plot: no temporary file next to it" test "$(ls -A "$T" | grep -c hertzdamp)" -eq 0
check "plot: no scratch file left" no_scratch_left
# a path with a newline and quotes works
NL="$T/a
b 'q\".png"
run scene $SCENE --plot "$NL"
check "plot: path with a newline and quotes: exit 0 (got $RC)" test "$RC" -eq 0
check "plot: path with a newline: a complete PNG" complete_png "$NL"
# an existing regular file is replaced
echo old >"$T/old.png"
run scene $SCENE --plot "$T/old.png"
check "plot: an existing regular file is replaced by a complete PNG" complete_png "$T/old.png"

# special files: refused before any work (exit 2), never opened or replaced
mkdir "$T/dir"
expect_fail 2 "plot: a directory" scene $SCENE --plot "$T/dir"
check "plot: directory left empty" test -z "$(ls -A "$T/dir")"
mkfifo "$T/fifo"
timeout 20 "$BIN" scene $SCENE --plot "$T/fifo" >"$OUT" 2>"$ERR"; RC=$?
check "plot: a FIFO is refused without blocking (exit $RC)" test "$RC" -eq 2
check "plot: FIFO: stdout empty, one line on stderr" test ! -s "$OUT" -a "$(wc -l <"$ERR")" -eq 1
check "plot: the FIFO is still a FIFO" test -p "$T/fifo"
timeout 20 "$BIN" bench --quick --plot "$T/fifo" >"$OUT" 2>"$ERR"; RC=$?
check "bench --plot: a FIFO is refused at once (exit $RC)" test "$RC" -eq 2
if mknod "$T/null" c 1 3 2>/dev/null; then
  expect_fail 2 "plot: a character device (mknod)" scene $SCENE --plot "$T/null"
  check "plot: device message" grep -q 'exists and is not a regular file' "$ERR"
  check "plot: the device is still a device" test -c "$T/null"
  timeout 20 "$BIN" bench --quick --plot "$T/null" >"$OUT" 2>"$ERR"; RC=$?
  check "bench --plot: a device is refused at once (exit $RC)" test "$RC" -eq 2 -a -c "$T/null"
else
  skip "mknod not permitted: device-node test not run"
fi
python3 -c 'import socket, sys; s = socket.socket(socket.AF_UNIX); s.bind(sys.argv[1])' "$T/sock"
expect_fail 2 "plot: a socket" scene $SCENE --plot "$T/sock"
check "plot: the socket is still a socket" test -S "$T/sock"
ln -s "$T/nowhere" "$T/dangling"
expect_fail 2 "plot: a dangling symbolic link" scene $SCENE --plot "$T/dangling"
check "plot: special files: no scratch left" no_scratch_left

# a full disk: exit 4, nothing left behind (the PNG gnuplot wrote is checked and copied
# with every write checked; gnuplot itself exits 0 on a full disk)
mkdir "$FULL"
if mount -t tmpfs -o size=16k tmpfs "$FULL" 2>/dev/null; then
  run scene $SCENE --plot "$FULL/x.png"
  check "full disk: exit 4 (got $RC)" test "$RC" -eq 4
  check "full disk: stdout empty, one line on stderr" test ! -s "$OUT" -a "$(wc -l <"$ERR")" -eq 1
  check "full disk: nothing left on the disk" test -z "$(ls -A "$FULL")"
  check "full disk: no scratch left" no_scratch_left
  run scene $SCENE --plot "$FULL/a
b.png"
  check "full disk, newline in the path: exit 4 (got $RC)" test "$RC" -eq 4
  check "full disk, newline in the path: nothing left" test -z "$(ls -A "$FULL")"
  check "full disk, newline in the path: one line on stderr" test "$(wc -l <"$ERR")" -eq 1
  # an existing plot on the full disk is kept whole
  umount "$FULL"; mount -t tmpfs -o size=64k tmpfs "$FULL"
  cp "$T/ok.png" "$FULL/keep.png"
  head -c 30000 /dev/zero >"$FULL/filler" 2>/dev/null
  run scene $SCENE --plot "$FULL/keep.png"
  check "full disk: an existing plot is kept unchanged (exit $RC)" cmp -s "$T/ok.png" "$FULL/keep.png"
  check "full disk: no temporary file left" test "$(ls -A "$FULL" | grep -c hertzdamp)" -eq 0
  # gnuplot's own scratch directory full: gnuplot writes a truncated PNG and exits 0
  # (64k: room for the scene's data file, not for the whole PNG)
  umount "$FULL"; mount -t tmpfs -o size=64k tmpfs "$FULL"
  TMPDIR=$FULL run scene $SCENE --plot "$T/trunc.png"
  check "scratch directory full: exit 4 (got $RC)" test "$RC" -eq 4
  check "scratch directory full: message names the incomplete PNG" grep -q 'incomplete PNG' "$ERR"
  check "scratch directory full: no target, nothing left" test ! -e "$T/trunc.png" -a -z "$(ls -A "$FULL")"
  umount "$FULL"
else
  skip "cannot mount a tmpfs (not root?): full-disk tests not run"
fi
# a file size limit (ulimit -f, no root needed): the program ignores SIGXFSZ, so every
# write beyond the limit fails and is reported (exit 4, one line) instead of killing it
# (exit 153) with its scratch files left.  Limits: 1 KiB (the scratch data stops),
# 16 KiB, and 1 KiB below the size of the PNG (gnuplot's PNG or an earlier scratch
# file stops), for scene and calibrate; a limit the plot fits gives the plot
CAL="calibrate data/calibrate/example.csv --radius 1e-3 --density 7800 --wall"
for cmd in "scene $SCENE" "$CAL"; do
  # shellcheck disable=SC2086
  (ulimit -f 4000; exec "$BIN" $cmd --plot "$T/lim.png") >"$OUT" 2>"$ERR"; RC=$?
  check "${cmd%% *} --plot under a limit the plot fits: exit 0, a complete PNG" \
    bash -c "[ $RC -eq 0 ] && python3 -c 'import sys; b = open(sys.argv[1], \"rb\").read(); sys.exit(b[-8:-4] != b\"IEND\")' '$T/lim.png'"
  kib=$(( $(stat -c %s "$T/lim.png" 2>/dev/null || echo 4096) / 1024 - 1 ))
  rm -f "$T/lim.png"
  for lim in 1 16 $kib; do
    # shellcheck disable=SC2086
    (ulimit -f $lim; exec "$BIN" $cmd --plot "$T/lim.png") >"$OUT" 2>"$ERR"; RC=$?
    check "${cmd%% *} --plot under ulimit -f $lim: exit 4 (got $RC: $(head -c 120 "$ERR"))" test "$RC" -eq 4
    check "${cmd%% *} --plot under ulimit -f $lim: stdout empty, one line on stderr" \
      test ! -s "$OUT" -a "$(wc -l <"$ERR")" -eq 1
    check "${cmd%% *} --plot under ulimit -f $lim: no target, no scratch, no temporary file" \
      test ! -e "$T/lim.png" -a ! -e "$T/lim.png.hertzdamp-tmp" -a -z "$(ls -A "$TMPDIR")"
  done
done

# the plot target is one of the command's inputs, under any name: refused (exit 2)
# before any work, the input unchanged
cp $SCENE "$T/in.nml"; cp data/calibrate/example.csv "$T/in.csv"
ln "$T/in.csv" "$T/hard.csv"; ln -s in.nml "$T/sym.nml"
expect_fail 2 "scene --plot its own scene file" scene "$T/in.nml" --plot "$T/in.nml"
expect_fail 2 "scene --plot its scene file through a symbolic link" scene "$T/in.nml" --plot "$T/sym.nml"
check "scene --plot its own scene file: message says so" grep -q 'is the input file' "$ERR"
expect_fail 2 "calibrate --plot its own data file" calibrate "$T/in.csv" --radius 1e-3 --density 7800 --wall \
  --plot "$T/in.csv"
expect_fail 2 "calibrate --plot its data file through a hard link" calibrate "$T/in.csv" --radius 1e-3 \
  --density 7800 --wall --plot "$T/hard.csv"
expect_fail 2 "calibrate --plot its data file as ./path" calibrate "$T/in.csv" --radius 1e-3 --density 7800 --wall \
  --plot "$T/./in.csv"
check "the inputs are unchanged" bash -c "cmp -s $SCENE '$T/in.nml' && cmp -s data/calibrate/example.csv '$T/in.csv'"
check "refused inputs: no scratch left" no_scratch_left

# SIGTERM and SIGINT while gnuplot draws (issue 21): every temporary file removed (in
# $TMPDIR and next to the target), gnuplot stopped before it writes anything, no
# target, and the program ends by that signal (before: leftovers, gnuplot went on and
# wrote its PNG, SIGINT was ignored while it ran).  A stand-in gnuplot answers the
# program's checks at once and draws only after a pause, in which the signal comes.
REAL_GNUPLOT=$(command -v gnuplot)
mkdir -p "$T/slow"
cat >"$T/slow/gnuplot" <<STANDIN
#!/bin/sh
case "\$1" in -e) exec "$REAL_GNUPLOT" "\$@" ;; esac
echo \$\$ >"$T/slow/pid.tmp" && mv "$T/slow/pid.tmp" "$T/slow/pid"
sleep 30
exec "$REAL_GNUPLOT" "\$@"
STANDIN
chmod +x "$T/slow/gnuplot"
# SIG command...: run it with the stand-in first in PATH, send SIG once the stand-in
# waits; prints "<how the program ended> <stand-in alive 2 s later: yes|no>"
signal_during_plot() {
  local sig=$1; shift
  rm -f "$T/slow/pid"
  PATH="$T/slow:$PATH" "$PYTHON" - "$sig" "$T/slow/pid" "$@" <<'PY'
import os, signal, subprocess, sys, time
sig, pidfile, cmd = getattr(signal, "SIG" + sys.argv[1]), sys.argv[2], sys.argv[3:]
p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
for _ in range(600):                      # up to 60 s for the work before the plot
    if os.path.exists(pidfile) or p.poll() is not None:
        break
    time.sleep(0.1)
if not os.path.exists(pidfile):
    if p.poll() is None:
        p.kill()
    p.wait()
    print("no-plot-started unknown")
    sys.exit()
gp = int(open(pidfile).read())
p.send_signal(sig)
try:
    rc = p.wait(timeout=20)
except subprocess.TimeoutExpired:
    p.kill(); p.wait(); rc = "hung"
time.sleep(2)
try:
    os.kill(gp, 0)
    alive = "yes"
except ProcessLookupError:
    alive = "no"
if alive == "yes":                        # do not leave it behind ourselves
    for kill in (lambda: os.killpg(gp, signal.SIGKILL), lambda: os.kill(gp, signal.SIGKILL)):
        try:
            kill()
        except ProcessLookupError:
            pass
ended = ("killed-by-" + signal.Signals(-rc).name) if isinstance(rc, int) and rc < 0 else "exit-%s" % rc
print(ended, alive)
PY
}
for sig in TERM INT; do
  for cmd in "calibrate data/calibrate/example.csv --radius 1e-3 --density 7800 --wall" "scene $SCENE" \
             "bench --quick"; do
    [ "${cmd%% *}" = bench ] && [ $sig = TERM ] && continue   # bench works for seconds first: SIGINT only
    rm -f "$T/sig.png"
    # shellcheck disable=SC2086
    got=$(signal_during_plot $sig "$BIN" $cmd --plot "$T/sig.png")
    check "${cmd%% *} --plot, SIG$sig while gnuplot draws: the program ends by it ($got)" \
      test "${got% *}" = "killed-by-SIG$sig"
    check "${cmd%% *} --plot, SIG$sig while gnuplot draws: gnuplot stopped ($got)" test "${got#* }" = no
    check "${cmd%% *} --plot, SIG$sig: no scratch file left ($(ls -A "$TMPDIR" | head -c 200))" no_scratch_left
    check "${cmd%% *} --plot, SIG$sig: no target, no temporary copy" \
      test ! -e "$T/sig.png" -a ! -e "$T/sig.png.hertzdamp-tmp"
  done
done

echo "$SUITE: $skipped test groups skipped"
finish

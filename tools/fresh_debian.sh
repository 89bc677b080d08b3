#!/usr/bin/env bash
# tools/fresh_debian.sh [DIR]: run `make test` exactly as the README says, on a really
# fresh machine: a minimal Debian 12 root (`debootstrap --variant=minbase bookworm`
# with git, make, python3, python3-pip and python3-venv, nothing else), into which a
# fresh clone of this repository's HEAD is made (committed work only, not the work
# tree).  Prints the time `make test` took (its installs included) and its final
# `N passed, N failed` line; then installs the Python wheel that make test built into a
# fresh venv of a second copy of the base root (no gfortran) and runs the package's tests
# there (log wheel-test.log).  Exits non-zero when either fails.  `--wheel-only [DIR]`:
# the wheel test alone, on the wheel of the last run's root.
#
# DIR (default build/fresh-debian) keeps the debootstrapped root (base/, made once and
# reused: delete it to start over) and the root of the last run (root/, replaced by
# every run, kept for inspection) with its log (make-test.log).  Needs root (or sudo),
# debootstrap (installed when missing) and the Debian and PyPI registries.
#
# What a minimal root lacks and a real machine has, provided here:
#   /proc, /sys, /dev (devtmpfs), /dev/pts and /dev/shm (a tmpfs: MPI's shared memory)
#   are mounted for the run and unmounted on exit, also on failure or a signal;
#   the host's apt sources (its mirror) and its Acquire settings, /etc/resolv.conf,
#   and /etc/hosts as the Debian installer writes it (localhost, the machine's name);
#   what pip is configured with on the host (pip config, PIP_* variables, the CA
#   bundle and files they name), so that PyPI is reachable the same way.
# No locale is set: a fresh root has none (the POSIX locale), and make test must pass
# there.
#   MIRROR=URL  the Debian mirror for debootstrap (default: the host's, else deb.debian.org)
set -euo pipefail

if [ "$(id -u)" != 0 ]; then exec sudo -E bash "$0" "$@"; fi
src=$(cd "$(dirname "$0")/.." && pwd)
wheel_only=0
if [ "${1:-}" = --wheel-only ]; then wheel_only=1; shift; fi
dir=${1:-$src/build/fresh-debian}
mkdir -p "$dir"; dir=$(cd "$dir" && pwd)
base=$dir/base root=$dir/root log=$dir/make-test.log
die() { echo "fresh_debian: $*" >&2; exit 1; }
say() { echo "fresh_debian: $*"; }

# ------------------------------------------------------------ the commit under test
git -C "$src" rev-parse --verify -q HEAD >/dev/null || die "$src is not a git repository with a commit"
commit=$(git -C "$src" rev-parse HEAD)
gitdir=$(cd "$src" && cd "$(git rev-parse --git-common-dir)" && pwd)
[ -z "$(git -C "$src" status --porcelain --untracked-files=no)" ] ||
  say "warning: uncommitted changes in $src are not tested (a clone of HEAD is)"

# ------------------------------------------------------------ mounts (undone on exit)
mounted=()
unmount_all() {
  local i
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
    umount "${mounted[i]}" 2>/dev/null || umount -l "${mounted[i]}" 2>/dev/null ||
      echo "fresh_debian: could not unmount ${mounted[i]}" >&2
  done
  mounted=()
}
trap unmount_all EXIT
trap 'unmount_all; exit 130' INT
trap 'unmount_all; exit 143' TERM
mount_in() {  # type, source, target, options
  mkdir -p "$3"
  mount -t "$1" -o "$4" "$2" "$3" || die "cannot mount $1 on $3"
  mounted+=("$3")
}
# Nothing may be mounted below a root that is about to be deleted: /dev there is the
# host's devtmpfs.
remove_root() {
  [ -e "$1" ] || return 0
  if findmnt -rno TARGET | grep -q "^$1/"; then
    die "something is still mounted below $1 (findmnt | grep $1); unmount it first"
  fi
  rm -rf --one-file-system "$1"
}

# ------------------------------------------------------------ the base root (cached)
host_mirror() {
  local m
  m=$(grep -hoE '^(URIs:|deb) +(\[[^]]*\] +)?https?://[^ ]+/debian/?( |$)' \
        /etc/apt/sources.list.d/*.sources /etc/apt/sources.list 2>/dev/null |
      grep -oE 'https?://[^ ]+' | head -n 1 || true)
  echo "${m:-http://deb.debian.org/debian}"
}
if [ ! -f "$base/.hertzdamp-base-complete" ]; then
  command -v debootstrap >/dev/null || {
    say "installing debootstrap"
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null
  }
  mirror=${MIRROR:-$(host_mirror)}
  remove_root "$base"
  say "debootstrap --variant=minbase bookworm from $mirror into $base"
  t0=$SECONDS
  debootstrap --variant=minbase --include=git,make,python3,python3-pip,python3-venv \
    bookworm "$base" "$mirror" >"$dir/debootstrap.log" 2>&1 ||
    { tail -n 20 "$dir/debootstrap.log" >&2; die "debootstrap failed (log: $dir/debootstrap.log)"; }
  say "base root made in $((SECONDS - t0)) s"
  touch "$base/.hertzdamp-base-complete"
fi

# pip in a root: the host's settings (pip config, PIP_* variables) and the files they name
# (a CA bundle, a wheel directory), so that PyPI is reachable the same way.
pipenv=()
while IFS='=' read -r name value; do
  case $name in PIP_*) pipenv+=("$name=$value") ;; esac
done < <(env)
pip_setup() {  # root: its /etc/pip.conf from the host's settings, with the files they name
  {
    echo "[global]"
    if command -v pip3 >/dev/null; then
      pip3 config list 2>/dev/null | sed -nE "s/^(global|install)\.([a-z-]+)='(.*)'$/\2 = \3/p"
    fi
  } >"$1/etc/pip.conf"
  local f
  for f in $(sed -nE 's/^(cert|client-cert|find-links) = (.*)$/\2/p' "$1/etc/pip.conf") \
           $(printf '%s\n' "${pipenv[@]}" | sed -nE 's/^PIP_(CERT|CLIENT_CERT|FIND_LINKS)=(.*)$/\2/p'); do
    case $f in /*) [ -e "$f" ] && { mkdir -p "$1$(dirname "$f")"; cp -a "$f" "$1$f"; } ;; esac
  done
}

# ------------------------------------------------------------ this run's root
# (--wheel-only: none; the wheel test below takes the wheel of the last run's root)
if [ "$wheel_only" = 1 ]; then rc=0; else
remove_root "$root"
cp -a "$base" "$root"
rm -f "$root/.hertzdamp-base-complete"
# apt: the host's sources (the same mirror and suites) when the host is bookworm, and
# its Acquire settings (a proxy, a snapshot mirror's validity dates).
if grep -qs 'VERSION_CODENAME=bookworm' /etc/os-release; then
  rm -f "$root/etc/apt/sources.list"
  [ -f /etc/apt/sources.list ] && cp /etc/apt/sources.list "$root/etc/apt/"
  cp /etc/apt/sources.list.d/*.sources /etc/apt/sources.list.d/*.list "$root/etc/apt/sources.list.d/" 2>/dev/null || true
fi
apt-config dump 2>/dev/null | grep -E '^Acquire::(https?::Proxy|Check-Valid-Until|Check-Date) ' \
  >"$root/etc/apt/apt.conf.d/99fresh-debian-host" || true
cp -L /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
# /etc/hosts as the Debian installer writes it (debootstrap writes none): without it
# localhost and the machine's name go to DNS, and every MPI start waits for the answer
if [ ! -s "$root/etc/hosts" ]; then
  printf '127.0.0.1\tlocalhost\n127.0.1.1\t%s\n::1\tlocalhost ip6-localhost ip6-loopback\n' \
    "$(cat "$root/etc/hostname" 2>/dev/null || hostname)" >"$root/etc/hosts"
fi
# pip: the host's settings, and the files they name (a CA bundle, a wheel directory).
pip_setup "$root"

say "cloning $commit into $root/root/hertzdamp"
git clone -q --no-hardlinks --no-checkout "$gitdir" "$root/root/hertzdamp"
git -C "$root/root/hertzdamp" checkout -q --detach "$commit"

mount_in proc proc "$root/proc" nosuid,noexec,nodev
mount_in sysfs sys "$root/sys" nosuid,noexec,nodev,ro
mount_in devtmpfs udev "$root/dev" mode=0755,nosuid
mount_in devpts devpts "$root/dev/pts" mode=0620,gid=5,nosuid,noexec
mount_in tmpfs shm "$root/dev/shm" mode=1777,nosuid,nodev

# ------------------------------------------------------------ make test, timed
# The log has each line of make test with the seconds since the start; the longest
# silences are listed at the end (from one line to the next: an install, a build, or
# the test whose summary line ends it).
say "running make test in the fresh root (log: $log)"
start=$(date +%s)
set +e
chroot "$root" /usr/bin/env -i HOME=/root TERM=dumb \
  PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin "${pipenv[@]}" \
  bash -c 'cd /root/hertzdamp && make test' </dev/null 2>&1 |
  while IFS= read -r line; do
    printf '%s\n' "$line"
    printf '%5d %s\n' $(($(date +%s) - start)) "$line" >&3
  done 3>"$log"
rc=${PIPESTATUS[0]}
set -e
elapsed=$(($(date +%s) - start))
summary=$(sed -E 's/^ *[0-9]+ //' "$log" | grep -E '^[0-9]+ passed, [0-9]+ failed$' | tail -n 1 || true)
unmount_all
say "commit $commit"
say "longest steps (seconds between two lines of make test):"
awk 'NR > 1 { d = $1 - t; if (d > 0) printf "%5d s  %.60s  ->  %.60s\n", d, prev, substr($0, 7) }
     { t = $1; prev = substr($0, 7) }' "$log" | sort -rn | head -n 15 | sed 's/^/    /'
say "make test: exit $rc in $((elapsed / 60)) min $((elapsed % 60)) s (installs included)"
say "summary: ${summary:-none (make test did not get to the summary)}"
fi   # wheel_only

# ------------------------------------------------------------ the wheel without a compiler
# The repaired wheel that make test built (test/integration/python_wheel.sh) installed
# into a fresh venv of another copy of the base root, which has python3 and no gfortran:
# python -m hertzdamp and the package's tests that need neither the program nor LAMMPS.
wheel_rc=1
whl=$(ls "$root"/root/hertzdamp/build/python/wheelhouse/hertzdamp-*.whl 2>/dev/null | head -n 1 || true)
if [ -z "$whl" ]; then
  say "wheel: none in $root/root/hertzdamp/build/python/wheelhouse (make test did not build it)"
else
  wroot=$dir/root-wheel wlog=$dir/wheel-test.log
  remove_root "$wroot"
  cp -a "$base" "$wroot"
  cp -L /etc/resolv.conf "$wroot/etc/resolv.conf" 2>/dev/null || true
  pip_setup "$wroot"
  mkdir -p "$wroot/root/src/include" "$wroot/root/src/doc"
  cp "$whl" "$wroot/root/"
  # the tests, and what they read: the header's codes, the README's and the guide's Python blocks
  cp -r "$root/root/hertzdamp/python" "$root/root/hertzdamp/pyproject.toml" "$root/root/hertzdamp/README.md" \
    "$wroot/root/src/"
  cp "$root/root/hertzdamp/include/hertzdamp.h" "$wroot/root/src/include/"
  cp "$root/root/hertzdamp/doc/python.md" "$wroot/root/src/doc/"
  mount_in proc proc "$wroot/proc" nosuid,noexec,nodev
  mount_in devtmpfs udev "$wroot/dev" mode=0755,nosuid
  say "wheel: $(basename "$whl") ($(stat -c %s "$whl") bytes) in a fresh venv of a root without gfortran (log: $wlog)"
  set +e
  chroot "$wroot" /usr/bin/env -i HOME=/root TERM=dumb PATH=/usr/local/bin:/usr/bin:/bin "${pipenv[@]}" bash -c '
    set -e
    if command -v gfortran || find /usr /lib -name "libgfortran.so*" 2>/dev/null | grep -q .; then
      echo "wheel root: gfortran or libgfortran present"; exit 1
    fi
    echo "wheel root: no gfortran, no libgfortran; $(python3 --version)"
    python3 -m venv /root/venv
    /root/venv/bin/pip install -q /root/hertzdamp-*.whl pytest==9.2.0 hypothesis==6.170.17
    cd /tmp && /root/venv/bin/python -m hertzdamp
    PYTHONDONTWRITEBYTECODE=1 /root/venv/bin/python -m pytest -c /root/src/pyproject.toml --rootdir /root/src       -p no:cacheprovider -q -rs -m "not cli and not lammps" /root/src/python/tests' </dev/null >"$wlog" 2>&1
  wheel_rc=$?
  set -e
  unmount_all
  # every selected test must have run
  if [ "$wheel_rc" -eq 0 ] && tail -n 1 "$wlog" | grep -qE 'skipped|failed|error'; then wheel_rc=1; fi
  sed 's/^/    /' "$wlog" | grep -vE '^ +\.+ *\[' | tail -n 12
  say "wheel: exit $wheel_rc ($(grep -E '[0-9]+ passed' "$wlog" | tail -n 1))"
fi
[ "$rc" -eq 0 ] && [ "$wheel_rc" -eq 0 ]
exit $?

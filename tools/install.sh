#!/usr/bin/env bash
# make install PREFIX=dir: build with CMake (CMakeLists.txt), install into a staging
# directory, check that the core library needs nothing but the Fortran runtime, and
# only then copy everything into PREFIX, so that a failed install leaves PREFIX as
# it was.   Usage: bash tools/install.sh ABSOLUTE_PREFIX [BUILD_DIR]
set -euo pipefail
prefix=$1
build=${2:-build/cmake}
cd "$(dirname "$0")/.."
die() { echo "install: $*" >&2; exit 1; }
case "$prefix" in /*) ;; *) die "PREFIX must be an absolute path: $prefix";; esac

mkdir -p "$(dirname "$build")"   # a fresh clone has no build/ yet
cmake -S . -B "$build" -DCMAKE_INSTALL_PREFIX="$prefix" >"$build.configure.log" 2>&1 ||
  { cat "$build.configure.log" >&2; die "cmake configure failed"; }
cmake --build "$build" -j "$(nproc)" >"$build.build.log" 2>&1 ||
  { tail -n 30 "$build.build.log" >&2; die "build failed"; }
stage=$(mktemp -d "${TMPDIR:-/tmp}/hertzdamp-stage.XXXXXX")
trap 'rm -rf "$stage"' EXIT
DESTDIR=$stage cmake --install "$build" >/dev/null
root=$stage$prefix

# The core may need only the Fortran runtime and the C library.
so=$(find "$root" -name 'libhertzdamp.so' | head -n 1)
[ -n "$so" ] || die "libhertzdamp.so was not built"
bad=$(ldd "$so" | awk '{print $1}' | grep -Ev '^(linux-vdso|/lib64/ld-linux|libgfortran|libquadmath|libm\.|libc\.|libgcc_s)' || true)
[ -z "$bad" ] || die "the core library links more than the Fortran runtime: $bad"

mkdir -p "$prefix"
cp -a "$root/." "$prefix/"
echo "installed hertzdamp into $prefix"

#!/usr/bin/env bash
# Install the hertzdamp core for non-fpm users:   bash tools/install.sh FPM FLAGS PREFIX
# (normally through `make install PREFIX=dir`).
#
# Installs under PREFIX
#   lib/libhertzdamp.a, lib/libhertzdamp.so   the core objects only (no GSL peer, no
#                                            generators): they need only the Fortran runtime
#   include/hertzdamp.h                      the C interface
#   include/hertzdamp/*.mod                  the Fortran modules of the core (gfortran-version specific)
#   lib/pkgconfig/hertzdamp.pc               Cflags / Libs / Libs.private
#   bin/hertzdamp                            the command-line program
#
# Everything is built and checked in a staging directory inside PREFIX first and
# moved into place only when complete, so a failure leaves PREFIX as it was.
set -euo pipefail

fpm=$1; flags=$2; prefix=$3
cd "$(dirname "$0")/.."
root=$PWD

# Sources that must stay out of the installed core: the GSL peer solver and any
# generator-only module (a source file carrying the line `!> hertzdamp-install: exclude`).
is_excluded() {
  case "$(basename "$1" .f90)" in
    hertzdamp_gsl | *_gen | *_gen_* | *_generator*) return 0 ;;
  esac
  grep -q '^!> hertzdamp-install: exclude' "$1"
}

die() { echo "install.sh: $*" >&2; exit 1; }

case " $flags " in *" -fPIC "*) ;; *) die "the release flags must contain -fPIC (shared library)";; esac

"$fpm" build --flag "$flags" >/dev/null
bin=$("$fpm" run hertzdamp --flag "$flags" --runner echo 2>/dev/null | tail -n 1)
[ -x "$bin" ] || die "cannot find the hertzdamp executable built by fpm"

# The core sources in dependency order, from fpm's own model of the package
# (`fpm build --dump`: the modules each source provides and uses).  They are compiled
# afresh below with the same flags as fpm's build: fpm 0.12 exposes neither the
# build/gfortran_<hash> directory of a flag set nor a complete compile database
# (build/compile_commands.json lists only what the last run recompiled), and its
# archive also holds the GSL peer.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$fpm" build --flag "$flags" --dump "$work/model.json" >/dev/null
excluded=()
for src in src/*.f90; do is_excluded "$src" && excluded+=("$src"); done
mapfile -t core < <(python3 - "$work/model.json" "${excluded[@]}" <<'PY'
import json, os, sys
model = json.load(open(sys.argv[1]))
excluded = {os.path.normpath(p) for p in sys.argv[2:]}
srcs = model["packages"]["hertzdamp"]["sources"].values()
lib = {os.path.normpath(s["file-name"]): s for s in srcs if s["unit-scope"] == "FPM_SCOPE_LIB"}
def names(x):
    return [x] if isinstance(x, str) else list(x or [])
provider = {m: f for f, s in lib.items() for m in names(s.get("modules-provided"))}
order, state = [], {}
def visit(f):
    if state.get(f) == 2: return
    if state.get(f) == 1: sys.exit("install.sh: module cycle at " + f)
    state[f] = 1
    for m in names(lib[f].get("modules-used")):
        dep = provider.get(m)
        if dep is None: continue          # intrinsic module
        if dep in excluded:
            sys.exit(f"install.sh: core source {f} uses {m} from excluded {dep}")
        visit(dep)
    state[f] = 2
    order.append(f)
for f in sorted(lib):
    if f not in excluded: visit(f)
print("\n".join(order))
PY
)
[ "${#core[@]}" -gt 0 ] || die "no core sources found"
# fpm.toml [fortran]: implicit-typing = false, implicit-external = false, source-form = "free"
fpm_fortran_flags="-fimplicit-none -Werror=implicit-interface -ffree-form"
mkdir -p "$work/obj"
objects=(); modules=()
for src in "${core[@]}"; do
  obj="$work/obj/$(basename "$src" .f90).o"
  # shellcheck disable=SC2086
  gfortran -c $flags $fpm_fortran_flags -J "$work/obj" -I "$work/obj" "$src" -o "$obj"
  objects+=("$obj")
  while read -r mod; do
    modules+=("$work/obj/$mod.mod")
  done < <(sed -nE 's/^[[:space:]]*module[[:space:]]+([A-Za-z0-9_]+)[[:space:]]*(!.*)?$/\1/Ip' "$src" | tr 'A-Z' 'a-z')
done

mkdir -p "$prefix"
prefix=$(cd "$prefix" && pwd)
stage=$(mktemp -d "$prefix/.hertzdamp-install.XXXXXX")
trap 'rm -rf "$work" "$stage"' EXIT
mkdir -p "$stage/lib/pkgconfig" "$stage/include/hertzdamp" "$stage/bin"

# Archive and shared library from the core objects only.
ar rcs "$stage/lib/libhertzdamp.a" "${objects[@]}"
gfortran -shared -Wl,-soname,libhertzdamp.so -Wl,--no-undefined -o "$stage/lib/libhertzdamp.so" "${objects[@]}"
for mod in "${modules[@]}"; do
  [ -f "$mod" ] || die "missing module file $mod"
  cp "$mod" "$stage/include/hertzdamp/"
done
cp include/hertzdamp.h "$stage/include/"
cp "$bin" "$stage/bin/hertzdamp"

# The core must not reference GSL, BLAS or LAPACK, and must be self-contained:
# every hertzdamp symbol an object needs is defined in the archive.
undef=$(nm -u "$stage/lib/libhertzdamp.a" | awk 'NF == 2 {print $2}' | sort -u)
bad=$(grep -E '^(gsl_|cblas_|dgesv_|dgels|dgetr|dpotr|dsyev|dgemm_|dgemv_|daxpy_|ddot_|dnrm2_)|hertzdamp_gsl' <<<"$undef" || true)
[ -z "$bad" ] || die "the core references GSL/LAPACK/BLAS: $(tr '\n' ' ' <<<"$bad")"
defined=$(nm --defined-only "$stage/lib/libhertzdamp.a" | awk 'NF == 3 {print $3}' | sort -u)
missing=$(comm -23 <(grep -E '^__hertzdamp|^hertzdamp' <<<"$undef" || true) <(echo "$defined"))
[ -z "$missing" ] || die "the core needs symbols of excluded sources: $(tr '\n' ' ' <<<"$missing")"
if ldd "$stage/lib/libhertzdamp.so" | grep -Eq 'libgsl|liblapack|libblas|libopenblas'; then
  die "libhertzdamp.so depends on GSL/LAPACK/BLAS"
fi

version=$(sed -nE 's/^version[[:space:]]*=[[:space:]]*"([^"]+)".*/\1/p' fpm.toml)
cat >"$stage/lib/pkgconfig/hertzdamp.pc" <<PC
prefix=$prefix
libdir=\${prefix}/lib
includedir=\${prefix}/include
fmoddir=\${includedir}/hertzdamp

Name: hertzdamp
Description: Damped Hertzian normal collision: restitution and contact time, forward and inverse
Version: $version
Cflags: -I\${includedir} -I\${fmoddir}
Libs: -L\${libdir} -lhertzdamp
Libs.private: -lgfortran -lm
PC

# Move into place (same file system: every mv is a rename).
find "$stage" -mindepth 1 -type d | while read -r dir; do mkdir -p "$prefix/${dir#"$stage"/}"; done
find "$stage" -type f | while read -r file; do mv -f "$file" "$prefix/${file#"$stage"/}"; done
echo "installed hertzdamp $version into $prefix (core: ${#objects[@]} objects, ${#modules[@]} modules)"

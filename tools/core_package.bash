# Sourced by tools/core_build_time.sh, tools/fit_bits.sh, tools/fit_speed.sh and the timing
# tools of min_steps (core_library and release_core, below): a
# temporary fpm package of the core library alone, for timing and comparing revisions.
#   core_package DIR SRC [PROGRAM.f90]
# copies SRC (a core src/ tree) to DIR/src and writes DIR/fpm.toml: no programs, tests
# or examples, or PROGRAM.f90 (copied to DIR/prog/) as its only executable, named after it.
core_package() {
  local dir=$1 src=$2 prog=${3:-}
  mkdir -p "$dir"
  cp -r "$src" "$dir/src"
  {
    printf 'name = "hertzdamp"\n[build]\nauto-executables = false\nauto-tests = false\nauto-examples = false\n'
    printf '[fortran]\nimplicit-typing = false\nimplicit-external = false\nsource-form = "free"\n'
    if [ -n "$prog" ]; then
      mkdir -p "$dir/prog"
      cp "$prog" "$dir/prog/"
      printf '[[executable]]\nname = "%s"\nsource-dir = "prog"\nmain = "%s"\n' "$(basename "$prog" .f90)" "$(basename "$prog")"
    fi
  } > "$dir/fpm.toml"
}

# core_library DIR SRC FPM FLAGS: core_package DIR SRC, built with FPM at FLAGS; prints the
# path of its libhertzdamp.a (the build log on failure, status 1).
core_library() {
  local dir=$1 src=$2 fpm=$3 flags=$4
  core_package "$dir" "$src"
  (cd "$dir" && "$fpm" build --flag "$flags" >"$dir/build.log" 2>&1) || { cat "$dir/build.log" >&2; return 1; }
  find "$dir/build" -name libhertzdamp.a | head -1
}

# release_core DIR ROOT: core_library of SRC (default ROOT/src) with FPM (default ROOT's
# .venv fpm) at the release flags of ROOT/data/release_flags.txt; prints the archive.
release_core() {
  local dir=$1 root=$2
  core_library "$dir" "${SRC:-$root/src}" "${FPM:-$root/.venv/bin/fpm}" "$(grep -v '^#' "$root/data/release_flags.txt")"
}

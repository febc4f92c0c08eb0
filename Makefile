# The two commands: `make demo` and `make test`. Both install what is
# missing (Debian packages as root, a Python virtual environment), build
# into build/ (reused between runs), then run the demo or the tests.
# `make sanitize` runs the same tests on an AddressSanitizer + UBSan build in
# build-sanitize/ (CI runs it after `make test`).
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
BUILD := build
JOBS ?= 2

.PHONY: all deps venv build test test-cpp test-python demo clean sanitize sanitize-build

all: build

deps:
	@tools/setup_deps.sh

$(VENV)/.installed: requirements-dev.txt
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install -q --upgrade pip
	$(PY) -m pip install -q -r requirements-dev.txt
	@touch $@

venv: deps $(VENV)/.installed

$(BUILD)/CMakeCache.txt: | venv
	$(VENV)/bin/cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release \
	  -DBEAMSOLID_INPLACE=ON -DPython_EXECUTABLE=$(abspath $(PY)) \
	  -DCMAKE_MAKE_PROGRAM=$(abspath $(VENV)/bin/ninja)

build: venv $(BUILD)/CMakeCache.txt
	$(VENV)/bin/cmake --build $(BUILD) -j $(JOBS)

test-cpp: build
	$(VENV)/bin/ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

test-python: build
	PYTHONPATH=python $(PY) -m pytest tests/python -q

test: test-cpp test-python

demo: build
	PYTHONPATH=python MPLBACKEND=Agg $(PY) examples/donut_pullout.py

# --- the sanitizer build (issue 13) ---
# Library, extension, example plugin and C++ tests built with
# -fsanitize=address,undefined into their own folder; its Python package is
# build-sanitize/python/beamsolid (the sanitized .so files plus symlinks to the
# working tree's modules), so python/beamsolid's in-place build is untouched.
SAN_BUILD := build-sanitize
SAN_CXX ?= g++
# The Python interpreter is not instrumented, so the sanitizer runtimes must be
# loaded first, before the extension pulls them in; they must be the runtimes of
# the compiler that built it.
SAN_PRELOAD = $(shell readlink -f $$($(SAN_CXX) -print-file-name=libasan.so)) $(shell readlink -f $$($(SAN_CXX) -print-file-name=libubsan.so))
# Any report ends the process with an abort, so it fails ctest and pytest.
SAN_ASAN_COMMON := abort_on_error=1:halt_on_error=1:check_initialization_order=1:strict_init_order=1
SAN_UBSAN := print_stacktrace=1:halt_on_error=1
# Leak detection is off for the Python run only: CPython and pybind11 keep
# interned objects, module state and static type data alive at exit by design,
# so LeakSanitizer would report them; the C++ tests (ctest) keep it on.
# pytest captures file descriptor 2, so a report written there would be lost
# with the aborted process: the Python run writes reports (its children's too)
# into files, and any file there fails the run, even from a child whose
# failure a test expected.
SAN_REPORTS = $(abspath $(SAN_BUILD))/sanitizer-reports
SAN_PYTHON_ENV = LD_PRELOAD="$(SAN_PRELOAD)" PYTHONMALLOC=malloc \
  ASAN_OPTIONS=detect_leaks=0:$(SAN_ASAN_COMMON):log_path=$(SAN_REPORTS)/asan \
  UBSAN_OPTIONS=$(SAN_UBSAN):log_path=$(SAN_REPORTS)/ubsan \
  PYTHONPATH=$(abspath $(SAN_BUILD))/python BEAMSOLID_PLUGIN_DIR=$(abspath $(SAN_BUILD))/plugins
# What pytest runs under the sanitizers (e.g. a single test file, or -k to pick tests).
# test_plugin_install is left to `make test`: it pip-builds a plain package into a
# fresh virtual environment, so no sanitized code runs in it, and it takes minutes.
SAN_PYTEST_ARGS ?= tests/python --ignore=tests/python/test_plugin_install.py

# -O1 -g and no -DNDEBUG: readable stacks, and assertions (Eigen's index checks
# among them) stay on.
$(SAN_BUILD)/CMakeCache.txt: | venv
	$(VENV)/bin/cmake -S . -B $(SAN_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_COMPILER=$(SAN_CXX) -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
	  -DBEAMSOLID_SANITIZE=ON -DBEAMSOLID_INPLACE=ON \
	  -DBEAMSOLID_PACKAGE_DIR=$(abspath $(SAN_BUILD))/python/beamsolid \
	  -DPython_EXECUTABLE=$(abspath $(PY)) -DCMAKE_MAKE_PROGRAM=$(abspath $(VENV)/bin/ninja)

sanitize-build: venv $(SAN_BUILD)/CMakeCache.txt
	$(VENV)/bin/cmake --build $(SAN_BUILD) -j $(JOBS)

sanitize: sanitize-build
	ASAN_OPTIONS=detect_leaks=1:$(SAN_ASAN_COMMON) UBSAN_OPTIONS=$(SAN_UBSAN) \
	  $(VENV)/bin/ctest --test-dir $(SAN_BUILD) --output-on-failure -j $(JOBS)
	rm -rf $(SAN_REPORTS) && mkdir -p $(SAN_REPORTS)
	@# the run below must import the sanitized build, not python/beamsolid
	$(SAN_PYTHON_ENV) $(PY) -c "import beamsolid._beamsolid as b, sys; \
	  sys.exit(0 if b.__file__.startswith('$(abspath $(SAN_BUILD))/') else 'imported ' + b.__file__)"
	$(SAN_PYTHON_ENV) $(PY) -m pytest -q $(SAN_PYTEST_ARGS); status=$$?; \
	  if [ -n "$$(ls -A $(SAN_REPORTS))" ]; then cat $(SAN_REPORTS)/*; \
	    echo "make sanitize: sanitizer reports above (files in $(SAN_REPORTS))"; exit 1; fi; \
	  exit $$status

clean:
	rm -rf $(BUILD) $(SAN_BUILD) python/beamsolid/*.so python/beamsolid/beamsolid_blas \
	  python/beamsolid/include python/beamsolid/cmake

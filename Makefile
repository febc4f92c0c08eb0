# The two commands: `make demo` and `make test`. Both install what is
# missing (Debian packages as root, a Python virtual environment), build
# into build/ (reused between runs), then run the demo or the tests.
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
BUILD := build
JOBS ?= 2

.PHONY: all deps venv build test test-cpp test-python demo clean

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

clean:
	rm -rf $(BUILD) python/beamsolid/*.so

# Two entry points (see README):  `make run`  and  `make test`.
# Both create the project .venv with passagemath on first use.
PYTHON ?= python3.11
VENV   := .venv
PY     := $(VENV)/bin/python
SAGE   := $(VENV)/bin/sage
STAMP  := $(VENV)/.installed

.PHONY: run test doctest pytest bench venv clean

venv: $(STAMP)

$(STAMP): setup.py requirements-dev.txt
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip setuptools wheel
	$(PY) -m pip install --quiet -r requirements-dev.txt
	$(PY) -m pip install --quiet --no-deps -e . --config-settings editable_mode=compat
	touch $(STAMP)

run: $(STAMP)
	$(PY) -m sage_dynsym examples/*.yaml

doctest: $(STAMP)
	$(SAGE) -t --force-lib -p 2 sage_dynsym doc

pytest: $(STAMP)
	$(PY) -m pytest -q tests

test: doctest pytest

bench: $(STAMP)
	$(PY) -m pip install --quiet -r requirements-bench.txt
	for b in bench/bench_*.py; do $(PY) $$b || exit 1; done

clean:
	rm -rf $(VENV) build *.egg-info

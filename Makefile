# Two entry points (see README):  `make run`  and  `make test`.
# Both create the project .venv with passagemath on first use; `make test`
# also registers the SageMath Jupyter kernel in the .venv; `make test-slow`
# installs Debian's chromium for the browser test (idempotent).
PYTHON ?= python3.11
VENV   := .venv
PY     := $(VENV)/bin/python
SAGE   := $(VENV)/bin/sage
STAMP  := $(VENV)/.installed
KERNEL := $(VENV)/share/jupyter/kernels/sagemath/kernel.json
CHROMIUM ?= /usr/bin/chromium

.PHONY: setup timings run test test-slow doctest doctest-long pytest pytest-slow worksheets docs browser kernel chromium bench venv clean

venv: $(STAMP)

setup: $(STAMP) kernel

# uv installs the ~200 wheels in parallel, pip where uv cannot be installed.
# Both compile the modules to bytecode, as pip does by default: without it,
# every process of the tests compiles Sage's modules again.
$(STAMP): setup.py requirements-dev.txt
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip setuptools wheel
	if $(PY) -m pip install --quiet uv; then \
	  INSTALL="$(PY) -m uv pip install --quiet --native-tls --compile-bytecode --python $(PY)"; \
	else INSTALL="$(PY) -m pip install --quiet"; fi; \
	$$INSTALL -r requirements-dev.txt && \
	$$INSTALL --no-deps -e . -C editable_mode=compat
	touch $(STAMP)

run: $(STAMP)
	$(PY) -m sage_dynsym examples/*.yaml

# the SageMath kernel spec (passagemath installs it; re-created if missing)
kernel: $(KERNEL)

$(KERNEL): | $(STAMP)
	$(PY) -c "from sage.repl.ipython_kernel.install import SageKernelSpec; SageKernelSpec.update(prefix='$(abspath $(VENV))')"
	test -f $(KERNEL)

chromium:
	@command -v chromium >/dev/null 2>&1 || test -x $(CHROMIUM) || { \
	  SUDO=$$(test "$$(id -u)" = 0 || echo sudo); \
	  $$SUDO apt-get update -qq && $$SUDO apt-get install -y -qq chromium; }

# every module imported and Maxima started once, before the fork of each
# file's process (tests/sage_doctest_environment.py): half the time
DOCTEST_ENV := PYTHONPATH=tests$${PYTHONPATH:+:$$PYTHONPATH}
DOCTEST := $(DOCTEST_ENV) $(SAGE) -t --force-lib -p 2 --environment=sage_doctest_environment

# the files in the order of their last times, slowest first (sage -t's own
# order; on a machine where it never ran, from tests/doctest_timings.json):
# no slow file left for the end, with the other process idle
DOCTEST_STATS := $(VENV)/doctest-timings.json

$(DOCTEST_STATS): tests/doctest_timings.json | $(STAMP)
	cp tests/doctest_timings.json $@

doctest: $(STAMP) $(DOCTEST_STATS)
	$(DOCTEST) --stats-path=$(DOCTEST_STATS) sage_dynsym doc/*.rst

# refresh tests/doctest_timings.json and tests/pytest_timings.json (the
# order of make test) after `make doctest`, from a timed run of the pytest set
timings: $(STAMP) kernel
	$(PY) tests/update_timings.py

# the examples marked `# long time` (pictures), in the files that have them
doctest-long: $(STAMP)
	$(DOCTEST) --long $$(grep -rl --include='*.py' --include='*.rst' '# long time' sage_dynsym doc --exclude-dir=_build)

# two processes (pytest-xdist), a file's tests on one process, the slowest
# files first (tests/conftest.py); the slowest tests listed at the end
PYTEST := $(PY) -m pytest -q -n 2 --dist loadfile --no-loadscope-reorder --durations=10

pytest: $(STAMP) kernel
	$(PYTEST) -m "not slow" tests --ignore=tests/browser

# the long cross-checks, every worksheet, the pictures of the doctests, the
# documentation (Sphinx -W) and the browser test (CI runs them after `make test`)
test-slow:
	@tests/timed.sh $(MAKE) setup chromium -- pytest-slow doctest-long docs browser

# the property-based tests (marked fuzz) again, on all their examples
pytest-slow: $(STAMP) kernel
	SAGE_DYNSYM_FUZZ=full $(PYTEST) -m "slow or fuzz" tests --ignore=tests/browser

worksheets: $(STAMP) kernel
	$(PY) -m pytest -q tests/test_worksheets.py

docs: $(STAMP)
	rm -rf doc/_build
	$(PY) -m sphinx -W -q -b html doc doc/_build/html

browser: $(STAMP) kernel chromium
	CHROMIUM=$$(command -v chromium || echo $(CHROMIUM)) $(PY) -m pytest -q tests/browser

# every part timed; the times are printed at the end (also when a part fails).
# The set-up (the .venv on the first run, the kernel spec) is timed apart.
test:
	@tests/timed.sh $(MAKE) setup -- doctest pytest

bench: $(STAMP)
	$(PY) -m pip install --quiet -r requirements-bench.txt
	for b in bench/bench_*.py; do $(PY) $$b || exit 1; done

clean:
	rm -rf $(VENV) build *.egg-info doc/_build doc/api

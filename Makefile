# Two entry points: `make run` (the main job) and `make test` (the tests).
# Both create the local virtual environment .venv on first use (`make test` adds the test tools to it).
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
TEST_STAMP := $(VENV)/.installed-test
KATEX := node_modules/.installed

# `install ARGS`: uv installs ARGS into .venv (the versions pip would choose, in about 5 s where pip takes
# about 30: it resolves, downloads and unpacks in parallel); pip installs uv from PyPI first. Where uv cannot
# be had or cannot reach the index, pip installs ARGS itself, and says so. uv compiles the bytecode as pip
# does: where PYTHONDONTWRITEBYTECODE is set, Python cannot cache it on first import, and every process the
# tests start would compile SymPy again (about 4 s each).
define install
	@$(BIN)/python -m pip install --quiet uv \
	&& $(BIN)/uv pip install --quiet --native-tls --compile-bytecode --python $(BIN)/python $(1) \
	|| { echo "make: uv could not install $(1); pip installs it (about a minute)"; \
	     $(BIN)/python -m pip install --quiet --upgrade pip && $(BIN)/python -m pip install --quiet $(1); }
endef

.PHONY: run test clean

$(STAMP): pyproject.toml setup.py symfloat/geometry/_clipped.c
	@echo "make: creating $(VENV) and installing symfloat with what the main job needs (once; a few seconds)"
	$(PYTHON) -m venv $(VENV)
	@echo "make: installing sympy, mpmath, python-flint, numpy, matplotlib, nbclient ..."
	$(call install,-e .)
	$(BIN)/python -c "from symfloat.report.notebook_html import install; install()"
	touch $(STAMP)
	@echo "make: $(VENV) is ready"

# The tests' own tools, added to the same environment by the first `make test`: pytest with xdist and
# hypothesis, Sphinx and MyST-NB for the site, Dask and pyarrow for the atlas, Playwright for the browser.
$(TEST_STAMP): $(STAMP)
	@echo "make: adding the test tools (pytest, hypothesis, Sphinx, MyST-NB, Dask, pyarrow, Playwright) ..."
	$(call install,-e '.[test]')
	touch $(TEST_STAMP)

# KaTeX, which typesets the site's mathematics at build time (symfloat/site/typeset.py), pinned by
# package-lock.json; without node the site's tests skip and say why.
$(KATEX): package.json package-lock.json
	@if command -v npm >/dev/null 2>&1; then npm ci --no-audit --no-fund --loglevel=error && touch $(KATEX); \
	else echo "make: npm not found: KaTeX is not installed, so the site cannot be built (install node >= 18)" >&2; fi

# The checkout's own modules compiled to bytecode before each run, for the reason `install` gives: where
# PYTHONDONTWRITEBYTECODE is set, every process would compile them again (about 0.4 s for one that imports the
# checker and a few derivations; a scene's 0.4 s of CPU becomes 0.33). compileall skips what is up to date.
COMPILE := $(BIN)/python -m compileall -q -j 0 symfloat derivations >/dev/null

run: $(STAMP)
	@echo "make: symfloat run checks every derivation (finished checks are cached) and writes every record; one line per derivation follows"
	@$(COMPILE)
	$(BIN)/symfloat run

test: $(TEST_STAMP) $(KATEX)
	@$(COMPILE)
	$(BIN)/python -m pytest -q -n 2 --dist loadfile

clean:
	rm -rf $(VENV) .symfloat-cache node_modules

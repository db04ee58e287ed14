# Two entry points: `make run` (the main job) and `make test` (the tests).
# Both create the local virtual environment .venv on first use.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
KATEX := node_modules/.installed

.PHONY: run test clean

$(STAMP): pyproject.toml setup.py symfloat/geometry/_clipped.c
	@echo "make: creating $(VENV) and installing symfloat with its dependencies (once; a few minutes)"
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	@echo "make: pip is installing sympy, mpmath, numpy, matplotlib, nbclient and the test tools ..."
	$(BIN)/python -m pip install --quiet -e '.[test]'
	$(BIN)/python -c "from symfloat.report.notebook_html import install; install()"
	touch $(STAMP)
	@echo "make: $(VENV) is ready"

# KaTeX, which typesets the site's mathematics at build time (symfloat/site/typeset.py), pinned by
# package-lock.json; without node the site's tests skip and say why.
$(KATEX): package.json package-lock.json
	@if command -v npm >/dev/null 2>&1; then npm ci --no-audit --no-fund --loglevel=error && touch $(KATEX); \
	else echo "make: npm not found: KaTeX is not installed, so the site cannot be built (install node >= 18)" >&2; fi

run: $(STAMP)
	@echo "make: symfloat run checks every derivation (finished checks are cached) and writes every record; one line per derivation follows"
	$(BIN)/symfloat run

test: $(STAMP) $(KATEX)
	$(BIN)/python -m pytest -q -n 2 --dist loadfile

clean:
	rm -rf $(VENV) .symfloat-cache node_modules

# Two entry points: `make run` (the main job) and `make test` (the tests).
# Both create the local virtual environment .venv on first use.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: run test clean

$(STAMP): pyproject.toml
	@echo "make: creating $(VENV) and installing symfloat with its dependencies (once; a few minutes)"
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	@echo "make: pip is installing sympy, mpmath, numpy, matplotlib, nbclient and the test tools ..."
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $(STAMP)
	@echo "make: $(VENV) is ready"

run: $(STAMP)
	@echo "make: symfloat run checks every derivation (finished checks are cached) and writes every record; one line per derivation follows"
	$(BIN)/symfloat run

test: $(STAMP)
	$(BIN)/python -m pytest -q -n 2 --dist loadfile

clean:
	rm -rf $(VENV) .symfloat-cache

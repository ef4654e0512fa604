# frictionlab: two commands on a fresh machine, `make demo` and `make test`.
PYTHON ?= $(shell command -v python3.11 2>/dev/null || command -v python3)
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
OUT    ?= out/demo

.PHONY: demo test test-fast check lint typecheck docs pytest bench clean venv schemas

venv: $(STAMP)

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e ".[dev]"
	$(BIN)/frictionlab warmup --quiet
	touch $(STAMP)

demo: $(STAMP)
	$(BIN)/python -c "import skfem" 2>/dev/null || $(BIN)/python -m pip install --quiet -e ".[fem]"
	$(BIN)/frictionlab warmup --quiet
	$(BIN)/frictionlab demo --out $(OUT)

# The whole test suite: lint, type check, the docs site (strict), then every test.
test: check docs pytest

check: lint typecheck

lint: $(STAMP)
	$(BIN)/ruff check src tests benchmarks examples
	$(BIN)/ruff format --check src tests benchmarks examples

typecheck: $(STAMP)
	$(BIN)/mypy

# The documentation site (mkdocs + mkdocstrings, API pages from the docstrings) into site/;
# --strict: any warning (a broken link, a docstring that does not parse) is an error.
docs: $(STAMP)
	$(BIN)/mkdocs build --strict --quiet

# --dist loadfile: each test file on one worker, so a module-scoped fixture (the whole demo,
# the Hertz-Mindlin solve) runs once and not once per worker.
pytest: $(STAMP)
	$(BIN)/python -m pytest -n auto --dist loadfile -q

# While developing: lint, type check and the tests not marked slow (no docs site).
test-fast: check
	$(BIN)/python -m pytest -n auto --dist loadfile -q -m "not slow"

# docs/schemas/*.json and the key tables of the docs, from src/frictionlab/schema/.
schemas: $(STAMP)
	$(BIN)/python -m frictionlab.schema

bench: $(STAMP)
	$(BIN)/python benchmarks/run_all.py

clean:
	rm -rf $(VENV) out site .pytest_cache .mypy_cache .ruff_cache .hypothesis

#!/usr/bin/env bash
# The Python step of .ci/run: a fresh virtual environment, the package built and installed by
# `pip install ./routh-py` (maturin build backend), and pytest on routh-py/tests. Any non-zero
# pytest exit code fails, including 5 (no tests collected).
# The extension is built in the workspace's target/ (release profile), so after the first run
# only what changed is rebuilt; each step prints its start time (docs/python.md: how long).
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v python3 >/dev/null 2>&1; then
  echo "python3 not found: the Python step cannot run" >&2
  exit 1
fi
step() { echo "-- $(date -u +%T) $*"; }
ROOT="$PWD"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
step "fresh venv in $WORK/venv"
python3 -m venv "$WORK/venv"
PY="$WORK/venv/bin/python"
step "pip install maturin numpy pytest matplotlib sympy pandas dask[distributed] psutil"
# sympy for the formulas' round trip (routh-py/tests/test_formulas.py); pandas and
# dask[distributed] (the extra `routh[dask]`) for routh.study's tests on a LocalCluster of 2
# worker processes (routh-py/tests/test_study.py); psutil to check that no worker process is left.
"$PY" -m pip install -q maturin numpy pytest matplotlib sympy pandas "dask[distributed]" psutil
step "pip install ./routh-py"
"$PY" -m pip install -q ./routh-py
step "pytest routh-py/tests"
# Run from outside the source tree so that the installed package is the one tested.
cd "$WORK"
MPLBACKEND=Agg timeout 600 "$PY" -m pytest -q -p no:cacheprovider "$ROOT/routh-py/tests"
step "done"

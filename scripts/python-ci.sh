#!/usr/bin/env bash
# The Python step of .ci/run: a fresh virtual environment, the package built and installed by
# `pip install ./routh-py` (maturin build backend), and pytest on routh-py/tests. Any non-zero
# pytest exit code fails, including 5 (no tests collected).
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v python3 >/dev/null 2>&1; then
  echo "python3 not found: the Python step cannot run" >&2
  exit 1
fi
PYVENV="$(mktemp -d)"
trap 'rm -rf "$PYVENV"' EXIT
python3 -m venv "$PYVENV/venv"
PY="$PYVENV/venv/bin/python"
"$PY" -m pip install -q maturin numpy pytest matplotlib
"$PY" -m pip install -q ./routh-py
# Run from outside the source tree so that the installed package is the one tested.
cd "$PYVENV"
MPLBACKEND=Agg timeout 600 "$PY" -m pytest -q -p no:cacheprovider "$OLDPWD/routh-py/tests"

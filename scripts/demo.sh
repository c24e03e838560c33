#!/usr/bin/env bash
# Installs what is needed, builds, runs every example (C++ and Python), writes the
# figures into out/ with out/index.html, and prints a summary table.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
BUILD_DIR=build bash scripts/build.sh
mkdir -p out
PYTHONPATH="$PWD/build/python" /usr/bin/python3 examples/run_demo.py --build build --out out

#!/usr/bin/env bash
# Installs what is needed, builds, runs every example (C++ and Python), writes the
# figures into out/ with out/index.html, and prints a summary table.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# The demo needs neither the tests nor the benchmarks: it builds in a third of the time.
BUILD_DIR=build bash scripts/build.sh -DSILLAGE_BUILD_TESTS=OFF -DSILLAGE_BUILD_BENCH=OFF
mkdir -p out
PYTHONPATH="$PWD/build/python" /usr/bin/python3 examples/run_demo.py --build build --out out

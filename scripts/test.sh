#!/usr/bin/env bash
# Installs what is needed, builds, then runs every test: CTest (C++) and pytest (Python).
# SANITIZE=1 builds into build-asan/ with AddressSanitizer + UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
if [ "${SANITIZE:-0}" = "1" ]; then
  export BUILD_DIR=build-asan BUILD_TYPE=RelWithDebInfo
  bash scripts/build.sh -DSILLAGE_SANITIZE=ON -DSILLAGE_BUILD_TESTS=ON -DSILLAGE_BUILD_BENCH=OFF -DSILLAGE_BUILD_PYTHON=OFF
  export ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
else
  export BUILD_DIR=build
  # ON explicitly: the demo leaves the tests and benchmarks OFF in the same build directory.
  bash scripts/build.sh -DSILLAGE_BUILD_TESTS=ON -DSILLAGE_BUILD_BENCH=ON -DSILLAGE_BUILD_PYTHON=ON
fi

status=0
if [ "${SANITIZE:-0}" = "1" ]; then
  # The install tests build unsanitized consumers: they belong to the plain run.
  (cd "$BUILD_DIR" && ctest --output-on-failure -j "$(nproc)" -E '^install\.') || status=1
else
  (cd "$BUILD_DIR" && ctest --output-on-failure -j "$(nproc)") || status=1
fi

if [ "${SANITIZE:-0}" != "1" ]; then
  # pytest exits 5 when it collects nothing: that is a failure of the suite here too.
  PYTHONPATH="$PWD/$BUILD_DIR/python" /usr/bin/python3 -m pytest -q tests/python || status=1
fi
exit $status

#!/usr/bin/env bash
# `pip install --no-build-isolation .` into a fresh virtual environment, offline,
# then imports the installed package and uses it. With a build directory as
# argument, pip takes the module from it (SILLAGE_BUILD_DIR, setup.py) rather
# than compiling the whole library a second time.
set -euo pipefail
if [ $# -ge 1 ]; then export SILLAGE_BUILD_DIR="$1"; fi
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 -m venv --system-site-packages "$work/venv"
# A copy of the sources, so that the build leaves the checkout untouched.
mkdir -p "$work/src"
git -C "$source_dir" ls-files -z --cached --others --exclude-standard \
  | (cd "$source_dir" && xargs -0 cp --parents -t "$work/src")
"$work/venv/bin/pip" install --quiet --no-build-isolation --no-index "$work/src" > "$work/pip.log" 2>&1 \
  || { cat "$work/pip.log"; exit 1; }
cd "$work"
"$work/venv/bin/python" - <<'PY'
import sillage
assert "venv" in sillage.__file__, sillage.__file__
x = sillage.IntervalVector([[-10, 10], [-10, 10]])
sillage.CtcFunction(sillage.Function(["a", "b"], "a^2 + b^2"), sillage.Interval(0, 1)).contract(x)
assert x[0].ub() <= 1.0000001, x
print("pip: installed package works:", x)
PY

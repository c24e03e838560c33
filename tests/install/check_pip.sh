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

# The contractor test kit, installed with the package, on a toy contractor: y = 2 x.
import random
from sillage import Interval, testing as kit
assert "venv" in kit.__file__, kit.__file__

def double_case(rng):
    t = rng.uniform(-3, 3)
    return kit.Case([kit.around(Interval(t), rng), kit.around(Interval(2 * t), rng)], [Interval(t), Interval(2 * t)])

def contract(d):
    d[1] &= 2 * d[0]
    d[0] &= d[1] / 2

kit.check_laws(contract, double_case, cases=5)
try:
    kit.check_laws(lambda d: d.__setitem__(1, Interval(1e6, 1e7)), double_case, cases=5)
    raise SystemExit("pip: the test kit missed a contractor that grows a domain")
except AssertionError as e:
    assert "contraction" in str(e), e
print("pip: sillage.testing checks a contractor")
PY

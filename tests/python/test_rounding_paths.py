"""The rounding path of the interval core, chosen once per process from the
environment (SILLAGE_ROUNDING): the portable path gives the bounds of the
default one bit for bit, and a value that is neither 'portable' nor 'auto' is
reported instead of being silently ignored."""
import os
import subprocess
import sys
from pathlib import Path

import sillage

# Bounds, in hex, of + - * / sqr sqrt on operands with inexact results,
# zero-straddling, unbounded and empty cases.
SCRIPT = """
import sillage as s
I = s.Interval
xs = [I(0.1, 0.3), I(-0.7, 0.2), I(-3.0, -1e-300), I(0.0, float('inf')), I.empty(), I(1e308, 1.7e308)]
out = []
for x in xs:
    out.append([s.sqr(x).lb().hex(), s.sqr(x).ub().hex(), s.sqrt(x).lb().hex(), s.sqrt(x).ub().hex()])
    for y in xs:
        for r in (x + y, x - y, x * y, x / y):
            out.append([r.lb().hex(), r.ub().hex()])
print(out)
"""


def run(rounding):
    env = dict(os.environ)
    package_root = str(Path(sillage.__file__).resolve().parent.parent)
    env["PYTHONPATH"] = os.pathsep.join([package_root, env.get("PYTHONPATH", "")])
    env["SILLAGE_ROUNDING"] = rounding
    return subprocess.run([sys.executable, "-c", SCRIPT], capture_output=True, text=True, env=env, timeout=120)


def test_portable_path_gives_the_same_bounds():
    auto, portable = run("auto"), run("portable")
    assert auto.returncode == 0, auto.stderr
    assert portable.returncode == 0, portable.stderr
    assert auto.stdout == portable.stdout
    assert "SILLAGE_ROUNDING" not in auto.stderr + portable.stderr


def test_unknown_value_is_reported():
    r = run("fast")
    assert r.returncode == 0, r.stderr
    assert "SILLAGE_ROUNDING=fast" in r.stderr
    assert r.stdout == run("auto").stdout

"""numpy is optional (plots, array conversions and Function.eval_batch, which returns an
array): the README's first lines run where it cannot be imported."""
import os
import subprocess
import sys
from pathlib import Path

import sillage

SCRIPT = """
import sys
sys.modules["numpy"] = None  # import numpy now raises ImportError
import sillage as sl
x = sl.IntervalVector([[-10, 10], [-10, 10]])
f = sl.Function(["x1", "x2"], "sqrt((x1-1)^2 + (x2-2)^2)")
print(f.eval(x))
sl.CtcFunction(f, sl.Interval(2, 3)).contract(x)
p = sl.sivia(sl.IntervalVector([[-5, 5], [-5, 5]]), f, sl.Interval(2, 3), 0.05)
m = sl.IntervalMatrix([[[0, 1], [2, 3]], [[4, 5], [6, 7]]])
print(len(p.inner()) > 0, len(p.boundary()) > 0, x[0], m)
"""


def test_readme_lines_without_numpy():
    env = dict(os.environ)
    package_root = str(Path(sillage.__file__).resolve().parent.parent)
    env["PYTHONPATH"] = os.pathsep.join([package_root, env.get("PYTHONPATH", "")])
    r = subprocess.run([sys.executable, "-c", SCRIPT], capture_output=True, text=True, env=env, timeout=120)
    assert r.returncode == 0, r.stderr
    assert "True True" in r.stdout

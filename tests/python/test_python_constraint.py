"""kind = "python" in a problem file: a user's sillage.TubeCtc subclass joins the network of
sillage.solve(path), with keyword parameters; Emptied(arg, slice=k) makes the emptiness message
say where; the sillage command (no Python in it) says that the file needs Python."""
import subprocess
import textwrap
from pathlib import Path

import pytest

import sillage

BUILD = Path(sillage.__file__).resolve().parents[2]
SILLAGE = BUILD / "tools" / "sillage" / "sillage"

MODULE = textwrap.dedent('''
    import sillage

    class Clamp(sillage.TubeCtc):
        """x in [lo, hi] at every time."""
        def __init__(self, lo, hi):
            super().__init__()
            self.box = sillage.Interval(lo, hi)

        def contract(self, domains):
            x = domains[0]
            for k in range(x.nb_slices()):
                x.set(x.slice(k) & self.box, k)
            for k in range(x.nb_slices() + 1):
                x.set_gate(k, x.gate(k) & self.box)

    class NoneAtSlice3(sillage.TubeCtc):
        def contract(self, domains):
            return sillage.Emptied(1, slice=3, component=1)
''')

PROBLEM = textwrap.dedent('''
    [time]
    domain = [0, 1]
    delta = 0.1
    [var.x]
    kind = "tube"
    value = "[-10, 10]"
    [var.p]
    kind = "tube_vector"
    dim = 2
    [[constraint]]
    kind = "python"
    module = "{module}"
    class = "{cls}"
    args = {args}
    {params}
''')


def write(tmp_path, cls="Clamp", args='["x"]', params="params = { lo = 0, hi = 0.5 }", module="user_ctcs"):
    (tmp_path / "user_ctcs.py").write_text(MODULE)
    path = tmp_path / f"{cls}.toml"
    path.write_text(PROBLEM.format(module=module, cls=cls, args=args, params=params))
    return path


def test_a_python_contractor_joins_the_file(tmp_path):
    r = sillage.solve(str(write(tmp_path)))
    assert not r.empty
    x = r.domains["x"]
    assert x.codomain().lb() == 0 and x.codomain().ub() == 0.5


def test_emptied_repr():
    assert repr(sillage.Emptied(1, slice=3, component=1)) == "Emptied(1, slice=3, component=1)"
    assert repr(sillage.Emptied(0, gate=2)) == "Emptied(0, gate=2)"


def test_emptied_says_where(tmp_path):
    r = sillage.solve(str(write(tmp_path, cls="NoneAtSlice3", args='["x", "p"]', params="")))
    assert r.empty
    assert "p[1]" in r.why_empty and "slice 3" in r.why_empty, r.why_empty
    assert "NoneAtSlice3" in r.why_empty


def test_errors_name_the_constraint(tmp_path):
    with pytest.raises(sillage.Error, match=r"cannot build no_such_module\.Clamp: ModuleNotFoundError"):
        sillage.solve(str(write(tmp_path, module="no_such_module")))
    with pytest.raises(sillage.Error, match=r"found no class 'Nope' in the module user_ctcs"):
        sillage.solve(str(write(tmp_path, cls="Nope")))
    with pytest.raises(sillage.Error, match=r"unexpected keyword argument 'high'"):
        sillage.solve(str(write(tmp_path, params="params = { lo = 0, high = 1 }")))
    with pytest.raises(sillage.ParseError, match=r"expected a tube or tube_vector variable"):
        sillage.load_problem(str(write(tmp_path, args='["nope"]')))
    with pytest.raises(sillage.ParseError, match=r"expected a Python module name"):
        sillage.load_problem(str(write(tmp_path, module="my-ctc")))


def test_the_command_says_it_needs_python(tmp_path):
    path = write(tmp_path)
    r = subprocess.run([str(SILLAGE), "solve", str(path), "--out", str(tmp_path / "out")],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 2
    assert "needs Python, and the sillage command runs none: solve this file from Python" in r.stderr, r.stderr
    assert "sillage.solve(" in r.stderr
    assert subprocess.run([str(SILLAGE), "check", str(path)], capture_output=True, text=True).returncode == 0

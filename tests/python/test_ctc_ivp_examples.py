"""The CtcIvp resolutions of the chapter 4 examples (examples/python/lissajous.py,
kidnapped_robot.py) on coarse slicings: the truth and the extreme paths stay
inside, and CtcIvp is tighter than the CtcDeriv network where docs/ivp.md says so."""
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "examples" / "python"))
lissajous = pytest.importorskip("lissajous")
kidnapped = pytest.importorskip("kidnapped_robot")


def test_lissajous_ivp_holds_the_truth_and_beats_the_network():
    x_true, dx_true, _ = lissajous.truths()
    x, dx, ok = lissajous.solve_ivp(0.05)
    assert ok and x.contains(x_true) and dx.contains(dx_true)
    n = x.nb_slices()
    xd, _, _, _ = lissajous.solve(0.05)
    # the initial box is 0.4 x 0.4: CtcIvp adds little to it, the network much more
    assert x.gate(n)[1].diam() < 0.5 and x.gate(n)[1].diam() < xd.gate(xd.nb_slices())[1].diam()
    assert x.gate(n).is_subset(xd.gate(xd.nb_slices()))


def test_kidnapped_ivp_holds_the_extreme_paths():
    td = kidnapped.make_tdomain(0.05)
    xi, ok, k37 = kidnapped.solve_ivp(td)
    assert ok
    paths = kidnapped.reference_paths(0.05)
    assert kidnapped.max_excess(xi, paths) <= 1e-9
    n = td.nb_slices()
    x, _, _ = kidnapped.solve(td)
    d = [kidnapped.diagonal(t.gate(k).subvector(0, 1)) for t in (x, xi) for k in (0, k37, n)]
    assert d[4] == pytest.approx(d[1])  # the measurement box at 37
    assert d[5] < 0.2 * d[2] and d[3] < d[0]  # forward far tighter, backward tighter too

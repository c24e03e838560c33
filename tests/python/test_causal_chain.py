"""The causal chain example (thesis 4.4.1, examples/python/causal_chain.py): the CtcIvp
resolution beside the CtcDeriv network contains the true path, is bounded and tighter
than the network's from x0, and keeps the final box when it is given."""
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "examples" / "python"))
cc = pytest.importorskip("causal_chain")
from sillage import TDomain  # noqa: E402


def truth_inside(x, path, n):
    g = [x[i].gates_array() for i in range(3)]
    return all(g[i][k, 0] - 1e-9 <= path[k, i] <= g[i][k, 1] + 1e-9 for i in range(3) for k in range(n + 1))


def test_ivp_from_x0_is_tighter_than_the_network():
    td = TDomain(0.0, cc.TF, 0.05)
    n = td.nb_slices()
    x, stats = cc.solve(td, False)
    xi, ivp = cc.solve_ivp(td, False)
    assert not ivp.empty and not stats.empty and not xi.is_empty()
    for i in (0, 1):
        assert xi.gate(n)[i].is_subset(x.gate(n)[i])
        assert xi.gate(n)[i].diam() < 0.8 * x.gate(n)[i].diam()
    # measured at delta = 0.05: x(14) in [47.26, 62.61] x [-5.04, 20.90]
    assert xi.gate(n)[0].diam() < 16 and xi.gate(n)[1].diam() < 26


def test_ivp_truth_inside_with_the_final_box():
    td = TDomain(0.0, cc.TF, cc.DT)  # the truth is sampled at the example's slicing
    n = td.nb_slices()
    xi, ivp = cc.solve_ivp(td, True)
    assert not ivp.empty and xi.gate(n).is_subset(cc.FINAL)
    assert truth_inside(xi, cc.truth(n), n)


def test_main(tmp_path, monkeypatch):
    monkeypatch.setattr(sys, "argv", ["causal_chain.py", "--out", str(tmp_path)])
    cc.main()
    assert (tmp_path / "causal_chain_x0_deriv_vs_ivp_py.png").exists()

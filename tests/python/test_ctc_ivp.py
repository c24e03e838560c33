"""CtcIvp from Python: x' = -sin x against its closed form, the harmonic
oscillator on a TubeVector, an input tube, a network, errors and the laws."""
import math

import pytest
import sillage
from sillage import CtcDeriv, CtcIvp, Function, Interval, IntervalVector, TDomain, Tube, TubeVector

from sillage import testing as kit


def sin_flow(x0, t):
    """x(t) = 2 atan(e^-t tan(x0/2)), enclosed in interval arithmetic."""
    return Interval(2) * sillage.atan(sillage.exp(-t) * sillage.tan(Interval(x0) / Interval(2)))


def test_sin_closed_form_and_width():
    td = TDomain(0.0, 10.0, 0.5)
    x = Tube(td)
    x.set_gate(0, Interval(1))
    assert CtcIvp(Function(["x"], "-sin(x)")).contract(x) is True
    for k in range(td.nb_slices() + 1):
        assert x.gate(k).intersects(sin_flow(1.0, Interval(td.t(k))))
    assert x.gate(td.nb_slices()).diam() < 1e-15
    assert x.gate(td.nb_slices()).intersects(sin_flow(1.0, Interval(10.0)))


def test_tighter_than_ctc_deriv():
    td = TDomain(0.0, 10.0, 0.01)
    x = Tube(td)
    x.set_gate(0, Interval(1))
    v = Tube(td)
    net = sillage.ContractorNetwork()
    net.add(sillage.CtcFunction(Function(["v", "x"], "v + sin(x)")), [v, x])
    net.add(CtcDeriv(), [x, v])
    net.contract()
    y = Tube(td)
    y.set_gate(0, Interval(1))
    CtcIvp(Function(["x"], "-sin(x)")).contract(y)
    assert y.gate(td.nb_slices()).diam() < 1e-6 * x.gate(td.nb_slices()).diam()


def test_harmonic_oscillator_tube_vector():
    td = TDomain(0.0, 20 * math.pi, 0.5)
    x = TubeVector(td, 2)
    x.set_gate(0, IntervalVector([Interval(0), Interval(1)]))
    ctc = CtcIvp(Function(["x1", "x2"], "(x2, -x1)"))
    assert ctc.nb_states() == 2 and ctc.nb_inputs() == 0 and ctc.order() == 20
    assert ctc.contract(x)
    n = td.nb_slices()
    t = Interval(td.t(n))
    assert x.gate(n)[0].intersects(sillage.sin(t))
    assert x.gate(n)[1].intersects(sillage.cos(t))
    assert x.gate(n).max_diam() < 1e-11


def test_input_tube_covers_every_input():
    # x' = -x + u, u(t) in [-0.1, 0.1], x(0) = 1: x(t) in e^-t ± 0.1 (1 - e^-t), attained by u = ±0.1.
    td = TDomain(0.0, 3.0, 0.25)
    x = Tube(td)
    x.set_gate(0, Interval(1))
    u = Tube(td, Interval(-0.1, 0.1))
    assert CtcIvp(Function(["x", "u"], "-x + u"), nb_inputs=1).contract(x, u)
    for k in range(td.nb_slices() + 1):
        t = Interval(td.t(k))
        e = sillage.exp(-t)
        lo, hi = e - Interval(0.1) * (Interval(1) - e), e + Interval(0.1) * (Interval(1) - e)
        assert x.gate(k).intersects(lo) and x.gate(k).intersects(hi)
        assert x.gate(k).diam() < 1.5 * (hi - lo).ub() + 1e-9


def test_dead_reckoning_inside_the_linearised_resolution():
    # Thesis 3.4 with f(x1, x2, x3, x4, tau, n1, n2), the noise n in [-1/1000, 1/1000]^2 as
    # inputs: the final box lies inside the example's linearised resolution
    # [33.09, 43.56] x [48.36, 57.77] and holds extreme paths (constant noise at a corner,
    # RK4 with a fine step: its error is far below the 1e-6 margin).
    td = TDomain(0.0, 64.0, 0.5)
    f = Function(["x1", "x2", "x3", "x4", "tau", "n1", "n2"],
                 "(x4*cos(x3), x4*sin(x3), -9/20*cos(tau/5) + n1, 1/10 + sin(tau/4) + n2, 1)")
    x = TubeVector(td, 5)
    c = Interval(-1, 1) / Interval(100)
    x.set_gate(0, IntervalVector([Interval(-1, 1), Interval(-1, 1), Interval.half_pi() + c, c, Interval(0)]))
    u = TubeVector(td, 2, Interval(-1, 1) / Interval(1000))
    assert CtcIvp(f, nb_inputs=2, order=10, time_propag=sillage.TimePropag.FORWARD).contract(x, u)
    end = x.gate(td.nb_slices())
    assert end[0].is_subset(Interval(33.09, 43.56)), end
    assert end[1].is_subset(Interval(48.36, 57.77)), end

    def rhs(s, n1, n2):
        return [s[3] * math.cos(s[2]), s[3] * math.sin(s[2]), -9 / 20 * math.cos(s[4] / 5) + n1,
                0.1 + math.sin(s[4] / 4) + n2, 1.0]

    for s0, n1, n2 in [([1, -1, math.pi / 2 + 0.01, 0.01, 0], 1e-3, 1e-3),
                       ([-1, 1, math.pi / 2 - 0.01, -0.01, 0], -1e-3, -1e-3),
                       ([1, 1, math.pi / 2 - 0.01, 0.01, 0], -1e-3, 1e-3)]:
        s, h = list(map(float, s0)), 1 / 64
        for _ in range(64 * 64):
            k1 = rhs(s, n1, n2)
            k2 = rhs([a + h / 2 * b for a, b in zip(s, k1)], n1, n2)
            k3 = rhs([a + h / 2 * b for a, b in zip(s, k2)], n1, n2)
            k4 = rhs([a + h * b for a, b in zip(s, k3)], n1, n2)
            s = [a + h / 6 * (b + 2 * c2 + 2 * d + e) for a, b, c2, d, e in zip(s, k1, k2, k3, k4)]
        for i in range(4):
            assert end[i].inflate(1e-6).contains(s[i]), (i, s[i], end[i])


def test_in_a_network():
    td = TDomain(0.0, 4.0, 0.5)
    x = TubeVector(td, 2)
    x.set_gate(0, IntervalVector([Interval(0), Interval(1)]))
    cn = sillage.ContractorNetwork()
    cn.add(CtcIvp(Function(["x1", "x2"], "(x2, -x1)")), [x])
    cn.contract()
    assert x.gate(td.nb_slices())[0].intersects(sillage.sin(Interval(4.0)))
    assert x.gate(td.nb_slices()).max_diam() < 1e-12


def test_errors():
    with pytest.raises(sillage.DimensionError):
        CtcIvp(Function(["x", "u"], "u"))
    with pytest.raises(sillage.Error, match="order"):
        CtcIvp(Function(["x"], "-x"), order=0)
    td = TDomain(0.0, 1.0, 0.5)
    with pytest.raises(sillage.DimensionError):
        CtcIvp(Function(["x"], "-x")).contract(TubeVector(td, 2))
    assert "CtcIvp" in repr(CtcIvp(Function(["x"], "-x")))


def test_abs_where_it_is_smooth():
    # x' = -abs(x) from x0 = 1 stays positive: x = e^{-t}; abs has a Taylor
    # rule where its operand keeps its sign.
    td = TDomain(0.0, 2.0, 0.5)
    x = Tube(td)
    x.set_gate(0, Interval(1))
    assert CtcIvp(Function(["x"], "-abs(x)")).contract(x)
    assert x.gate(td.nb_slices()).contains(math.exp(-2.0))
    assert x.gate(td.nb_slices()).diam() < 1e-12


def test_laws():
    def generate(rng):
        a, p = rng.uniform(0.3, 2.0), rng.uniform(-3.0, 3.0)

        def s(t):
            return Interval(a) * sillage.sin(t + Interval(p))

        def c(t):
            return Interval(a) * sillage.cos(t + Interval(p))

        td = kit.random_tdomain(rng, 8)
        return kit.Case([TubeVector([kit.tube_around(td, s, rng, 0.2, 0.6), kit.tube_around(td, c, rng, 0.2, 0.6)])],
                        [[s, c]])

    ctc = CtcIvp(Function(["x1", "x2"], "(x2, -x1)"), order=10)
    kit.check_laws(lambda d: ctc.contract(d[0]), generate, cases=6, idempotence="contraction")


def vdp_reference(x10, x20, h, steps):
    """Van der Pol (mu = 1) by its Taylor series of order 30 in 60-digit decimals (stdlib),
    fixed step h (exact in binary); the states after every step."""
    from decimal import Decimal, localcontext
    with localcontext() as ctx:
        ctx.prec = 60
        H, s, out = Decimal(h), (Decimal(x10), Decimal(x20)), []
        for _ in range(steps):
            a, b, sq = [s[0]], [s[1]], []
            for k in range(30):  # (k+1) a_{k+1} = b_k, (k+1) b_{k+1} = b_k - (a^2 b)_k - a_k
                sq.append(sum(a[j] * a[k - j] for j in range(k + 1)))
                sqb = sum(sq[j] * b[k - j] for j in range(k + 1))
                a.append(b[k] / (k + 1))
                b.append((b[k] - sqb - a[k]) / (k + 1))
            s = tuple(sum(c * H ** k for k, c in enumerate(cs)) for cs in (a, b))
            out.append(s)
        return out


def test_van_der_pol_encloses_a_high_precision_reference():
    """Twin of tests/cpp/dynamics/test_ctc_ivp_vdp.cpp: x(0) = (2, 0), t in [0, 3]; every gate
    contains the reference (compared exactly as decimals) and stays thin."""
    from decimal import Decimal
    td = TDomain(0.0, 3.0, 0.125)
    x = TubeVector(td, 2)
    x.set_gate(0, IntervalVector([Interval(2.0), Interval(0.0)]))
    assert CtcIvp(Function(["x1", "x2"], "(x2, (1 - x1^2)*x2 - x1)")).contract(x)
    ref = vdp_reference(2.0, 0.0, 0.125 / 8, 8 * td.nb_slices())
    for k in range(1, td.nb_slices() + 1):
        for i in range(2):
            g = x.gate(k)[i]
            assert Decimal(g.lb()) <= ref[8 * k - 1][i] <= Decimal(g.ub()), (k, i, g)
    assert x.gate(td.nb_slices()).max_diam() < 1e-10


def test_pieces_carry_a_wide_box_of_van_der_pol_to_the_end():
    """From the 0.2 box around (2, 0) one set blows up near t = 2.5; with set_max_pieces(64)
    the tube stays bounded to t = 5 and holds the decimal references of the corners and
    the centre at every eighth gate."""
    from decimal import Decimal
    f = Function(["x1", "x2"], "(x2, (1 - x1^2)*x2 - x1)")
    td = TDomain(0.0, 5.0, 0.125)
    x = TubeVector(td, 2)
    x.set_gate(0, IntervalVector([Interval(1.9, 2.1), Interval(-0.1, 0.1)]))
    ctc = CtcIvp(f)
    assert ctc.max_pieces() == 1
    ctc.set_max_pieces(64)
    assert ctc.max_pieces() == 64 and ctc.contract(x)
    n = td.nb_slices()
    assert x.gate(n).max_diam() < 1.0
    for a, b in ((1.9, -0.1), (1.9, 0.1), (2.1, -0.1), (2.1, 0.1), (2.0, 0.0)):
        ref = vdp_reference(a, b, 0.125 / 8, 8 * n)
        for k in range(8, n + 1, 8):
            for i in range(2):
                g = x.gate(k)[i]
                assert Decimal(g.lb()) <= ref[8 * k - 1][i] <= Decimal(g.ub()), (a, b, k, i, g)
    with pytest.raises(sillage.Error):
        ctc.set_max_pieces(0)

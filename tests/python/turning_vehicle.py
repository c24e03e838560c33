"""The true trajectory of the heading tests: a vehicle at speed s turning at rate b from heading a,
travelling at a constant e off its heading: psi(t) = a + b t, phi = psi + e,
p(t) = p0 + (s / b) (sin(phi(t)) - sin(phi(0)), cos(phi(0)) - cos(phi(t)))."""
from types import SimpleNamespace

import sillage
from sillage import Interval


def turning(rng, track):
    """Draws a, b, s, e (|e| <= track) and p0; returns s, b and the interval functions psi, px, py of t."""
    a, b, s, e = rng.uniform(-3, 3), rng.uniform(0.1, 0.9), rng.uniform(0.5, 2.5), rng.uniform(-track, track)
    x0, y0 = rng.uniform(-5, 5), rng.uniform(-5, 5)

    def psi(t):
        return Interval(a) + Interval(b) * t

    def phi(t):
        return psi(t) + Interval(e)

    def px(t):
        return Interval(x0) + Interval(s) / Interval(b) * (sillage.sin(phi(t)) - sillage.sin(phi(Interval(0))))

    def py(t):
        return Interval(y0) + Interval(s) / Interval(b) * (sillage.cos(phi(Interval(0))) - sillage.cos(phi(t)))

    return SimpleNamespace(s=s, b=b, psi=psi, px=px, py=py)

"""The contractor test kit: the generic laws every contractor obeys, checked on
random problems whose true solution is known. Pure Python, installed with the
package (``from sillage import testing as kit``), for the tests of sillage and
of contractors written outside it; its C++ twin is the header
``sillage/testing/contractor_kit.h`` (namespace ``sillage::kit``, same names).
docs/extending.md ("Testing your contractor") says how to use it.

A contractor's test gives the kit

- ``contract(domains)``: contracts a list of domains in place (each an
  Interval, IntervalVector, Tube or TubeVector), a few lines around the
  contractor's own ``contract`` call or around ``ContractorNetwork.add``;
- ``generate(rng)``: from a ``random.Random``, a :class:`Case`: the input
  domains and the truth, one true value per domain (an enclosure of a real, a
  box, a trajectory ``f(t: Interval) -> Interval``, a list of trajectories for
  a TubeVector, or None: nothing known);

and calls ``check_laws(contract, generate, ...)``, which raises AssertionError
naming the law, the case and seed, the domain, the slice / gate and the values
when one of these fails on ``cases`` random cases:

(a) contraction (``check_contracted``): every output inside its input,
    component by component, slice by slice and gate by gate, no NaN bound;
(b) truth kept (``check_truth``): the true value meets every output (at every
    gate and at ``samples`` + 2 times of every slice);
(c) idempotence (``check_idempotent``): a second call changes nothing bit for
    bit ("exact"), or only contracts and keeps the truth ("contraction"), or
    is not checked (None);
(e) threads (``check_threads``): two Python threads contracting independent
    copies of the same case get the serial result bit for bit (the C++ kit
    also runs oneTBB with 1 and 2 threads: no thread-count control in Python);
(f) empty and unbounded inputs (``check_special_inputs``): each domain in turn
    set empty (then every domain of ``outputs``, default all, comes out empty
    -- or one of them, ``empty_any``, for a network that stops at the first
    empty domain) or set to all reals (no exception, no NaN, contraction and
    the truth kept).

(d) order independence is checked by ``check_order_independent`` on a
contract that takes an insertion order, and (g) monotonicity by
``check_monotone`` (not a law of every contractor).
"""
import math
import random
import struct
import threading

from sillage import Interval, IntervalVector, TDomain, Tube, TubeVector


class Case:
    """Input domains and the truth (one entry per domain)."""

    def __init__(self, domains, truth):
        """domains: the input domains; truth: one true value per domain (None: unknown)."""
        assert len(domains) == len(truth), "one truth per domain (None: unknown)"
        self.domains = domains
        self.truth = truth


# ------------------------------------------------------------------ helpers

def copy_domains(domains):
    """Copies of the domains (a Tube copy shares the TDomain)."""
    return [d.copy() for d in domains]


def _bits(v):
    return struct.pack("<d", v)


def same_bits(a, b):
    """Bit-for-bit equality of two intervals (all empty intervals alike)."""
    if a.is_empty() and b.is_empty():
        return True
    return _bits(a.lb()) == _bits(b.lb()) and _bits(a.ub()) == _bits(b.ub())


def _has_nan(a):
    return math.isnan(a.lb()) or math.isnan(a.ub())


def atoms(dom):
    """(where, scalar Interval) for every component, gate and slice of dom."""
    if isinstance(dom, Interval):
        return [("", dom)]
    if isinstance(dom, IntervalVector):
        return [(f"component {i}", dom[i]) for i in range(len(dom))]
    if isinstance(dom, Tube):
        return _tube_atoms(dom, "")
    if isinstance(dom, TubeVector):
        out = []
        for i in range(len(dom)):
            out += _tube_atoms(dom[i], f"component {i}, ")
        return out
    raise TypeError(f"sillage.testing: unsupported domain {type(dom).__name__}")


def _tube_atoms(x, pre):
    td = x.tdomain()
    n = x.nb_slices()
    out = [(f"{pre}gate {k} (t = {td.t(k)!r})", x.gate(k)) for k in range(n + 1)]
    out += [(f"{pre}slice {k} {td.slice_domain(k)}", x.slice(k)) for k in range(n)]
    return out


def _paired(after, before, law, d):
    a, b = atoms(after), atoms(before)
    if len(a) != len(b):
        raise AssertionError(f"{law}: domain {d}: number of atoms changed from {len(b)} to {len(a)}")
    return zip(a, b)


def _at(where):
    return f" {where}" if where else ""


def check_contracted(after, before, law="contraction"):
    """(a) Every atom of `after` inside the same atom of `before`, no NaN bound."""
    for d, (x, y) in enumerate(zip(after, before)):
        for (where, a), (_, b) in _paired(x, y, law, d):
            if _has_nan(a):
                raise AssertionError(f"{law}: NaN bound in domain {d}{_at(where)}: {a}")
            if not a.is_subset(b):
                raise AssertionError(f"{law}: domain {d}{_at(where)} grew from {b!r} to {a!r}")


def check_identical(a, b, law, name_a="second", name_b="first"):
    """Bit-for-bit equality of two lists of domains; the message names them name_a and name_b."""
    for d, (x, y) in enumerate(zip(a, b)):
        for (where, p), (_, q) in _paired(x, y, law, d):
            if not same_bits(p, q):
                raise AssertionError(f"{law}: domain {d}{_at(where)}: {name_b} {q!r}, {name_a} {p!r}")


def _meets(t, y, d, where):
    if not t.intersects(y):
        raise AssertionError(f"truth kept: domain {d}{_at(where)}: true value {t!r} not in {y!r}")


def _tube_truth(x, f, samples, d, pre):
    td = x.tdomain()
    n = x.nb_slices()
    for k in range(n + 1):
        _meets(f(Interval(td.t(k))), x.gate(k), d, f"{pre}gate {k} (t = {td.t(k)!r})")
    for k in range(n):
        a, b = td.t(k), td.t(k + 1)
        for i in range(samples + 2):
            t = min(max(a + (b - a) * i / (samples + 1), a), b)
            _meets(f(Interval(t)), x.slice(k), d, f"{pre}slice {k} at t = {t!r}")


def check_truth(domains, truth, samples=3):
    """The truth (an enclosure) meets every domain: a disjoint enclosure
    proves the true value lost."""
    for d, (x, t) in enumerate(zip(domains, truth)):
        if t is None:
            continue
        if isinstance(x, Interval):
            _meets(t, x, d, "")
        elif isinstance(x, IntervalVector):
            for i in range(len(x)):
                _meets(t[i], x[i], d, f"component {i}")
        elif isinstance(x, Tube):
            _tube_truth(x, t, samples, d, "")
        else:
            for i in range(len(x)):
                _tube_truth(x[i], t[i], samples, d, f"component {i}, ")


def _run(contract, domains, law):
    try:
        contract(domains)
    except Exception as e:  # noqa: BLE001 -- any exception breaks the law
        raise AssertionError(f"{law}: exception {type(e).__name__}: {e}") from e


def _is_empty(dom):
    return dom.is_empty()


def filled(dom, y):
    """The same kind of domain, every atom set to y."""
    if isinstance(dom, Interval):
        return Interval(y)
    if isinstance(dom, IntervalVector):
        return IntervalVector(len(dom), y)
    if isinstance(dom, Tube):
        t = dom.copy()
        t.set(y)
        return t
    t = dom.copy()
    t.set(IntervalVector(len(t), y))
    return t


# ------------------------------------------------------------------ the laws

def check_idempotent(contract, once, truth, mode, samples=3):
    """(c) Idempotence from the contracted state `once`: mode "exact", "contraction" or None."""
    if mode is None:
        return
    twice = copy_domains(once)
    _run(contract, twice, "idempotence")
    if mode == "exact":
        check_identical(twice, once, "idempotence (a second call changed the result)", "after 2 calls",
                        "after 1 call")
    elif mode == "contraction":
        check_contracted(twice, once, "idempotence (contraction on a second call)")
        check_truth(twice, truth, samples)
    else:
        raise ValueError(f"idempotence: 'exact', 'contraction' or None, not {mode!r}")


def check_threads(contract, generate, seed):
    """(e) Two threads contracting copies of the case of `seed` get the serial result bit for bit."""
    serial = generate(random.Random(seed)).domains
    _run(contract, serial, "serial call")
    copies = [generate(random.Random(seed)).domains for _ in range(2)]
    errors = [None, None]

    def work(i):
        try:
            _run(contract, copies[i], "concurrent calls")
        except AssertionError as e:
            errors[i] = e

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for i, name in enumerate(("thread A", "thread B")):
        if errors[i]:
            raise errors[i]
        check_identical(copies[i], serial, "concurrent calls", name, "serial")


def check_special_inputs(contract, case, *, samples=3, empty_inputs=True, unbounded_inputs=True, outputs=None,
                         empty_any=False, skip_empty=(), skip_unbounded=()):
    """(f) Each domain of the case in turn empty, then all reals."""
    n = len(case.domains)
    for d in range(n):
        if empty_inputs and d not in skip_empty:
            law = f"empty input (domain {d} empty)"
            inp = copy_domains(case.domains)
            inp[d] = filled(inp[d], Interval.empty())
            out = copy_domains(inp)
            _run(contract, out, law)
            check_contracted(out, inp, law)
            if empty_any:
                if not any(_is_empty(x) for x in out):
                    raise AssertionError(f"{law}: no domain is empty after the call")
            else:
                for e in range(n) if outputs is None else outputs:
                    if not _is_empty(out[e]):
                        raise AssertionError(f"{law}: domain {e} is not empty after the call")
        if unbounded_inputs and d not in skip_unbounded:
            law = f"unbounded input (domain {d} all reals)"
            inp = copy_domains(case.domains)
            inp[d] = filled(inp[d], Interval())
            out = copy_domains(inp)
            try:
                _run(contract, out, law)
                check_contracted(out, inp, law)
                check_truth(out, case.truth, samples)
            except AssertionError as e:
                raise AssertionError(f"{law}: {e}") from e


def check_laws(contract, generate, *, cases=20, samples=3, seed=20170101, idempotence="exact", threads=True,
               empty_inputs=True, unbounded_inputs=True, outputs=None, empty_any=False, skip_empty=(),
               skip_unbounded=()):
    """All the laws on `cases` random cases (see the module's docstring)."""
    for i in range(cases):
        s = seed + i
        case = generate(random.Random(s))
        try:
            try:
                check_truth(case.domains, case.truth, samples)
            except AssertionError as e:
                raise AssertionError(f"generator: the truth is not in the input: {e}") from e
            out = copy_domains(case.domains)
            _run(contract, out, "contract")
            check_contracted(out, case.domains)
            check_truth(out, case.truth, samples)
            check_idempotent(contract, out, case.truth, idempotence, samples)
            if threads:
                check_threads(contract, generate, s)
            check_special_inputs(contract, case, samples=samples, empty_inputs=empty_inputs,
                                 unbounded_inputs=unbounded_inputs, outputs=outputs, empty_any=empty_any,
                                 skip_empty=skip_empty, skip_unbounded=skip_unbounded)
        except AssertionError as e:
            raise AssertionError(f"case {i} (seed {s}): {e}") from None


def check_order_independent(contract, generate, order1, order2, same_fixed_point, *, cases=20, samples=3,
                            seed=20170101):
    """contract(domains, order) applies (or adds to a network) its parts in
    that order. Both orders contract and keep the truth; with
    same_fixed_point the results are also equal bit for bit."""
    for i in range(cases):
        s = seed + i
        case = generate(random.Random(s))
        try:
            a, b = copy_domains(case.domains), copy_domains(case.domains)
            _run(lambda d: contract(d, order1), a, "order 1")
            _run(lambda d: contract(d, order2), b, "order 2")
            check_contracted(a, case.domains, "order 1, contraction")
            check_contracted(b, case.domains, "order 2, contraction")
            check_truth(a, case.truth, samples)
            check_truth(b, case.truth, samples)
            if same_fixed_point:
                check_identical(b, a, "order independence", "order 2", "order 1")
        except AssertionError as e:
            raise AssertionError(f"case {i} (seed {s}): {e}") from None


def _shrink_atom(y, rng):
    if y.is_empty() or y.is_unbounded():
        return y
    w = y.diam()
    a, b = y.lb() + rng.uniform(0, 0.3) * w, y.ub() - rng.uniform(0, 0.3) * w
    return Interval(a, b) & y if a <= b else y


def shrunk(dom, rng):
    """A random sub-domain: each bounded atom shrunk by up to 30% per side.
    Tubes: the slices and gates are shrunk on their own; a gate disjoint
    from a shrunk slice (Tube refuses it) is replaced by its intersection
    with the slices around it, empty if need be."""
    if isinstance(dom, Interval):
        return _shrink_atom(dom, rng)
    if isinstance(dom, IntervalVector):
        return IntervalVector([_shrink_atom(dom[i], rng) for i in range(len(dom))])
    if isinstance(dom, Tube):
        return _shrunk_tube(dom, rng)
    return TubeVector([_shrunk_tube(dom[i], rng) for i in range(len(dom))])


def _shrunk_tube(x, rng):
    n = x.nb_slices()
    s = [_shrink_atom(x.slice(k), rng) for k in range(n)]
    g = [_shrink_atom(x.gate(k), rng) for k in range(n + 1)]
    for k in range(n + 1):
        for j in (k - 1, k):
            if 0 <= j < n and not g[k].is_empty() and not s[j].is_empty() and not g[k].intersects(s[j]):
                g[k] = Interval.empty()
    return Tube(x.tdomain(), s, g)


def check_monotone(contract, generate, *, cases=20, seed=20170101):
    """(g) X ⊆ Y => C(X) ⊆ C(Y), Y the case's input, X a random sub-domain.
    Not a law of every contractor: what makes a network's fixed point
    independent of the order."""
    for i in range(cases):
        s = seed + i
        case = generate(random.Random(s))
        rng = random.Random(s ^ 0x5EED)
        big = copy_domains(case.domains)
        small = [shrunk(d, rng) for d in case.domains]
        try:
            _run(contract, big, "monotonicity (C(Y))")
            _run(contract, small, "monotonicity (C(X))")
            check_contracted(small, big, "monotonicity: X ⊆ Y but C(X) ⊄ C(Y)")
        except AssertionError as e:
            raise AssertionError(f"case {i} (seed {s}): {e}") from None


# ------------------------------------------------------------------ generators' helpers

def around(y, rng, w=0.5, p_inf=0.0):
    """A random interval around the enclosure y, each side widened by up to w
    (plus one ulp outward), unbounded with probability p_inf."""
    lo = -math.inf if rng.random() < p_inf else math.nextafter(y.lb() - w * rng.random(), -math.inf)
    hi = math.inf if rng.random() < p_inf else math.nextafter(y.ub() + w * rng.random(), math.inf)
    return Interval(lo, hi)


def tube_around(td, f, rng, w, p_unknown=0.0):
    """A tube around the trajectory f: slices around f over each slice, gates
    around f(t_k), widened by up to w, all reals with probability p_unknown."""
    n = td.nb_slices()
    s = [Interval() if rng.random() < p_unknown else around(f(td.slice_domain(k)), rng, w) for k in range(n)]
    g = [Interval() if rng.random() < p_unknown else around(f(Interval(td.t(k))), rng, w) for k in range(n + 1)]
    return Tube(td, s, g)


def random_tdomain(rng, n, t0=0.0):
    """Random increasing time points from t0: n slices of widths in [0.05, 0.5]."""
    ts = [t0]
    for _ in range(n):
        ts.append(ts[-1] + rng.uniform(0.05, 0.5))
    return TDomain(ts)


class SineSum:
    """x(t) = sum a_i sin(w_i t + p_i) and its exact derivative, in interval
    arithmetic: x(t), v(t) enclose the true values (ranges for an interval t)."""

    def __init__(self, rng, terms=3):
        """`terms` sines of random amplitudes, pulsations and phases drawn from rng."""
        self.a = [rng.uniform(-1.5, 1.5) for _ in range(terms)]
        self.w = [rng.uniform(0.3, 3.0) for _ in range(terms)]
        self.p = [rng.uniform(-3.0, 3.0) for _ in range(terms)]

    def x(self, t):
        """An enclosure of x over the Interval t."""
        from sillage import sin
        r = Interval(0)
        for a, w, p in zip(self.a, self.w, self.p):
            r = r + Interval(a) * sin(Interval(w) * t + Interval(p))
        return r

    def v(self, t):
        """An enclosure of x' over the Interval t."""
        from sillage import cos
        r = Interval(0)
        for a, w, p in zip(self.a, self.w, self.p):
            r = r + Interval(a) * Interval(w) * cos(Interval(w) * t + Interval(p))
        return r


def position(f):
    """The trajectory t -> x(t) of a SineSum, for a Case's truth (f.x itself)."""
    return f.x


def velocity(f):
    """The trajectory t -> x'(t) of a SineSum, for a Case's truth (f.v itself)."""
    return f.v

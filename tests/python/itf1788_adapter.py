"""Adapter of sillage for the ITF1788 checker (shared/itf1788/check_itf1788.py).

Maps every IEEE 1788 operation that sillage implements; the reverse-mode
operations come from the backward projections (fRevBin(c, x) = bwd_f(c, x),
fRev(c) = bwd_f(c, entire)), mulRevToPair from the two-piece division div2.
"""
import sillage as s
from sillage import Interval

ENTIRE = Interval.all_reals


def make(lo, hi):
    return Interval(lo, hi)


def empty():
    return Interval.empty()


def bounds(x):
    return None if x.is_empty() else (x.lb(), x.ub())


def _rev(bwd):
    """fRev(c) and fRevBin(c, x) from bwd_f(y, x) -> (x,)."""
    return (lambda c: bwd(c, ENTIRE())[0]), (lambda c, x: bwd(c, x)[0])


_REV = {}
for _name, _bwd in (('sqr', s.bwd_sqr), ('abs', s.bwd_abs), ('sin', s.bwd_sin), ('cos', s.bwd_cos),
                    ('tan', s.bwd_tan), ('cosh', s.bwd_cosh)):
    _REV[_name + 'Rev'], _REV[_name + 'RevBin'] = _rev(_bwd)

OPS = {
    # arithmetic
    'pos': lambda x: +x,
    'neg': lambda x: -x,
    'add': lambda x, y: x + y,
    'sub': lambda x, y: x - y,
    'mul': lambda x, y: x * y,
    'div': lambda x, y: x / y,
    'recip': lambda x: Interval(1) / x,
    'sqr': s.sqr,
    'sqrt': s.sqrt,
    'pown': lambda x, n: s.pow(x, n),
    'pow': lambda x, y: s.pow(x, y),
    'rootn': lambda x, n: s.root(x, n),
    'cbrt': lambda x: s.root(x, 3),
    # elementary functions
    'exp': s.exp,
    'log': s.log,
    'sin': s.sin,
    'cos': s.cos,
    'tan': s.tan,
    'asin': s.asin,
    'acos': s.acos,
    'atan': s.atan,
    'atan2': s.atan2,
    'sinh': s.sinh,
    'cosh': s.cosh,
    'tanh': s.tanh,
    'abs': s.abs,
    'min': s.min,
    'max': s.max,
    'sign': s.sign,
    # set operations
    'intersection': lambda x, y: x & y,
    'convexHull': lambda x, y: x | y,
    # numeric functions
    'inf': lambda x: x.lb(),
    'sup': lambda x: x.ub(),
    'mid': lambda x: x.mid(),
    'wid': lambda x: x.diam(),
    'rad': lambda x: x.rad(),
    'midRad': lambda x: (x.mid(), x.rad()),
    'mag': lambda x: x.mag(),
    'mig': lambda x: x.mig(),
    # predicates
    'isEmpty': lambda x: x.is_empty(),
    'isEntire': lambda x: x.is_all_reals(),
    'isSingleton': lambda x: x.is_degenerate(),
    'isCommonInterval': lambda x: not x.is_empty() and x.is_bounded(),
    'isMember': lambda v, x: x.contains(v),
    'subset': lambda x, y: x.is_subset(y),
    'interior': lambda x, y: x.is_interior_subset(y),
    'disjoint': lambda x, y: x.is_disjoint(y),
    'equal': lambda x, y: x == y,
    # reverse-mode operations (backward projections)
    'mulRev': lambda b, c: s.bwd_mul(c, ENTIRE(), b)[0],
    'mulRevTen': lambda b, c, x: s.bwd_mul(c, x, b)[0],
    'mulRevToPair': lambda b, c: s.div2(c, b),
    'pownRev': lambda c, n: s.bwd_pow(c, ENTIRE(), n)[0],
    'pownRevBin': lambda c, x, n: s.bwd_pow(c, x, n)[0],
    'powRev1': lambda b, c, x: s.bwd_pow(c, x, b)[0],
    'powRev2': lambda a, c, y: s.bwd_pow(c, a, y)[1],
    **_REV,
}

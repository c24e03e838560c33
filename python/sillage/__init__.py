"""sillage: guaranteed state estimation by constraint programming over intervals and tubes.

Everything lives in the compiled module ``sillage._sillage`` and is re-exported
here with the C++ names: ``Interval``, ``IntervalVector``, ``IntervalMatrix``,
the elementary functions (``sqr``, ``exp``, ``atan2``, ...) and the backward
projections ``bwd_*``.

Notes on the Python API:

* Intervals, boxes and matrices are mutable objects: in-place operators
  (``x &= y``, ``x += 1``) modify the object itself, which is what a
  ``ContractorNetwork`` holding it sees. ``v[i]`` returns a copy.
* Floats are accepted wherever an ``Interval`` is expected, and lists of
  intervals / numbers / ``[lb, ub]`` pairs or ``(n, 2)`` arrays wherever an
  ``IntervalVector`` is. ``to_numpy()`` / ``numpy.asarray`` give the bounds back.
* ``bwd_f(y, x1, ...)`` returns the contracted arguments as a tuple, e.g.
  ``x1, x2 = bwd_add(y, x1, x2)`` and ``(x,) = bwd_sqr(y, x)``.
* Invalid input raises ``sillage.Error`` (a ``ValueError``).
* Tubes and numpy: ``Tube(td, a)`` from an ``(N, 2)`` array of slice bounds,
  ``TubeVector(td, a)`` from a ``(dim, N, 2)`` one; ``slices_array()`` /
  ``gates_array()`` / ``lb()`` / ``ub()`` / ``diam()`` give arrays back.
  Interval, IntervalVector, TDomain, Tube, TubeVector and sampled Trajectory
  objects pickle bit for bit (tubes pickled together share one TDomain).
* ``sillage.abs``, ``sillage.min``, ``sillage.max`` and ``sillage.pow`` work on
  intervals; ``from sillage import *`` leaves Python's own ``abs``/``min``/
  ``max``/``pow`` alone (``abs(x)`` and ``x ** n`` work on intervals anyway).
"""
from . import _sillage
from ._sillage import *  # noqa: F401,F403
from ._sillage import Error  # noqa: F401
from .rigor import outward  # noqa: F401

#: The version of the C++ project (project(sillage VERSION ...) in CMakeLists.txt).
__version__ = _sillage.__version__


_BUILTIN_NAMES = {"abs", "min", "max", "pow"}
__all__ = [n for n in dir(_sillage) if not n.startswith("_") and n not in _BUILTIN_NAMES] + ["outward"]

"""Outward rounding for contractors that compute bounds with numpy (docs/extending.md, "Keeping a
numpy contractor rigorous"). numpy's +, -, *, / and sqrt round each result to the nearest float:
the true bound may lie one ulp beyond it, so a lower bound is moved one float down and an upper
bound one float up per such operation (``ulps``). numpy's sin, exp, ... are not correctly rounded
(several ulps): evaluate them with ``Function.eval_batch``, which rounds outward itself."""


def outward(lb, ub, ulps=1):
    """(lb, ub) moved ``ulps`` floats outward (lb down, ub up), as numpy arrays; -inf and inf stay."""
    import numpy as np  # numpy is needed only by the numpy features

    if not isinstance(ulps, int) or ulps < 0:
        raise ValueError(f"outward: ulps must be an integer >= 0, got {ulps!r}")
    lo, hi = np.array(lb, dtype=float), np.array(ub, dtype=float)
    for _ in range(ulps):
        lo, hi = np.nextafter(lo, -np.inf), np.nextafter(hi, np.inf)
    return lo, hi

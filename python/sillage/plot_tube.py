"""Matplotlib helpers for tubes (thesis Figs. 3.4-3.12).

* ``plot_tube(ax, tube)``: slices as rectangles over time, optional gates and
  true trajectory;
* ``plot_tube_vector_2d(ax, tubevector, i, j)``: the projection
  [x_i](.) x [x_j](.), one box per slice, gates 0 and N highlighted;
* ``plot_thickness(ax, tube_or_tubevector)``: the thickness d(t) (Fig. 3.12).

Beyond ``max_shapes`` slices, consecutive slices are merged into their hull
(the drawing still covers every slice). Unbounded bounds are clipped to a
finite window (the limits of the axes are set to it when ``autoscale``).
"""
import numpy as np
from matplotlib.collections import PolyCollection

from ._sillage import ThicknessMeasure, Tube, thickness_values

__all__ = ["TUBE_COLOURS", "plot_tube", "plot_tube_vector_2d", "plot_thickness"]

#: The colours of the SVG tube figures (TubeStyle defaults).
TUBE_COLOURS = {"slice": ("#a9cdf2", "#2a6aa8"), "gate": "#1f3f66", "truth": "#d62728",
                "initial": ("#e1bee7", "#7b1fa2"), "final": ("#a5d6a7", "#2e7d32")}


def _arrays(tube):
    """(times (N+1,), slices (N, 2), gates (N+1, 2)) of a scalar tube."""
    times = np.asarray(tube.tdomain().times(), dtype=float)
    if hasattr(tube, "slices_array"):
        return times, np.asarray(tube.slices_array(), dtype=float), np.asarray(tube.gates_array(), dtype=float)
    n = tube.nb_slices()  # fallback: one call per slice

    def bounds(x):
        return (x.lb(), x.ub()) if not x.is_empty() else (np.inf, -np.inf)
    return (times, np.array([bounds(tube.slice(k)) for k in range(n)], dtype=float),
            np.array([bounds(tube.gate(k)) for k in range(n + 1)], dtype=float))


def _finite_window(*bounds):
    """(lo, hi, clipped): the finite bounds with a margin (5 %, 25 % if some bound is infinite)."""
    pairs = np.concatenate([np.asarray(x, dtype=float).reshape(-1, 2) for x in bounds])
    b = pairs[pairs[:, 0] <= pairs[:, 1]].ravel()  # empty intervals are (inf, -inf)
    clipped = bool(np.any(np.isinf(b)))
    b = b[np.isfinite(b)]
    if b.size == 0:
        return -1.0, 1.0, clipped
    lo, hi = float(b.min()), float(b.max())
    if lo == hi:
        m = max(1.0, abs(lo) * 0.1)
        return lo - m, hi + m, clipped
    m = (0.25 if clipped else 0.05) * (hi - lo)
    return lo - m, hi + m, clipped


def _merge(starts, ends, lo, hi, max_shapes, breaks=None):
    """Hulls of consecutive groups of slices when there are more than max_shapes.

    `breaks`: indices where a group must start (after an empty slice, which must stay visible).
    """
    n = len(starts)
    if n <= max_shapes:
        return starts, ends, lo, hi
    idx = np.linspace(0, n, max_shapes + 1).astype(int)[:-1]
    if breaks is not None:
        idx = np.concatenate([idx, breaks])
    idx = np.unique(idx)
    nxt = np.append(idx[1:], n)
    return starts[idx], ends[nxt - 1], np.minimum.reduceat(lo, idx), np.maximum.reduceat(hi, idx)


def _rect_verts(x0, x1, y0, y1):
    return np.stack([np.stack([x0, y0], 1), np.stack([x1, y0], 1), np.stack([x1, y1], 1),
                     np.stack([x0, y1], 1)], axis=1)


def _edge(n, face, edge):
    """Outlines of hundreds of thin shapes would darken the tube: then use the face colour."""
    return face if n > 200 else edge


def _sample(traj, t0, tf, n=1000):
    dom = traj.domain()
    a, b = max(dom.lb(), t0), min(dom.ub(), tf)
    if not a < b:
        return np.empty(0), np.empty(0)
    ts = np.linspace(a, b, n)
    vs = np.array([traj(float(t)).mid() if not traj(float(t)).is_empty() else np.nan for t in ts], dtype=float)
    vs[~np.isfinite(vs)] = np.nan
    return ts, vs


def plot_tube(ax, tube, color=None, edgecolor=None, traj=None, gates=False, linewidth=0.4, max_shapes=2000,
              autoscale=True, **kwargs):
    """Draws a scalar Tube over time; returns the PolyCollection of the slices.

    `traj`: a Trajectory drawn as a red line; `gates`: draw the gates as vertical segments.
    With `autoscale`, the limits are set and the time axis is labelled "t (s)".
    """
    face, edge = TUBE_COLOURS["slice"]
    times, sl, gt = _arrays(tube)
    lo_w, hi_w, _ = _finite_window(sl, gt)
    keep = sl[:, 0] <= sl[:, 1]  # empty slices are not drawn
    t0s, t1s = times[:-1][keep], times[1:][keep]
    lo, hi = np.clip(sl[keep, 0], lo_w, hi_w), np.clip(sl[keep, 1], lo_w, hi_w)
    kept = np.flatnonzero(keep)
    breaks = np.flatnonzero(np.diff(kept) > 1) + 1  # no group across an empty slice
    t0s, t1s, lo, hi = _merge(t0s, t1s, lo, hi, max_shapes, breaks)
    coll = PolyCollection(_rect_verts(t0s, t1s, lo, hi), facecolors=color or face,
                          edgecolors=edgecolor or _edge(len(t0s), color or face, edge), linewidths=linewidth, **kwargs)
    ax.add_collection(coll)
    if gates:
        g = gt[:, 0] <= gt[:, 1]
        ax.vlines(times[g], np.clip(gt[g, 0], lo_w, hi_w), np.clip(gt[g, 1], lo_w, hi_w),
                  colors=TUBE_COLOURS["gate"], linewidth=1.0)
    if traj is not None:
        ts, vs = _sample(traj, times[0], times[-1])
        ax.plot(ts, vs, color=TUBE_COLOURS["truth"], linewidth=1.5)
    if autoscale:
        ax.set_xlim(times[0], times[-1])
        ax.set_ylim(lo_w, hi_w)
        ax.set_xlabel("t (s)")
    return coll


def plot_tube_vector_2d(ax, tubevector, i=0, j=1, color=None, edgecolor=None, truth=None, linewidth=0.4,
                        max_shapes=5000, autoscale=True, **kwargs):
    """Draws the projection [x_i] x [x_j] of a TubeVector; returns the PolyCollection of the slices.

    `truth`: a pair of Trajectories (x_i(t), x_j(t)) drawn as a red path.
    """
    n = len(tubevector)
    if not (0 <= i < n and 0 <= j < n and i != j):
        raise ValueError(f"plot_tube_vector_2d: components ({i}, {j}) of a tube vector of size {n}")
    face, edge = TUBE_COLOURS["slice"]
    times, xi, gi = _arrays(tubevector[i])
    _, xj, gj = _arrays(tubevector[j])
    wx, wy = _finite_window(xi, gi), _finite_window(xj, gj)
    keep = (xi[:, 0] <= xi[:, 1]) & (xj[:, 0] <= xj[:, 1])
    ax_, bx = np.clip(xi[keep, 0], wx[0], wx[1]), np.clip(xi[keep, 1], wx[0], wx[1])
    ay, by = np.clip(xj[keep, 0], wy[0], wy[1]), np.clip(xj[keep, 1], wy[0], wy[1])
    if len(ax_) > max_shapes:  # hulls of consecutive groups of slices, never across an empty one
        breaks = np.flatnonzero(np.diff(np.flatnonzero(keep)) > 1) + 1
        idx = np.unique(np.concatenate([np.linspace(0, len(ax_), max_shapes + 1).astype(int)[:-1], breaks]))
        ax_, bx = np.minimum.reduceat(ax_, idx), np.maximum.reduceat(bx, idx)
        ay, by = np.minimum.reduceat(ay, idx), np.maximum.reduceat(by, idx)
    coll = PolyCollection(_rect_verts(ax_, bx, ay, by), facecolors=color or face,
                          edgecolors=edgecolor or _edge(len(ax_), color or face, edge), linewidths=linewidth, **kwargs)
    ax.add_collection(coll)
    if truth is not None:
        ts, a = _sample(truth[0], times[0], times[-1])
        _, b = _sample(truth[1], times[0], times[-1])
        if len(a) == len(b):
            ax.plot(a, b, color=TUBE_COLOURS["truth"], linewidth=1.5)
    for k, key in ((0, "initial"), (-1, "final")):
        gx, gy = np.clip(gi[k], wx[0], wx[1]), np.clip(gj[k], wy[0], wy[1])
        if gx[0] <= gx[1] and gy[0] <= gy[1]:
            f, e = TUBE_COLOURS[key]
            ax.add_collection(PolyCollection(_rect_verts(gx[:1], gx[1:], gy[:1], gy[1:]), facecolors=f,
                                             edgecolors=e, linewidths=1.0, alpha=0.8))
            if gx[0] == gx[1] and gy[0] == gy[1]:  # a point: make it visible
                ax.plot([gx[0]], [gy[0]], "o", color=e, markersize=4)
    if autoscale:
        ax.set_xlim(wx[0], wx[1])
        ax.set_ylim(wy[0], wy[1])
    return coll


def plot_thickness(ax, tube, measure=None, color="#2a6aa8", **kwargs):
    """Draws the thickness d(t) of a Tube or TubeVector as a step curve; returns the line.

    For a TubeVector, d is the max diameter over the components (measure=ThicknessMeasure.Diagonal
    gives the diagonal of thesis Fig. 3.12). Infinite values are not drawn.
    """
    if isinstance(tube, Tube):
        d = np.asarray(thickness_values(tube), dtype=float)
    else:
        d = np.asarray(thickness_values(tube, measure if measure is not None else ThicknessMeasure.MaxDiameter),
                       dtype=float)
    times = np.asarray(tube.tdomain().times(), dtype=float)
    d[~np.isfinite(d)] = np.nan
    (line,) = ax.step(times, np.append(d, d[-1]), where="post", color=color, **kwargs)
    ax.set_xlim(times[0], times[-1])
    ax.set_xlabel("t (s)")
    ax.set_ylabel("d(t)")
    return line

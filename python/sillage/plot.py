"""Matplotlib helpers for sillage: boxes, pavings (thesis colours), rings, contours.

The colours follow the thesis (Fig. 2.11): green for inner boxes, yellow for
boundary boxes, blue for boxes proven outside. Every helper draws on a given
matplotlib Axes and returns what it added.
"""
import numpy as np
from matplotlib.collections import PolyCollection
from matplotlib.patches import Circle, PathPatch, Rectangle
from matplotlib.path import Path

from ._sillage import PavingTag

#: (face, edge) colours of each leaf tag, the same as the SVG figures.
PAVING_COLOURS = {
    PavingTag.Inner: ("#9bd49b", "#2f7d32"),
    PavingTag.Boundary: ("#ffe680", "#b89500"),
    PavingTag.Outside: ("#a9cdf2", "#2a6aa8"),
}


def _bounds(box, dims):
    """[(lb, ub), (lb, ub)] of a box (IntervalVector or sequence of Interval / pairs)."""
    out = []
    for d in dims:
        c = box[d]
        if hasattr(c, "lb"):
            out.append((c.lb(), c.ub()))
        else:
            out.append((float(c[0]), float(c[1])))
    return out


def _clip(lo, hi, limits):
    """Clips infinite bounds to the current axis limits so they can be drawn."""
    return max(lo, min(limits)) if np.isinf(lo) else lo, min(hi, max(limits)) if np.isinf(hi) else hi


def plot_box(ax, box, facecolor="none", edgecolor="black", dims=(0, 1), **kwargs):
    """Draws a 2-D box (or the projection of a box on `dims`) as a rectangle."""
    (a, b), (c, d) = _bounds(box, dims)
    if a > b or c > d:  # empty box
        return None
    a, b = _clip(a, b, ax.get_xlim())
    c, d = _clip(c, d, ax.get_ylim())
    rect = Rectangle((a, c), b - a, d - c, facecolor=facecolor, edgecolor=edgecolor, **kwargs)
    ax.add_patch(rect)
    return rect


def plot_boxes(ax, boxes, facecolor="none", edgecolor="black", dims=(0, 1), linewidth=0.5, **kwargs):
    """Draws many boxes at once; `boxes` is a list of boxes or an array (k, n, 2)."""
    arr = np.asarray(boxes if isinstance(boxes, np.ndarray) else [_bounds(b, range(max(dims) + 1)) for b in boxes],
                     dtype=float)
    if arr.size == 0:
        return None
    x, y = arr[:, dims[0], :], arr[:, dims[1], :]
    verts = np.stack([
        np.stack([x[:, 0], y[:, 0]], axis=1), np.stack([x[:, 1], y[:, 0]], axis=1),
        np.stack([x[:, 1], y[:, 1]], axis=1), np.stack([x[:, 0], y[:, 1]], axis=1)], axis=1)
    coll = PolyCollection(verts, facecolors=facecolor, edgecolors=edgecolor, linewidths=linewidth, **kwargs)
    ax.add_collection(coll)
    return coll


def plot_paving(ax, paving, show_outside=True, dims=(0, 1), linewidth=0.3, autoscale=True):
    """Draws the leaves of a Paving with the thesis colours; returns {tag: collection}."""
    out = {}
    tags = [PavingTag.Outside, PavingTag.Boundary, PavingTag.Inner] if show_outside else [
        PavingTag.Boundary, PavingTag.Inner]
    for tag in tags:
        face, edge = PAVING_COLOURS[tag]
        out[tag] = plot_boxes(ax, paving.boxes_array(tag), facecolor=face, edgecolor=edge, dims=dims,
                              linewidth=linewidth)
    if autoscale and not paving.is_empty():
        (a, b), (c, d) = _bounds(paving.domain(), dims)
        ax.set_xlim(a, b)
        ax.set_ylim(c, d)
    return out


def plot_ring(ax, center, radius, facecolor="#ffcc00", edgecolor="none", alpha=0.5, **kwargs):
    """Draws the annulus {p : |p - center| in radius} (radius: Interval or (lb, ub)), as in Fig. 2.9."""
    lo, hi = (radius.lb(), radius.ub()) if hasattr(radius, "lb") else (float(radius[0]), float(radius[1]))
    if lo > hi or hi < 0:
        return None
    lo = max(lo, 0.0)
    t = np.linspace(0, 2 * np.pi, 181)
    outer = np.column_stack([center[0] + hi * np.cos(t), center[1] + hi * np.sin(t)])
    if lo > 0:
        inner = np.column_stack([center[0] + lo * np.cos(t[::-1]), center[1] + lo * np.sin(t[::-1])])
        verts = np.concatenate([outer, inner])
        codes = [Path.MOVETO] + [Path.LINETO] * (len(t) - 1) + [Path.MOVETO] + [Path.LINETO] * (len(t) - 1)
        patch = PathPatch(Path(verts, codes), facecolor=facecolor, edgecolor=edgecolor, alpha=alpha, **kwargs)
    else:
        patch = Circle(center, hi, facecolor=facecolor, edgecolor=edgecolor, alpha=alpha, **kwargs)
    ax.add_patch(patch)
    return patch


def plot_contour(ax, loops, color="black", linewidth=1.5, arrows=False, **kwargs):
    """Draws oriented contour loops (Component.contour()); arrows show the orientation."""
    lines = []
    for loop in loops:
        pts = np.array(loop.vertices() + [loop.vertices()[0]], dtype=float)
        lines += ax.plot(pts[:, 0], pts[:, 1], color=color, linewidth=linewidth, **kwargs)
        if arrows:
            for e in loop.edges:
                (a, b), (c, d) = e.a, e.b
                ax.annotate("", xy=((a + c) / 2 + (c - a) * 0.05, (b + d) / 2 + (d - b) * 0.05),
                            xytext=((a + c) / 2, (b + d) / 2), arrowprops=dict(arrowstyle="->", color=color))
    return lines


# Tube helpers (plot_tube, plot_tube_vector_2d, plot_thickness), also here for convenience.
from .plot_tube import *  # noqa: E402,F401,F403

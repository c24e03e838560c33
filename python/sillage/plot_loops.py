"""Matplotlib helpers for the loops of a trajectory (thesis ch. 6, Figs. 6.12-6.17).

* ``plot_tplane(ax, tplane, truth=None)``: the t-plane paving (thesis colours),
  each detection filled and outlined by its status, the diagonal t1 = t2 and
  the true crossings (t1*, t2*) as points, with a legend; axes in seconds;
* ``plot_loops_map(ax, tplane, positions=None)``: the trajectory (a position
  TubeVector or an (n, 2) path) and the map box of each detection; axes in metres.

Statuses, as the SVG figures (``loop_style``): a complete detection proven by
the degree test is orange (so are the proven pieces of a split detection, drawn
over it), a complete one without proof black, a partial one
(touching the sides or the diagonal of the t-plane, never proven) grey. Boxes
are drawn by collections, one per status, so that large pavings stay fast.
"""
import numpy as np
from matplotlib.collections import LineCollection, PolyCollection
from matplotlib.patches import Patch, Rectangle

from ._sillage import PavingTag, contour
from .plot import PAVING_COLOURS
from .plot_tube import plot_tube_vector_2d

__all__ = ["LOOP_COLOURS", "TPLANE_LEGEND", "loop_status", "plot_tplane", "plot_loops_map"]

#: (face, edge) colours of each detection status (the same as the SVG figures).
LOOP_COLOURS = {"proven": ("#ff8c00", "#c25e00"), "unproven": ("#000000", "#000000"),
                "partial": ("#9e9e9e", "#616161")}
#: Drawn last to first: proofs stay on top.
_STATUS_ORDER = ("partial", "unproven", "proven")
_DIAGONAL = "#555555"
_TPLANE_CROSSING = "#1565c0"
_MAP_CROSSING = "#d62728"
_PATH = "#1f4e8c"


def loop_status(loop):
    """'proven', 'unproven' or 'partial' (a Loop of TPlane.detections())."""
    if not loop.complete():
        return "partial"
    return "proven" if loop.proven() else "unproven"


def _rect_verts(b):
    """Corners (k, 4, 2) of boxes given as an array (k, 2, 2) of [lb, ub] rows."""
    x, y = b[:, 0, :], b[:, 1, :]
    return np.stack([np.stack([x[:, 0], y[:, 0]], 1), np.stack([x[:, 1], y[:, 0]], 1),
                     np.stack([x[:, 1], y[:, 1]], 1), np.stack([x[:, 0], y[:, 1]], 1)], axis=1)


def _box_array(box):
    """(2, 2) bounds of a 2-D IntervalVector; None if empty."""
    if box.is_empty():
        return None
    return np.array([[box[0].lb(), box[0].ub()], [box[1].lb(), box[1].ub()]], dtype=float)


def _crossing_times(truth):
    """(k, 2) array of (t1, t2) from PathCrossings or pairs."""
    pts = [(c.t1, c.t2) if hasattr(c, "t1") else (float(c[0]), float(c[1])) for c in truth]
    return np.asarray(pts, dtype=float).reshape(-1, 2)


def _outline_segments(loops_boxes):
    """Segments (m, 2, 2) of the contours of several unions of boxes."""
    segs = []
    for boxes in loops_boxes:
        for loop in contour(boxes):
            segs.extend([e.a, e.b] for e in loop.edges)
    return np.asarray(segs, dtype=float).reshape(-1, 2, 2)


#: Legend text of each entry of plot_tplane's result.
TPLANE_LEGEND = {"domain": "outside (no loop)", "outside": "outside (no loop)", "boundary": "boundary",
                 "inner": "inner", "partial": "partial detection", "unproven": "detection (no proof)",
                 "proven": "proven loop", "diagonal": "t1 = t2", "truth": "true crossings"}


def plot_tplane(ax, tplane, truth=None, show_outside=False, show_diagonal=True, markers=0.01, alpha=0.45,
                linewidth=0.3, autoscale=True, legend=True):
    """Draws the t-plane of a TPlane (after compute_detections); returns a dict of the artists added.

    `truth`: true crossings, a list of PathCrossing (self_crossings) or of (t1, t2) pairs, drawn as
    blue points. `show_outside`: draw every Outside leaf; otherwise the domain is filled with the
    outside colour once (the same picture, far fewer shapes). `markers`: detections whose hull is
    smaller than this fraction of the domain also get a point at their centre so that they show
    (0 or None: no markers). `legend`: add a legend naming what is drawn (TPLANE_LEGEND), kept
    under the key 'legend'. Keys of the result: 'domain' or 'outside', 'inner', 'boundary',
    'proven', 'unproven', 'partial' (fills), 'outlines', 'markers', 'diagonal', 'truth', 'legend';
    an entry is absent when there is nothing to draw. Axes: t1 and t2 in seconds.
    """
    out = {}
    dom = _box_array(tplane.domain())
    paving = tplane.paving()
    face, edge = PAVING_COLOURS[PavingTag.Outside]
    if show_outside and paving.count(PavingTag.Outside) > 0:
        b = np.asarray(paving.boxes_array(PavingTag.Outside), dtype=float)
        out["outside"] = ax.add_collection(PolyCollection(_rect_verts(b), facecolors=face, edgecolors=edge,
                                                          linewidths=linewidth))
    elif not show_outside:
        out["domain"] = ax.add_patch(Rectangle((dom[0, 0], dom[1, 0]), dom[0, 1] - dom[0, 0], dom[1, 1] - dom[1, 0],
                                               facecolor=face, edgecolor=edge, linewidth=linewidth))
    for tag, key in ((PavingTag.Boundary, "boundary"), (PavingTag.Inner, "inner")):
        b = np.asarray(paving.boxes_array(tag), dtype=float)
        if len(b):
            face, edge = PAVING_COLOURS[tag]
            out[key] = ax.add_collection(PolyCollection(_rect_verts(b), facecolors=face, edgecolors=edge,
                                                        linewidths=linewidth))
    if show_diagonal:
        lo, hi = max(dom[0, 0], dom[1, 0]), min(dom[0, 1], dom[1, 1])
        (out["diagonal"],) = ax.plot([lo, hi], [lo, hi], color=_DIAGONAL, linewidth=0.8)

    groups = {s: [] for s in _STATUS_ORDER}
    for loop in tplane.detections():
        groups[loop_status(loop)].append(loop)
        # The proven pieces of a split detection, drawn over it.
        groups["proven"] += [p for p in loop.pieces() if p.proven()]
    size = max(dom[0, 1] - dom[0, 0], dom[1, 1] - dom[1, 0])
    centres, centre_colours = [], []
    outlines, outline_colours = [], []
    for status in _STATUS_ORDER:
        loops = groups[status]
        if not loops:
            continue
        face, edge = LOOP_COLOURS[status]
        arrays = [np.asarray(l.boxes_array(), dtype=float) for l in loops]
        # Filled without edges (the boxes' seams would show), then outlined by the contours.
        out[status] = ax.add_collection(PolyCollection(_rect_verts(np.concatenate(arrays)), facecolors=face,
                                                       edgecolors="none", alpha=alpha))
        segs = _outline_segments([l.boxes() for l in loops])
        outlines.append(segs)
        outline_colours += [edge] * len(segs)
        for l in loops:
            h = _box_array(l.t_box())
            if markers and max(h[0, 1] - h[0, 0], h[1, 1] - h[1, 0]) < markers * size:
                centres.append(h.mean(axis=1))
                centre_colours.append(face)
    if outlines:
        out["outlines"] = ax.add_collection(LineCollection(np.concatenate(outlines), colors=outline_colours,
                                                           linewidths=1.0))
    if centres:
        c = np.asarray(centres)
        out["markers"] = ax.scatter(c[:, 0], c[:, 1], s=30, c=centre_colours, edgecolors="none", zorder=3)
    if truth is not None:
        t = _crossing_times(truth)
        if len(t):
            (out["truth"],) = ax.plot(t[:, 0], t[:, 1], "o", color=_TPLANE_CROSSING, markeredgecolor="white",
                                      markeredgewidth=0.5, markersize=3.5, linestyle="none", zorder=4)
    if autoscale:
        ax.set_xlim(dom[0, 0], dom[0, 1])
        ax.set_ylim(dom[1, 0], dom[1, 1])
        ax.set_xlabel("t1 (s)")
        ax.set_ylabel("t2 (s)")
    if legend:
        out["legend"] = _tplane_legend(ax, out)
    return out


def _tplane_legend(ax, out):
    """A legend with one entry per drawn kind (patches for the fills, the lines themselves)."""
    handles = []
    for key in ("domain", "outside", "boundary", "inner", "partial", "unproven", "proven"):
        if key not in out:
            continue
        if key in LOOP_COLOURS:
            face, edge = LOOP_COLOURS[key]
        else:
            face, edge = PAVING_COLOURS[{"domain": PavingTag.Outside, "outside": PavingTag.Outside,
                                         "boundary": PavingTag.Boundary, "inner": PavingTag.Inner}[key]]
        handles.append(Patch(facecolor=face, edgecolor=edge, label=TPLANE_LEGEND[key]))
    for key in ("diagonal", "truth"):
        if key in out:
            out[key].set_label(TPLANE_LEGEND[key])
            handles.append(out[key])
    return ax.legend(handles=handles, loc="lower right", fontsize="small", framealpha=0.9)


def _path_array(positions):
    p = np.asarray(positions, dtype=float)
    if p.ndim != 2 or p.shape[1] != 2:
        raise ValueError(f"plot_loops_map: positions must be a TubeVector or an (n, 2) array, got shape {p.shape}")
    return p


def plot_loops_map(ax, tplane, positions=None, times=None, crossings=None, origin=None, show_partial=True,
                   alpha=0.2, autoscale=True):
    """Draws the trajectory and the map boxes of the detections (after compute_proofs); returns a dict.

    `positions`: a position TubeVector (its slices are drawn), or the path as an (n, 2) array of
    points. `times`: the (increasing) times of those points; then the two pieces of the path over
    [t1] and [t2] of each detection are drawn in bold with its colour, as in the thesis.
    `crossings`: PathCrossings drawn as red points at (x, y). `origin`: a point added to every map
    box; from a velocity tube alone the map boxes are relative to p(t0) (Loop.map_box), so give
    p(t0) to draw them over an absolute path. Keys: 'tube' or 'path', 'proven', 'unproven',
    'partial' (map boxes), 'projections', 'crossings'; absent when there is nothing to draw.
    """
    out = {}
    shift = np.zeros(2) if origin is None else np.asarray(origin, dtype=float).reshape(2)
    path = None
    if positions is not None and hasattr(positions, "tdomain"):
        out["tube"] = plot_tube_vector_2d(ax, positions, 0, 1, color="#dfe9f5", edgecolor="#9fbcdc",
                                          autoscale=autoscale)
    elif positions is not None:
        path = _path_array(positions)
        (out["path"],) = ax.plot(path[:, 0], path[:, 1], color=_PATH, linewidth=0.8)
    if times is not None:
        times = np.asarray(times, dtype=float)
        if path is None or times.shape != (len(path),):
            raise ValueError("plot_loops_map: times need an (n, 2) path of the same length")

    bounds = []  # of what is drawn, for the limits
    projections, projection_colours = [], []
    for status in _STATUS_ORDER:
        if status == "partial" and not show_partial:
            continue
        face, edge = LOOP_COLOURS[status]
        loops = [l for l in tplane.detections() if loop_status(l) == status]
        boxes = [b for b in (_box_array(l.map_box()) for l in loops) if b is not None]
        if boxes:
            b = np.asarray(boxes) + shift[:, None]
            bounds.append(b)
            out[status] = ax.add_collection(PolyCollection(_rect_verts(b), facecolors=face, edgecolors=edge,
                                                           linewidths=1.0, alpha=alpha))
        if times is None:
            continue
        for l in loops:
            tb = l.t_box()
            for t in (tb[0], tb[1]):
                if t.is_empty():
                    continue
                lo, hi = np.searchsorted(times, t.lb(), "left"), np.searchsorted(times, t.ub(), "right")
                if hi - lo >= 2:
                    projections.append(path[lo:hi])
                    projection_colours.append(face)
    if projections:
        out["projections"] = ax.add_collection(LineCollection(projections, colors=projection_colours,
                                                              linewidths=2.5))
    if crossings:
        xy = np.asarray([(c.x, c.y) for c in crossings], dtype=float)
        (out["crossings"],) = ax.plot(xy[:, 0], xy[:, 1], "o", color=_MAP_CROSSING, markeredgecolor="white",
                                      markeredgewidth=0.5, markersize=5, linestyle="none", zorder=4)
    if autoscale and "tube" not in out:
        for b in bounds:
            ax.update_datalim(np.concatenate([b[:, :, 0], b[:, :, 1]]))
        ax.autoscale_view()
    if autoscale:
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
    return out

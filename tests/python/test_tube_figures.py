"""SVG figures of tubes and the matplotlib tube helpers (Agg backend)."""
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
import sillage  # noqa: E402
from sillage import Interval, TDomain, Trajectory, Tube, TubeVector  # noqa: E402
from sillage import plot_tube as pt  # noqa: E402

NS = "{http://www.w3.org/2000/svg}"


def elements(svg, tag, cls):
    root = ET.fromstring(svg.encode())
    return [e for e in root.iter(NS + tag) if e.get("class") == cls]


def test_tube_figure_one_rect_per_slice_and_truth():
    td = TDomain(0, 6, 0.5)
    x = Tube(td, "sin(t) + [-0.2, 0.2]")
    truth = Trajectory("sin(t)", Interval(0, 6))
    fig = sillage.tube_figure(x, "sin & co", sillage.TubeStyle(show_gates=True, merge_px=0), truth)
    svg = fig.svg()
    assert len(elements(svg, "rect", "slice")) == x.nb_slices()
    assert len(elements(svg, "rect", "gate")) == x.nb_slices() + 1
    assert len(elements(svg, "polyline", "truth")) == 1
    assert "sin &amp; co" in svg


def test_draw_tube_on_a_figure_and_aggregation():
    td = TDomain(0, 10, 1e-4)
    x = Tube(td, "cos(t) + [-0.1, 0.1]")
    fig = sillage.Figure(sillage.IntervalVector([Interval(0, 10), Interval(-2, 2)]), 600, 300)
    n = sillage.draw_tube(fig, x)
    assert 0 < n <= 2000
    assert len(elements(fig.svg(), "rect", "slice")) == n
    assert len(fig.svg()) < 300000
    with pytest.raises(sillage.Error):
        sillage.draw_tube(fig, x, sillage.TubeStyle(merge_px=-1))


def test_unbounded_tube_is_clipped():
    td = TDomain(0, 3, 1)
    x = Tube(td, [Interval(), Interval(0, float("inf")), Interval(-1, 2)])
    svg = sillage.tube_figure(x, "u").svg()
    assert "clipped" in svg
    assert len(elements(svg, "rect", "slice")) == 3
    sillage.thickness_figure(Tube(td)).svg()


def test_tube_vector_figure_and_thickness():
    td = TDomain(0, 6, 0.5)
    v = TubeVector(td, "(cos(t) + [-0.1, 0.1], sin(t) + [-0.2, 0.2])")
    a, b = Trajectory("cos(t)", Interval(0, 6)), Trajectory("sin(t)", Interval(0, 6))
    fig = sillage.tube_vector_figure(v, 0, 1, "path", sillage.TubeStyle(merge_px=0), a, b)
    svg = fig.svg()
    assert len(elements(svg, "rect", "slice")) == v.nb_slices()
    assert len(elements(svg, "rect", "initial")) == 1 and len(elements(svg, "rect", "final")) == 1
    with pytest.raises(sillage.Error):
        sillage.tube_vector_figure(v, 0, 0)
    d = sillage.thickness_values(v)
    assert len(d) == v.nb_slices() and min(d) >= 0.4
    diag = sillage.thickness_values(v, sillage.ThicknessMeasure.Diagonal)
    assert all(q >= p for p, q in zip(d, diag))
    assert len(elements(sillage.thickness_figure(v).svg(), "polyline", "thickness")) == 1
    assert len(elements(sillage.thickness_figure(v[0], "d").svg(), "polyline", "thickness")) == 1


def test_plot_tube_matplotlib():
    td = TDomain(0, 10, 1e-3)
    x = Tube(td, "cos(t) + [-0.1, 0.1] * (1 + t)")
    truth = Trajectory("cos(t)", Interval(0, 10))
    fig, ax = plt.subplots()
    coll = pt.plot_tube(ax, x, traj=truth, gates=True, max_shapes=500)
    assert len(coll.get_paths()) <= 500
    # The merged rectangles cover the tube: the hull of the drawn y's contains the codomain.
    ys = np.concatenate([p.vertices[:, 1] for p in coll.get_paths()])
    c = x.codomain()
    assert ys.min() <= c.lb() and ys.max() >= c.ub()
    assert ax.get_xlim() == (0.0, 10.0)
    fig.canvas.draw()
    plt.close(fig)


def test_plot_tube_keeps_empty_slices_visible():
    td = TDomain(0, 10, 1e-3)
    x = Tube(td, "cos(t) + [-0.1, 0.1]")
    x.set(Interval.empty(), 5000)
    fig, ax = plt.subplots()
    coll = pt.plot_tube(ax, x, max_shapes=100)
    assert len(coll.get_paths()) <= 102
    xs = [(p.vertices[:, 0].min(), p.vertices[:, 0].max()) for p in coll.get_paths()]
    t0, t1 = td.t(5000), td.t(5001)
    assert not any(a < t1 and b > t0 for a, b in xs)  # the gap of the empty slice is not covered
    plt.close(fig)


def test_plot_tube_unbounded_and_small():
    td = TDomain(0, 3, 1)
    x = Tube(td, [Interval(), Interval(0, float("inf")), Interval(-1, 2)])
    fig, ax = plt.subplots()
    coll = pt.plot_tube(ax, x)
    assert len(coll.get_paths()) == 3
    assert np.all(np.isfinite(np.concatenate([p.vertices for p in coll.get_paths()])))
    fig.canvas.draw()
    plt.close(fig)


def test_plot_tube_vector_2d_and_thickness():
    td = TDomain(0, 6, 0.01)
    v = TubeVector(td, "(cos(t) + [-0.05, 0.05], sin(t) + [-0.05, 0.05], t)")
    fig, (a1, a2, a3) = plt.subplots(1, 3)
    coll = pt.plot_tube_vector_2d(a1, v, 0, 1, truth=(Trajectory("cos(t)", Interval(0, 6)),
                                                      Trajectory("sin(t)", Interval(0, 6))))
    assert len(coll.get_paths()) == v.nb_slices()
    coll = pt.plot_tube_vector_2d(a1, v, 0, 1, max_shapes=100)
    assert len(coll.get_paths()) <= 100
    with pytest.raises(ValueError):
        pt.plot_tube_vector_2d(a1, v, 1, 1)
    line = pt.plot_thickness(a2, v)
    assert len(line.get_xdata()) == v.nb_slices() + 1
    pt.plot_thickness(a3, v[0])
    pt.plot_thickness(a3, v, measure=sillage.ThicknessMeasure.Diagonal)
    fig.canvas.draw()
    plt.close(fig)


def test_plot_module_reexports_tube_helpers():
    from sillage import plot
    assert plot.plot_tube is pt.plot_tube


def test_axis_labels_landmarks_and_legend():
    td = TDomain(0, 6, 0.1)
    v = TubeVector(td, "(cos(t) + [-0.1, 0.1], sin(t) + [-0.1, 0.1])")
    a, b = Trajectory("cos(t)", Interval(0, 6)), Trajectory("sin(t)", Interval(0, 6))
    marks = [[3.0, 0.5], [-2.0, -4.0]]
    svg = sillage.tube_vector_figure(v, 0, 1, "map", sillage.TubeStyle(), a, b, 400, marks, "east (m)",
                                     "north (m)").svg()
    root = ET.fromstring(svg.encode())
    labels = {e.get("class"): e.text for e in root.iter(NS + "text") if e.get("class") in ("x-label", "y-label")}
    assert labels == {"x-label": "east (m)", "y-label": "north (m)"}
    frame = elements(svg, "rect", "frame")[0]
    x0, y0 = float(frame.get("x")), float(frame.get("y"))
    x1, y1 = x0 + float(frame.get("width")), y0 + float(frame.get("height"))
    dots = elements(svg, "circle", "landmark")
    assert len(dots) == 2
    assert all(x0 <= float(d.get("cx")) <= x1 and y0 <= float(d.get("cy")) <= y1 for d in dots)
    legend = [e for e in root.iter(NS + "g") if e.get("class") == "legend"]
    assert len(legend) == 1 and "landmarks" in ET.tostring(legend[0]).decode()
    y_label = [e for e in ET.fromstring(sillage.tube_figure(v[0], "c", name="c (m)").svg().encode()).iter(NS + "text")
               if e.get("class") == "y-label"]
    assert y_label[0].text == "c (m)"
    assert sillage.Style(label="tube").label == "tube"

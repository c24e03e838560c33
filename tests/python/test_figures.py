"""SVG figures, the HTML index and the matplotlib helpers (Agg backend)."""
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402
import sillage  # noqa: E402
from sillage import Interval, IntervalVector, PavingTag  # noqa: E402
from sillage import plot  # noqa: E402

NS = "{http://www.w3.org/2000/svg}"


def box(a, b, c, d):
    return IntervalVector([Interval(a, b), Interval(c, d)])


def disk_paving(eps=0.1):
    return sillage.sivia(box(-2, 2, -2, 2), lambda x: x[0] * x[0] + x[1] * x[1], Interval(0, 1), eps)


def rects(svg, cls):
    root = ET.fromstring(svg.encode())
    return [r for r in root.iter(NS + "rect") if r.get("class") == cls]


def test_figure_svg_is_well_formed_with_one_rect_per_leaf():
    p = disk_paving()
    fig = sillage.Figure(box(-2, 2, -2, 2), 300)
    fig.set_title("disk & <paving>")
    fig.draw_paving(p)
    fig.draw_contour(p.components()[0].contour())
    fig.draw_ring([0.0, 0.0], Interval(0.9, 1.1), sillage.Style(fill="orange", opacity=0.3, css_class="ring"))
    fig.draw_point([0.0, 0.0])
    fig.draw_box(box(-1, 1, -1, 1), sillage.Style(stroke="red", css_class="mine"))
    svg = fig.svg()
    assert len(rects(svg, "inner")) == p.count(PavingTag.Inner)
    assert len(rects(svg, "boundary")) == p.count(PavingTag.Boundary)
    assert len(rects(svg, "outside")) == p.count(PavingTag.Outside)
    (mine,) = rects(svg, "mine")
    assert float(mine.get("width")) == pytest.approx(150.0)
    root = ET.fromstring(svg.encode())
    assert [t.text for t in root.iter(NS + "text")][0] == "disk & <paving>"
    assert len([e for e in root.iter(NS + "path") if e.get("class") == "ring"]) == 1
    assert sillage.paving_style(PavingTag.Inner).css_class == "inner"


def test_figure_errors_and_html(tmp_path):
    with pytest.raises(sillage.Error):
        sillage.Figure(box(0, 0, 0, 1))
    fig = sillage.Figure(box(0, 1, 0, 1), 100)
    with pytest.raises(sillage.Error):
        fig.draw_box(IntervalVector([Interval(0, 1)]))
    html = sillage.Html("Report")
    html.add(fig, "a.svg", "An empty figure")
    with pytest.raises(sillage.Error):
        html.add(fig, "../b.svg", "outside the directory")
    html.save(str(tmp_path))
    assert (tmp_path / "a.svg").read_text() == fig.svg()
    index = (tmp_path / "index.html").read_text()
    assert 'src="a.svg"' in index and "An empty figure" in index
    ET.fromstring(index.split("\n", 1)[1].encode())  # well-formed after the doctype


def test_matplotlib_helpers():
    p = disk_paving()
    fig, ax = plt.subplots()
    colls = plot.plot_paving(ax, p)
    assert len(colls[PavingTag.Inner].get_paths()) == p.count(PavingTag.Inner)
    assert len(colls[PavingTag.Outside].get_paths()) == p.count(PavingTag.Outside)
    assert ax.get_xlim() == (-2.0, 2.0)
    assert plot.plot_box(ax, box(0, 1, 0, 1), facecolor="red") is not None
    assert plot.plot_box(ax, IntervalVector([Interval.empty(), Interval.empty()])) is None
    assert plot.plot_ring(ax, (8.0, 5.0), Interval(9.03, 9.83)) is not None
    assert plot.plot_ring(ax, (0.0, 0.0), (0.0, 1.0)) is not None
    lines = plot.plot_contour(ax, p.components()[0].contour(), arrows=True)
    assert len(lines) == 1
    no_out = plot.plot_paving(ax, p, show_outside=False)
    assert PavingTag.Outside not in no_out
    plt.close(fig)

"""Matplotlib figures of the Python examples: titles and axis labels inside
the saved figure, and thickness curves that coincide named together."""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402
from sillage import TDomain, Tube, TubeVector  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "examples" / "python"))
problem_file = pytest.importorskip("problem_file")
bathymetry_slam = pytest.importorskip("bathymetry_slam")


def assert_texts_inside(fig):
    """Every title and axis label of fig lies within the figure (none clipped at its edges)."""
    renderer = fig.canvas.get_renderer()
    w, h = fig.bbox.width, fig.bbox.height
    for ax in fig.axes:
        for t in (ax.title, ax.xaxis.label, ax.yaxis.label):
            if not t.get_text():
                continue
            b = t.get_window_extent(renderer)
            assert b.x0 >= 0 and b.y0 >= 0 and b.x1 <= w and b.y1 <= h, (t.get_text(), b, w, h)


def test_problem_file_figure_labels_fit(tmp_path):
    x = Tube(TDomain(0.0, 20.0, 0.1), "sin(t) + 1 + [-0.1, 0.1]")
    fig = problem_file.tube_figure(x, tmp_path / "p.png")
    assert fig.axes[0].get_xlabel() == "t (s)"
    assert_texts_inside(fig)
    plt.close(fig)


def test_bathymetry_thickness_names_coinciding_curves(tmp_path):
    td = TDomain(0.0, 10.0, 0.5)
    wide = TubeVector(td, "(t + [-2, 2] * t, [-1, 1])")
    thin = TubeVector(td, "(t + [-1, 1], [-1, 1])")
    fig = bathymetry_slam.thickness_figure([(wide, "#777777", "dead reckoning"), (thin, "#2a6aa8", "fast"),
                                            (thin, "#d62728", "accurate")], tmp_path / "t.png")
    ax = fig.axes[0]
    texts = [t.get_text() for t in ax.get_legend().get_texts()]
    assert texts == ["dead reckoning", "fast = accurate (the curves coincide)"]
    assert len({line.get_linestyle() for line in ax.get_lines()}) == 3  # distinct dashes too
    assert_texts_inside(fig)
    plt.close(fig)

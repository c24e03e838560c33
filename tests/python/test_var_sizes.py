"""The sizes a user reads (sillage.var_sizes) and the bound audit of a problem file
(sillage.audit_problem), the same names as in C++; the CLI prints both and writes them to
results.json."""
import json
import math
import subprocess
from pathlib import Path

import sillage

BUILD = Path(sillage.__file__).resolve().parents[2]
SILLAGE = BUILD / "tools" / "sillage" / "sillage"
PROBLEMS = Path(__file__).resolve().parents[2] / "examples" / "problems"


def test_var_sizes_of_line_ranges():
    p = sillage.load_problem(str(PROBLEMS / "line_ranges.toml"))
    r = sillage.solve_problem(p)
    sizes = {s.name: s for s in sillage.var_sizes(p, r)}
    assert list(sizes) == ["v", "x"]  # the order of Problem.variables
    x = sizes["x"]
    assert x.unit == "" and x.dim == 1 and x.over_time.samples == 400
    assert x.at_truth.samples == 201
    assert 0 < x.over_time.median <= x.over_time.max < 0.5
    assert sizes["v"].over_time.max > 0.02  # cos(t) ± 0.01 over a slice of 0.05 s
    assert "x: box diameter mean" in x.str()
    table = sillage.sizes_table(list(sizes.values())).splitlines()
    assert len(table) == 3 and table[1].startswith("v ") and table[2].startswith("x ")
    s = sillage.size_stats([1.0, 2.0, 10.0], [1.0, 1.0, 0.5])
    assert (s.mean, s.median, s.max, s.samples) == (8 / 2.5, 2.0, 10.0, 3)


def test_audit_problem_of_line_ranges():
    lines = sillage.audit_problem(sillage.load_problem(str(PROBLEMS / "line_ranges.toml")))
    by_name = {l.name: l for l in lines}
    assert "[var.x] value of x" in by_name
    ranges = [l for l in lines if "eval" in l.name]
    assert len(ranges) == 1 and "over 9 rows" in ranges[0].how
    assert all(l.percent() <= 100 for l in lines), [l.text() for l in lines]
    # The examples build their own lines from the same class.
    line = sillage.AuditLine("turn rate", "rad/s", 2.0, 3.0, "measured")
    assert line.percent() == 150 and line.text().endswith("<-- VIOLATED")
    assert math.isnan(sillage.AuditLine("x", "", 1.0, float("nan"), "").used)


def test_cli_prints_sizes_and_audit(tmp_path):
    r = subprocess.run([str(SILLAGE), "solve", str(PROBLEMS / "line_ranges.toml"), "--out", str(tmp_path)],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    assert "sizes: box diameter (the largest width over the components), mean / median / max" in r.stdout
    assert "    variable  unit  over time" in r.stdout and "at the 201 truth times" in r.stdout
    assert "\n    x   " in r.stdout
    assert "bound audit: how much of each stated bound the truth used" in r.stdout
    res = json.loads((tmp_path / "results.json").read_text())
    assert set(res["sizes"]) == {"x", "v"} and res["sizes"]["x"]["at_truth"]["samples"] == 201
    assert res["sizes"]["x"]["over_time"]["max"] > 0
    assert all(a["percent"] is None or a["percent"] <= 100 for a in res["bound_audit"])
    html = (tmp_path / "report.html").read_text()
    assert html.index('id="sizes"') < html.index('id="results"') < html.index('<details id="problem">')


def test_map_envelope_figure_in_python():
    td = sillage.TDomain(0.0, 100.0, 1.0)
    x = sillage.TubeVector(td, "(t + [-1, 1], [-1, 1])")
    svg = sillage.map_envelope_figure(x, 0, 1, "map", boxes=3).svg()
    assert "envelope of the 100 slice boxes" in svg and "a slice box (3 drawn)" in svg
    loops = sillage.map_envelope(x, 0, 1, sillage.IntervalVector([[-5, 105], [-2, 2]]), 110)
    assert len(loops) == 1 and not loops[0].is_hole

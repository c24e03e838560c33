"""Problem files from Python: sillage.solve returns the domains as sillage
objects, the same sets as the C++ network (tests/cpp/problem), errors with
file:line:column."""
import math
from pathlib import Path

import pytest

import sillage

PROBLEMS = Path(__file__).resolve().parents[2] / "examples" / "problems"


def test_solve_returns_sillage_objects():
    r = sillage.solve(str(PROBLEMS / "line_ranges.toml"))
    assert not r.empty and r.why_empty == ""
    x, v = r.domains["x"], r.domains["v"]
    assert isinstance(x, sillage.Tube) and isinstance(v, sillage.Tube)
    for i in range(0, 201, 7):
        t = 0.1 * i
        assert x(t).contains(math.sin(t) + 1)
    assert x.max_thickness() < 0.5
    assert r.schedule[-1]["slices"] == 400
    assert "solved" in repr(r)


def test_tube_vectors_and_the_cpp_sets():
    r = sillage.solve(str(PROBLEMS / "causal_chain.toml"))
    x = r.domains["x"]
    assert isinstance(x, sillage.TubeVector) and x.size() == 3
    # the final box of the file at t = 14
    assert x[0].gate(x.nb_slices()).is_subset(sillage.Interval(53.8, 56))


def test_auto_delta_schedule():
    r = sillage.solve(str(PROBLEMS / "line_ranges.toml"), auto_delta=True, tolerance=0.05)
    deltas = [s["delta"] for s in r.schedule]
    assert len(deltas) >= 2 and all(b == a / 2 for a, b in zip(deltas, deltas[1:]))


def test_auto_delta_by_regions():
    """refinement=Regions splits only the slices thick over their gates: fewer
    slices than halving for about the same thickness, the truth x(0) = 1 inside."""
    path = str(PROBLEMS / "line_ranges.toml")
    halving = sillage.solve(path, auto_delta=True, tolerance=0.05)
    regions = sillage.solve(path, auto_delta=True, tolerance=0.05, refinement=sillage.DeltaRefinement.Regions)
    assert regions.domains["x"](0.0).contains(1.0)
    slices = [s["slices"] for s in regions.schedule]
    assert all(b > a for a, b in zip(slices, slices[1:])) and slices[-1] < halving.schedule[-1]["slices"]
    assert regions.schedule[-1]["mean_thickness"] < regions.schedule[0]["mean_thickness"]


def test_solve_keywords_are_the_cli_options():
    """delta="auto", refine="halving" | "regions", scheduling="fifo" | "priority" (or the
    enums), as `sillage solve --delta auto --refine ... --scheduling ...`."""
    path = str(PROBLEMS / "line_ranges.toml")
    a = sillage.solve(path, delta="auto", refine="regions", tolerance=0.05)
    b = sillage.solve(path, auto_delta=True, refinement=sillage.DeltaRefinement.Regions, tolerance=0.05)
    assert [s["slices"] for s in a.schedule] == [s["slices"] for s in b.schedule] and len(a.schedule) >= 2
    assert sillage.solve(path, delta="auto", refine="halving", tolerance=0.05).schedule[-1]["slices"] == \
        sillage.solve(path, auto_delta=True, tolerance=0.05).schedule[-1]["slices"]
    assert sillage.solve(path).scheduling == sillage.Scheduling.Fifo  # the file's (none: FIFO)
    # The drifting clock (ratio 0 in its file): there the two orders take different runs.
    clock = str(PROBLEMS / "drifting_clock.toml")
    fifo, prio = sillage.solve(clock, scheduling="fifo"), sillage.solve(clock, scheduling=sillage.Scheduling.Priority)
    assert fifo.scheduling == sillage.Scheduling.Fifo and prio.scheduling == sillage.Scheduling.Priority
    assert prio.schedule[-1]["stats"].contractor_calls != fifo.schedule[-1]["stats"].contractor_calls
    for kw, msg in [({"delta": "coarse"}, "auto"), ({"refine": "thirds"}, "halving"), ({"scheduling": "lifo"}, "priority")]:
        with pytest.raises(ValueError, match=msg):
            sillage.solve(path, **kw)


def test_load_problem_errors_name_the_place(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("[time]\ndomain = [0, 1]\ndelta = 0.1\nspeed = 3\n")
    with pytest.raises(sillage.ParseError, match=r"bad.toml:4:1: found the unknown key 'speed' in \[time\]"):
        sillage.load_problem(str(bad))
    p = sillage.load_problem(str(PROBLEMS / "dead_reckoning.toml"))
    assert p.variables == ["v", "x"] and p.nb_constraints == 3
    assert "3 nodes" in sillage.check_summary(p)
    r = sillage.solve_problem(p, delta=0.5)
    assert r.schedule[0]["slices"] == 128


def test_a_log_with_text_columns(tmp_path):
    """A table with text columns (a frame name, a status) solves as long as no expression reads them."""
    (tmp_path / "fixes.csv").write_text("t,frame,x,status\n0,base_link,0,ok\n1,base_link,1,\n2,odom,2,slip\n")
    head = ('[data.fixes]\nfile = "fixes.csv"\n[time]\npoints = { data = "fixes", column = "t" }\n'
            '[var.v]\nkind = "tube"\nvalue = "[0.9, 1.1]"\n[var.x]\nkind = "tube"\n')
    tail = '[[constraint]]\nkind = "deriv"\nx = "x"\nv = "v"\n'
    problem = tmp_path / "log.toml"
    problem.write_text(head + 'gates = { data = "fixes", value = "x + [-0.1, 0.1]" }\n' + tail)
    r = sillage.solve(str(problem))
    x = r.domains["x"]
    assert not r.empty and x.gate(1).contains(1.0) and x.gate(1).diam() < 0.25
    assert x.slice(0).contains(0.5) and x.slice(0).is_subset(sillage.Interval(-0.2, 1.2))
    line = 'gates = { data = "fixes", value = "x + status" }'
    problem.write_text(head + line + "\n" + tail)
    at = f"log.toml:10:{line.index('x + status') + 1}"
    with pytest.raises(sillage.ParseError, match=f"{at}: found the column 'status' of table 'fixes', which is "
                       r"not all numbers \(.*fixes.csv:2: column 'status': 'ok' is not a finite number\)"):
        sillage.load_problem(str(problem))


def test_find_loops_and_constraint_order():
    p = sillage.load_problem(str(PROBLEMS / "figure_eight.toml"))
    r = sillage.solve_problem(p)
    tp = sillage.find_loops(p, r)
    assert isinstance(tp, sillage.TPlane)
    assert tp.nb_complete_detections() == 1 and tp.nb_proofs() == 1
    (loop,) = [l for l in tp.detections() if l.complete()]
    assert loop.t_box()[0].contains(math.pi / 2) and loop.t_box()[1].contains(3 * math.pi / 2)
    assert sillage.constraint_order(sillage.load_problem(str(PROBLEMS / "drifting_clock.toml"))) == [0, 1, 2, 3, 4, 5]


def test_check_truth_and_the_delta_given():
    p = sillage.load_problem(str(PROBLEMS / "line_ranges.toml"))
    c = sillage.check_truth(p, sillage.solve_problem(p))
    assert c.samples == 201 and c.inside == 201 and c.first_misses == []
    assert "201 of 201" in repr(c)
    # A delta given beside the file meets the file's rule, the option named.
    for bad in (-1.0, 0.0, 100.0, 1e-12):
        with pytest.raises(sillage.Error, match=r"^delta: found .*expected"):
            sillage.solve_problem(p, delta=bad)
        with pytest.raises(sillage.Error, match=r"^--delta: found "):
            sillage.check_delta(p, bad, "--delta")
    sillage.check_delta(p, 0.05)  # the file's own: no error

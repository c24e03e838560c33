"""Outliers in problem files (`q`, `q_window`, `q_rows` on an eval), in Python: one range of the
robot on a line corrupted (tests/cpp/problem/test_eval_outliers.cpp is the C++ twin)."""
from pathlib import Path

import sillage

PROBLEMS = Path(__file__).resolve().parents[2] / "examples" / "problems"


def write_problem(tmp_path, keys, bad=(4,)):
    rows = []
    n = 0
    for line in (PROBLEMS / "data" / "beacon_ranges.csv").read_text().splitlines():
        if line and line[0] not in "#t":
            t, b, r = line.split(",")
            if n in bad:
                r = repr(float(r) + 3)
            line = ",".join([t, b, r])
            n += 1
        rows.append(line)
    (tmp_path / "ranges.csv").write_text("\n".join(rows) + "\n")
    text = (PROBLEMS / "line_ranges.toml").read_text()
    text = text.replace('file = "data/beacon_ranges.csv"', f'file = "{tmp_path / "ranges.csv"}"')
    text = text.replace('file = "data/line_truth.csv"', f'file = "{PROBLEMS / "data" / "line_truth.csv"}"')
    text = text.replace('expr = "abs(x - b) - r"', keys + 'expr = "abs(x - b) - r"')
    path = tmp_path / "p.toml"
    path.write_text(text)
    return sillage.load_problem(str(path))


def test_one_wrong_range(tmp_path):
    assert sillage.solve_problem(write_problem(tmp_path, "")).empty
    for keys in ("q = 1\n", "q = 1\nq_window = 6\n", "q = 1\nq_rows = 4\n"):
        p = write_problem(tmp_path, keys)
        r = sillage.solve_problem(p)
        assert not r.empty, keys
        c = sillage.check_truth(p, r)
        assert c.inside == c.samples > 100, keys


def test_too_many_in_a_window_are_named(tmp_path):
    r = sillage.solve_problem(write_problem(tmp_path, "q = 1\nq_rows = 4\n", bad=(3, 4)))
    assert r.empty and "2 of its 4 fixes violated by every trajectory: ranges line 6, ranges line 7" in r.why_empty

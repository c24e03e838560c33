"""`sillage solve` on the example problems of thesis chapters 4 and 5 (the
kidnapped robot, the drifting clock, the low-cost beacons): each one solved
by the command, its truth table checked in the report and in the CSV it
writes (tests/cpp/problem/test_problem_examples_ch4_ch5.cpp compares the
sets with the C++ examples' networks)."""
import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import sillage

BUILD = Path(sillage.__file__).resolve().parents[2]
SILLAGE = BUILD / "tools" / "sillage" / "sillage"
PROBLEMS = Path(__file__).resolve().parents[2] / "examples" / "problems"


def solve(name, out):
    r = subprocess.run([str(SILLAGE), "solve", str(PROBLEMS / name), "--out", str(out), "--quiet"],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stdout + r.stderr
    return json.loads((out / "results.json").read_text())


def truth_rows(name):
    lines = [l for l in (PROBLEMS / "data" / name).read_text().splitlines() if not l.startswith("#")]
    return np.genfromtxt(lines, delimiter=",", names=True)


def gates(out, var):
    t = np.genfromtxt(out / (var + ".csv"), delimiter=",", names=True)
    return t[t["t_lb"] == t["t_ub"]]


@pytest.mark.parametrize("name, samples", [("kidnapped_robot.toml", 257), ("lowcost_beacons.toml", 257),
                                           ("drifting_clock.toml", 131)])
def test_truth_inside(tmp_path, name, samples):
    res = solve(name, tmp_path)
    assert res["status"] == "solved"
    assert res["summary"]["status"] == "converged" and res["summary"]["reason"] == ""
    assert res["summary"]["work"] == sum(s["contractor_calls"] for s in res["schedule"])
    # One per time point (row of the truth), every component inside, not one per component.
    assert f"{samples} of {samples} truth time points inside" in (tmp_path / "report.html").read_text()


def test_kidnapped_robot_from_one_measurement(tmp_path):
    solve("kidnapped_robot.toml", tmp_path)
    g = gates(tmp_path, "x")
    truth = truth_rows("robot_truth.csv")
    at = {round(t, 6): r for t, r in zip(g["t_lb"], g)}
    for row in truth[::8]:
        gate = at[round(float(row["t"]), 6)]
        for i in range(4):
            assert gate[f"x{i}_lb"] <= row[f"x{i + 1}"] <= gate[f"x{i}_ub"]
    # The measurement box at t = 37 (4.30) bounds the position there, and all
    # of [0, 64] through the dynamics.
    g37 = at[37.0]
    assert 59.25 - 1e-9 <= g37["x0_lb"] and g37["x0_ub"] <= 61.25 + 1e-9
    assert np.all(np.isfinite(g["x0_lb"])) and np.all(np.isfinite(g["x1_ub"]))


def test_drifting_clock_corrected(tmp_path):
    solve("drifting_clock.toml", tmp_path)
    h = gates(tmp_path, "h")
    true_h = 0.045 * h["t_lb"] ** 2 + 0.98 * h["t_lb"]
    assert np.all(h["h_lb"] <= true_h + 1e-9) and np.all(true_h <= h["h_ub"] + 1e-9)
    # h(0) = 0 and h' in [phi] alone give h(13) in [19.37, 24.18] (width
    # 0.02*13^2 + 0.11*13 = 4.81); the eight ranges (Table 5.3) correct it.
    assert h["h_ub"][-1] - h["h_lb"][-1] < 4.81 / 3


PLAZA1 = Path(__file__).resolve().parents[3] / "shared" / "data" / "plaza1"


@pytest.mark.skipif(not (PLAZA1 / "odometry.csv").exists(), reason="no plaza1 data")
def test_plaza1_real_data(tmp_path):
    """The real data read in place (${SILLAGE_DATA}, or the folder next to
    the repository): every ground-truth sample inside the position tube."""
    res = solve("plaza1.toml", tmp_path)
    assert res["status"] == "solved" and res["schedule"][0]["slices"] == 9657
    assert "9658 of 9658 truth time points inside" in (tmp_path / "report.html").read_text()
    p = gates(tmp_path, "p")
    truth = np.genfromtxt(PLAZA1 / "ground_truth.csv", delimiter=",", names=True)
    assert len(p) == len(truth)
    assert np.all((p["p0_lb"] <= truth["x_m"]) & (truth["x_m"] <= p["p0_ub"]))
    # The ranges bound the position box all along (odometry alone: over 3 km wide at the end).
    assert np.max(p["p0_ub"] - p["p0_lb"]) < 200
    # The map shows the 4 beacons ([output] landmarks) as dots, inside its window.
    html = (tmp_path / "report.html").read_text()
    first_map = html[html.index("<svg"):html.index("</svg>")]
    assert first_map.count('class="landmark"') == 4


def test_loops_in_the_report(tmp_path):
    """[output] loops: the t-plane of the velocity in the report, the one
    crossing of the figure eight proven, its figures drawn in Chromium."""
    from test_cli_report import PROBE, chromium_console
    solve("figure_eight.toml", tmp_path)
    html = (tmp_path / "report.html").read_text()
    assert "1 detections, 1 complete, 1 proven loops (degree test), 1 unique loops (Newton)" in html
    assert "The t-plane: detections of loops" in html and "The loops on the map" in html
    nb_svg = html.count("<svg")
    probe = tmp_path / "probe.html"
    probe.write_text(html.replace("</body>", PROBE + "</body>"))
    lines = chromium_console(probe)
    assert [l for l in lines if not l.startswith("SVG ")] == []
    sizes = [l for l in lines if l.startswith("SVG ")]
    assert len(sizes) == nb_svg and all(float(l[4:].split("x")[0]) > 100 for l in sizes)


SURVEY = BUILD / "examples" / "problems"


@pytest.mark.skipif(not (SURVEY / "loops_survey_velocity.csv").exists(),
                    reason="the survey's velocity table is generated by the build (target loops_survey_data)")
def test_loops_survey(tmp_path):
    """The loops survey of examples/cpp/loops_survey.cpp as a file: its
    velocity table from the build folder, the t-plane in the report with the
    example's detections and proofs (tests/cpp/problem/test_problem_loops_survey.cpp
    compares them one by one)."""
    r = subprocess.run([str(SILLAGE), "solve", str(PROBLEMS / "loops_survey.toml"), "--out", str(tmp_path), "--quiet"],
                       capture_output=True, text=True, timeout=600,
                       env={**os.environ, "SILLAGE_SURVEY_DATA": str(SURVEY)})
    assert r.returncode == 0, r.stdout + r.stderr
    html = (tmp_path / "report.html").read_text()
    assert "101 detections, 100 complete, 100 proven loops (degree test), 89 unique loops (Newton)" in html


def test_temporal_slam(tmp_path):
    """The temporal SLAM of the figure eight (examples/problems/temporal_slam.toml):
    the truth inside every gate, and the loop's observation narrows the final
    position below dead reckoning's (the same file without p_implies_z);
    tests/cpp/problem/test_problem_temporal_slam.cpp compares it with
    temporal_slam() bit for bit."""
    res = solve("temporal_slam.toml", tmp_path)
    assert res["status"] == "solved"
    assert "101 of 101 truth time points inside" in (tmp_path / "report.html").read_text()
    text = (PROBLEMS / "temporal_slam.toml").read_text()
    i = text.index("[[constraint]]           # C_p=>z")
    j = text.index("[network]")
    dr_file = tmp_path / "dead_reckoning.toml"
    dr_file.write_text(text[:i].replace('"data/', f'"{PROBLEMS}/data/') + text[j:])
    (tmp_path / "dr").mkdir()
    solve(str(dr_file), tmp_path / "dr")
    slam, dr = gates(tmp_path, "p"), gates(tmp_path / "dr", "p")
    for c in ("p0", "p1"):
        assert np.all(slam[c + "_lb"] >= dr[c + "_lb"]) and np.all(slam[c + "_ub"] <= dr[c + "_ub"])
    width = lambda g: (g["p0_ub"] - g["p0_lb"])[-1]
    assert width(slam) < 0.9 * width(dr)

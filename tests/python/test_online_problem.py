"""A problem file run online: OnlineProblem, replay_problem and the JSON Lines
of `sillage stream` in Python, and the two commands through real pipes
(docs/online.md, "From a problem file")."""
import json
import math
import subprocess
from pathlib import Path

import pytest

import sillage as s

BUILD = Path(s.__file__).resolve().parents[2]
SILLAGE = BUILD / "tools" / "sillage" / "sillage"
PROBLEMS = Path(__file__).resolve().parents[2] / "examples" / "problems"
CLOCK = PROBLEMS / "drifting_clock.toml"


def test_online_problem_feeds_rows_and_calls_back():
    p = s.load_problem(str(CLOCK))
    op = s.OnlineProblem(p)
    times = []
    op.on_update(lambda: times.append(op.estimator().now()))
    rows = op.recorded_rows()
    assert rows[0].table == "" and rows[0].t == pytest.approx(0.01)
    assert rows[-1].table == "clock" and rows[-1].t is None  # no time column: last
    for r in rows:
        op.feed(r)
    assert len(times) == 1308 and times[-1] == pytest.approx(13)  # 1300 advances, then the 8 readings
    est = json.loads(s.estimate_line(op))
    assert est["status"] == "converged" and list(est)[:3] == ["t", "status", "window"]
    assert set(op.outputs()) == {"x", "h", "y"}
    lo, hi = est["h"][0]
    assert lo < hi


def test_refusals_say_what_and_leave_the_estimate():
    op = s.OnlineProblem(s.load_problem(str(CLOCK)))
    op.feed(s.StreamRow(t=1.0))
    now = op.estimator().now()
    with pytest.raises(s.Error, match="no column nope"):
        op.feed(s.StreamRow("clock", None, {"tau": 1, "nope": 2}))
    with pytest.raises(s.Error, match="without its column z"):
        op.feed(s.StreamRow("clock", None, {"tau": 1}))
    with pytest.raises(s.Error, match="no table"):
        op.feed(s.StreamRow("other", 2.0, {}))
    assert op.estimator().now() == now


def test_replay_problem_holds_the_truth_and_the_batch():
    p = s.load_problem(str(CLOCK))
    r = s.replay_problem(p)
    assert r.summary.status == s.Status.Converged
    assert r.truth_samples == 131 and r.truth_inside == 131 and not r.truth_misses
    assert r.online_holds_batch() == len(r.t) == 1308
    assert r.mean_side_ratio() >= 1
    assert 0 < r.latency_quantile(0.5) <= r.latency_quantile(0.99)
    report = json.loads(s.replay_json(p, r))
    assert report["updates"] == 1308 and report["truth"]["inside"] == 131
    assert s.replay_svg(p, r).startswith("<svg") or "<svg" in s.replay_svg(p, r)


def test_parse_stream_line_errors():
    assert s.parse_stream_line('{"t": 3}').table == ""
    with pytest.raises(s.Error, match="unknown key"):
        s.parse_stream_line('{"tabel": "x"}')


def test_observe_several_states_and_a_bound_of_t():
    est = s.OnlineEstimator(0.0)
    est.add_bounded("v", s.Function(["t"], "cos(t) + [-0.01, 0.01]"))
    est.add_state("x", 1, s.IntervalVector([s.Interval(0, 0)]))
    est.add_state("y", 1, s.IntervalVector([s.Interval(1, 1)]))
    est.add_bounded("w", s.IntervalVector([s.Interval(-0.1, 0.1)]))
    est.add_deriv("x", "v")
    est.add_deriv("y", "w")
    for k in range(1, 11):
        est.advance(0.1 * k)
    x = est.now("x")[0]
    assert x.contains(math.sin(1.0)) and x.diam() < 0.1
    # x(t) and y(t) at one uncertain time: x + y in [1.8, 1.9], the time reaching past now: held.
    n = est.observe(s.Interval(0.95, 1.05), ["x", "y"], s.CtcFunction(s.Function(["a", "b"], "a + b"),
                                                                      s.Interval(1.8, 1.9)))
    assert n == 0 and est.pending() == 1 and est.stats().pending == 1
    est.advance(1.1)
    assert est.pending() == 0 and est.stats().observations == 1


def run(args, stdin):
    return subprocess.run([str(SILLAGE), *args], input=stdin, capture_output=True, text=True, timeout=300)


def clock_lines():
    op = s.OnlineProblem(s.load_problem(str(CLOCK)))
    return [s.stream_line(r) for r in op.recorded_rows()]


def test_stream_through_a_pipe():
    lines = clock_lines()[:200]
    lines.insert(10, "not json")
    lines.insert(20, '{"table": "clock", "columns": {"tau": 1}}')
    r = run(["stream", str(CLOCK)], "\n".join(lines) + "\n")
    assert r.returncode == 0, r.stderr
    out = [json.loads(l) for l in r.stdout.splitlines()]
    assert len(out) == 200 and out[-1]["t"] == pytest.approx(2.0)  # 200 ticks, the 2 bad lines besides
    assert all(o["status"] == "converged" for o in out)
    errors = r.stderr.splitlines()
    assert errors[0].startswith("sillage stream: line 11: not JSON")
    assert errors[1] == "sillage stream: line 21: a row of clock without its column z"
    strict = run(["stream", str(CLOCK), "--strict"], "\n".join(lines) + "\n")
    assert strict.returncode == 2 and len(strict.stdout.splitlines()) == 10


def test_stream_says_no_solution():
    lines = clock_lines()[:100] + ['{"table": "clock", "columns": {"tau": 0.5, "z": 1e6}}', '{"t": 1.5}']
    r = run(["stream", str(CLOCK)], "\n".join(lines) + "\n")
    assert r.returncode == 1
    assert "no solution" in r.stderr


def test_replay_command_writes_its_report(tmp_path):
    r = run(["replay", str(CLOCK), "--out", str(tmp_path)], "")
    assert r.returncode == 0, r.stdout + r.stderr
    assert "131 of 131 samples inside" in r.stdout
    report = json.loads((tmp_path / "replay.json").read_text())
    assert report["status"] == "converged" and report["batch"]["online_holds_batch"] == 1308
    assert len((tmp_path / "online.jsonl").read_text().splitlines()) == 1308
    assert (tmp_path / "replay.svg").read_text().lstrip().startswith("<")
    html = (tmp_path / "replay.html").read_text()
    assert "131 of 131 samples inside the online tubes" in html and html.count("<svg") == 1
    bad = run(["replay", str(CLOCK), "--out", str(tmp_path), "--speed", "-1"], "")
    assert bad.returncode == 2


def test_replay_report_in_headless_chromium(tmp_path):
    """The replay's page loads in a real browser without a console message, its figure drawn."""
    from test_cli_report import PROBE, chromium_console
    r = run(["replay", str(CLOCK), "--out", str(tmp_path), "--quiet"], "")
    assert r.returncode == 0, r.stderr
    probe = tmp_path / "probe.html"
    probe.write_text((tmp_path / "replay.html").read_text().replace("</body>", PROBE + "</body>"))
    lines = chromium_console(probe)
    sizes = [l for l in lines if l.startswith("SVG ")]
    assert [l for l in lines if not l.startswith("SVG ")] == []
    assert len(sizes) == 1
    w, h = map(float, sizes[0][4:].split("x"))
    assert w > 100 and h > 100


def test_replay_never_overwrites_an_input(tmp_path):
    """A problem file named like an output of the replay, --out its own folder: refused, untouched."""
    data = PROBLEMS / "data"
    text = CLOCK.read_text().replace('file = "data/', f'file = "{data.as_posix()}/')
    problem = tmp_path / "replay.json"
    problem.write_text(text)
    r = run(["replay", str(problem), "--out", str(tmp_path)], "")
    assert r.returncode == 2 and "would overwrite the problem file" in r.stderr, r.stderr
    assert problem.read_text() == text


def test_replay_problem_is_cancelled_by_its_token(tmp_path):
    # A replay at 1x real time of a 13 s log, cancelled from another thread after 0.2 s:
    # sillage.Cancelled at once, not at the end of the log.
    import threading
    import time
    p = s.load_problem(str(CLOCK))
    token = s.CancelToken()
    threading.Timer(0.2, token.cancel).start()
    started = time.monotonic()
    with pytest.raises(s.Cancelled):
        s.replay_problem(p, s.ReplayOptions(speed=1.0, budget=s.Budget(cancel=token)))
    assert time.monotonic() - started < 1.0

"""The sillage command end to end: exit codes, the files it writes, and its
report.html opened in a real headless Chromium (it loads, logs nothing to the
console, and shows its figures at a non-zero size). Without Chromium the
browser test is skipped on a developer's machine and fails in CI."""
import json
import os
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

import sillage

BUILD = Path(sillage.__file__).resolve().parents[2]
SILLAGE = BUILD / "tools" / "sillage" / "sillage"
PROBLEMS = Path(__file__).resolve().parents[2] / "examples" / "problems"

# Appended to a copy of the report: one console line per SVG with its size.
PROBE = ("<script>for (const s of document.querySelectorAll('svg')) {"
         " const r = s.getBoundingClientRect(); console.log('SVG ' + r.width + 'x' + r.height); }</script>")


def run(*args):
    return subprocess.run([str(SILLAGE), *map(str, args)], capture_output=True, text=True, timeout=600)


def chromium_console(html_path):
    """The console lines Chromium logs while loading the page headless."""
    exe = shutil.which("chromium") or shutil.which("chromium-browser")
    if exe is None:
        if os.environ.get("CI"):
            pytest.fail("Chromium is not installed (scripts/setup.sh installs it): the report cannot be checked")
        pytest.skip("Chromium is not installed")
    out = subprocess.run([exe, "--headless", "--no-sandbox", "--disable-gpu", "--enable-logging=stderr", "--v=0",
                          "--user-data-dir=" + str(html_path.parent / "chromium-profile"),
                          "--dump-dom", html_path.resolve().as_uri()],
                         capture_output=True, text=True, timeout=120)
    assert "</html>" in out.stdout, out.stderr[-2000:]
    return [m.group(1) for m in re.finditer(r':CONSOLE[^\]]*\] "(.*?)", source:', out.stderr)]


def test_solve_writes_json_csv_and_report(tmp_path):
    r = run("solve", PROBLEMS / "line_ranges.toml", "--out", tmp_path, "--quiet")
    assert r.returncode == 0, r.stderr
    res = json.loads((tmp_path / "results.json").read_text())
    assert res["status"] == "solved" and len(res["hash"]) == 16
    x = res["variables"]["x"]["components"][0]
    assert len(x["gates"]) == len(res["times"]) and len(x["slices"]) == len(res["times"]) - 1
    table = np.genfromtxt(tmp_path / "x.csv", delimiter=",", names=True)
    assert table.dtype.names == ("t_lb", "t_ub", "x_lb", "x_ub")
    gates = table[table["t_lb"] == table["t_ub"]]
    assert np.all(gates["x_lb"] <= np.sin(gates["t_lb"]) + 1) and np.all(np.sin(gates["t_lb"]) + 1 <= gates["x_ub"])
    assert "201 of 201 truth time points inside" in (tmp_path / "report.html").read_text()
    assert res["rows_outside"] == {} and not list(tmp_path.glob("*.tube"))  # .tube files only on request


def test_save_tubes_for_show_and_load_tube(tmp_path):
    r = run("solve", PROBLEMS / "line_ranges.toml", "--out", tmp_path, "--save-tubes")
    assert r.returncode == 0 and "one CSV and one .tube file per tube" in r.stdout, r.stdout + r.stderr
    assert sorted(f.name for f in tmp_path.glob("*.tube")) == ["v.tube", "x.tube"]
    shown = run("show", tmp_path / "x.tube")
    assert shown.returncode == 0 and "Tube of 1 component(s)" in shown.stdout, shown.stderr
    x = sillage.load_tube(str(tmp_path / "x.tube"))
    gates = json.loads((tmp_path / "results.json").read_text())["variables"]["x"]["components"][0]["gates"]
    assert [[g.lb(), g.ub()] for g in (x.gate(k) for k in range(len(gates)))] == gates


def test_exit_codes():
    assert run("check", PROBLEMS / "causal_chain.toml").returncode == 0
    bad = run("check", PROBLEMS / "data" / "beacon_ranges.csv")
    assert bad.returncode == 2 and "beacon_ranges.csv:" in bad.stderr
    missing = run("solve", "/no/such.toml")
    assert missing.returncode == 2 and missing.stderr == "sillage: /no/such.toml: found no such file, expected a problem file (TOML)\n"
    typo = run("slove", PROBLEMS / "causal_chain.toml")
    assert typo.returncode == 2 and "found the command 'slove', expected solve, explain, check, show, plot, stream, replay, batch or sweep" in typo.stderr
    assert run("solve", PROBLEMS / "causal_chain.toml", "--delta", "-1").returncode == 2


# x = y and y = 0.99999 x from [0, 10^6]: a contraction that runs for millions of steps.
SLOW = ('[time]\ndomain = [0, 1]\ndelta = 0.5\n[network]\nratio = 0\n[var.x]\nkind = "interval"\n'
        'value = "[0, 1000000]"\n[var.y]\nkind = "interval"\nvalue = "[0, 1000000]"\n'
        '[[constraint]]\nkind = "expr"\nexpr = "x - y"\n[[constraint]]\nkind = "expr"\nexpr = "y - 0.99999*x"\n')


def test_budget_options_and_exit_status_3(tmp_path):
    slow = tmp_path / "slow.toml"
    slow.write_text(SLOW)
    stopped = run("solve", slow, "--max-runs", 1000, "--out", tmp_path / "out")
    assert stopped.returncode == 3, stopped.stderr
    assert stopped.stderr.startswith("sillage: stopped before the fixed point: ContractorNetwork::contract: budget "
                                      "exceeded: 1001 contractor calls > max_boxes = 1000")
    assert "--max-runs N / --max-seconds S" in stopped.stderr
    result = json.loads((tmp_path / "out" / "results.json").read_text())  # the enclosures so far, written
    assert result["status"] == "stopped" and "max_boxes = 1000" in result["why"]
    assert result["summary"]["status"] == "stopped" and "max_boxes = 1000" in result["summary"]["reason"]
    assert "Stopped before the fixed point" in (tmp_path / "out" / "report.html").read_text()
    stopped = run("solve", slow, "--max-runs", 0, "--max-seconds", 0.1, "--out", tmp_path / "out")
    assert stopped.returncode == 3 and "max_seconds" in stopped.stderr
    assert run("solve", slow, "--max-seconds", -1).returncode == 2
    # The summary counts the runs done before the stop, as the budget does.
    five = run("solve", slow, "--max-runs", 5, "--out", tmp_path / "out")
    assert five.returncode == 3 and "STOPPED with" in five.stdout and ", 5 contractor runs," in five.stdout
    # Numbers that would wrap around or truncate: refused, the option named.
    for bad in ["-1", "10^20", "100000000000000000000", "1e20", "2.5"]:
        refused = run("solve", slow, "--max-runs", bad)
        assert refused.returncode == 2 and "--max-runs" in refused.stderr, (bad, refused.stderr)
        assert "expected a number of contractor runs (0: no limit) from 0 to 1000000000000000" in refused.stderr


def test_outputs_beside_the_problem_never_overwrite_it(tmp_path):
    (tmp_path / "x.csv").write_text("t,x\n0,1\n1,2\n")
    problem = tmp_path / "p.toml"
    problem.write_text('[time]\ndomain = [0, 1]\ndelta = 0.5\n[data.logged]\nfile = "x.csv"\n'
                       '[var.x]\nkind = "tube"\n[[constraint]]\nkind = "expr"\nexpr = "x - 1"\n')
    refused = run("solve", problem, "--out", tmp_path)
    assert refused.returncode == 2 and "would overwrite the table 'logged'" in refused.stderr
    assert (tmp_path / "x.csv").read_text() == "t,x\n0,1\n1,2\n"
    assert not (tmp_path / "results.json").exists()


def test_options_that_do_not_apply_are_errors_of_the_option(tmp_path):
    # A table's time points take no delta: the option is named, not the file.
    (tmp_path / "stamps.csv").write_text("t\n0\n0.5\n1\n")
    points = tmp_path / "points.toml"
    points.write_text('[data.stamps]\nfile = "stamps.csv"\n[time]\npoints = { data = "stamps", column = "t" }\n'
                      '[var.x]\nkind = "tube"\nvalue = "[0, 1]"\n[var.v]\nkind = "tube"\nvalue = "[-1, 1]"\n'
                      '[[constraint]]\nkind = "deriv"\nx = "x"\nv = "v"\n')
    assert run("solve", points, "--out", tmp_path / "out", "--quiet").returncode == 0
    bad = run("solve", points, "--delta", "0.1")
    assert bad.returncode == 2
    assert bad.stderr.startswith("sillage: --delta: found 0.1, expected no delta: the time points of this problem are "
                                 f"the stamps of the table 'stamps' ([time] points at {points}:4:10)"), bad.stderr
    assert run("solve", points, "--delta", "auto").stderr.startswith("sillage: --delta: found auto, expected no delta")
    bad = run("solve", PROBLEMS / "causal_chain.toml", "--refine", "regions")
    assert bad.returncode == 2
    assert bad.stderr.startswith("sillage: --refine: found regions, expected it with an automatic delta"), bad.stderr
    assert run("solve", PROBLEMS / "line_ranges.toml", "--refine", "regions", "--delta", "auto", "--quiet",
               "--out", tmp_path / "regions").returncode == 0


def test_scheduling_option_and_file_key(tmp_path):
    """--scheduling priority (or [network] scheduling) in results.json and the report; a bad
    value of the key is an error at its place (exit 2)."""
    r = run("solve", PROBLEMS / "line_ranges.toml", "--out", tmp_path, "--quiet", "--scheduling", "priority")
    assert r.returncode == 0, r.stderr
    assert json.loads((tmp_path / "results.json").read_text())["scheduling"] == "priority"
    assert '<p id="scheduling">Scheduling: priority' in (tmp_path / "report.html").read_text()
    assert run("solve", PROBLEMS / "line_ranges.toml", "--scheduling", "lifo").returncode == 2
    text = (PROBLEMS / "line_ranges.toml").read_text()
    lines = text.count("\n")
    problem = PROBLEMS / "test_scheduling_key.toml"
    try:
        problem.write_text(text + '[network]\nscheduling = "lifo"\n')
        bad = run("check", problem)
        assert bad.returncode == 2
        assert f'test_scheduling_key.toml:{lines + 2}:14: found a string "lifo", expected "fifo" or "priority"' \
            in bad.stderr
        problem.write_text(text + '[network]\nscheduling = "priority"\n')
        assert "priority scheduling" in run("check", problem).stdout
    finally:
        problem.unlink(missing_ok=True)


def test_no_solution_exits_1_and_says_why(tmp_path):
    text = (PROBLEMS / "line_ranges.toml").read_text().replace('value = "[-10, 10]"', 'value = "[5, 10]"')
    problem = PROBLEMS / "test_no_solution.toml"
    try:
        problem.write_text(text)
        r = run("solve", problem, "--out", tmp_path)
        quiet = run("solve", problem, "--out", tmp_path / "quiet", "--quiet")
    finally:
        problem.unlink()
    assert r.returncode == 1
    assert "NO SOLUTION" in r.stdout and "constraint" in r.stdout
    report = (tmp_path / "report.html").read_text()
    assert "No solution" in report
    results = report[report.index('<table id="results">'):]
    results = results[:results.index("</table>")]
    assert "[" not in results.replace("<th>", "").split("</tr>", 1)[1]  # no value shown as if it held a solution
    assert results.count("∅") >= 2
    assert quiet.returncode == 1  # --quiet drops the summary, not the explanation
    assert "NO SOLUTION" in quiet.stdout and "constraint" in quiet.stdout and "wrote" not in quiet.stdout


def test_rows_outside_the_time_domain(tmp_path):
    # [0, 10] leaves 4 of the 9 ranges (t = 11.4 ... 17.1) outside: an error naming the file and row,
    # or, with outside = "skip", skipped and counted by check, in the report and in results.json.
    text = (PROBLEMS / "line_ranges.toml").read_text().replace("domain = [0, 20]", "domain = [0, 10]")
    text = text.replace("times = [0, 5, 10, 20]", "times = [0, 5, 10]")
    problem, skip = PROBLEMS / "test_rows_outside.toml", PROBLEMS / "test_rows_outside_skip.toml"
    try:
        problem.write_text(text)
        skip.write_text(text.replace('time = "t"\n', 'time = "t"\noutside = "skip"\n'))
        bad, checked = run("check", problem), run("check", skip)
        solved = run("solve", skip, "--out", tmp_path, "--quiet")
    finally:
        problem.unlink()
        skip.unlink()
    assert bad.returncode == 2
    assert ("test_rows_outside.toml:30:1: found row 5 of 'ranges' (" in bad.stderr and
            "beacon_ranges.csv:8) at t = 11.4, outside the time domain [0, 10]" in bad.stderr), bad.stderr
    assert checked.returncode == 0 and "4 row(s) of 'ranges' outside [t0, tf] skipped" in checked.stdout
    assert solved.returncode == 0, solved.stdout + solved.stderr
    assert list(json.loads((tmp_path / "results.json").read_text())["rows_outside"].values()) == [4]
    assert "<td>eval rows outside [t0, tf], skipped</td><td>4 (" in (tmp_path / "report.html").read_text()


def test_report_in_headless_chromium(tmp_path):
    assert run("solve", PROBLEMS / "dead_reckoning.toml", "--out", tmp_path, "--quiet").returncode == 0
    html = (tmp_path / "report.html").read_text()
    nb_svg = html.count("<svg")
    assert nb_svg >= 5
    probe = tmp_path / "probe.html"
    probe.write_text(html.replace("</body>", PROBE + "</body>"))
    lines = chromium_console(probe)
    sizes = [l for l in lines if l.startswith("SVG ")]
    assert [l for l in lines if not l.startswith("SVG ")] == []  # no error, no warning
    assert len(sizes) == nb_svg
    for l in sizes:
        w, h = map(float, l[4:].split("x"))
        assert w > 100 and h > 100, l


def test_browser_check_sees_console_errors(tmp_path):
    # The check itself can fail: an uncaught error in a page is seen.
    page = tmp_path / "broken.html"
    page.write_text("<!DOCTYPE html><html><body><script>no_such_function();</script></body></html>")
    lines = chromium_console(page)
    assert any("no_such_function" in l for l in lines), lines


def test_show_and_plot_a_tube_file(tmp_path):
    td = sillage.TDomain(0, 10, 0.5)
    x = sillage.Tube(td, "sin(t) + [-0.1, 0.1]")
    sillage.save_tube(x, str(tmp_path / "x.tube"))
    r = run("show", tmp_path / "x.tube")
    assert r.returncode == 0 and "Tube of 1 component(s), 20 slices over [0, 10]" in r.stdout
    r = run("plot", tmp_path / "x.tube", "--out", tmp_path / "x.svg")
    assert r.returncode == 0 and (tmp_path / "x.svg").read_text().count("<svg") == 1
    before = (tmp_path / "x.tube").read_bytes()
    over = run("plot", tmp_path / "x.tube", "--out", tmp_path / "x.tube")  # never overwrites its input
    assert over.returncode == 2 and "is the tube file read" in over.stderr
    assert (tmp_path / "x.tube").read_bytes() == before
    assert run("show", tmp_path / "missing.tube").returncode == 2
    bad = run("show", PROBLEMS / "causal_chain.toml")  # not a tube file: the message names it
    assert bad.returncode == 2
    assert f"load tube: '{PROBLEMS / 'causal_chain.toml'}': not a sillage tube file" in bad.stderr


def test_outputs_in_proportion(tmp_path):
    # 20 000 slices: written as 10 000 slice rows (hulls of two) unless --full-tubes.
    problem = tmp_path / "long.toml"
    problem.write_text('[time]\ndomain = [0, 20]\ndelta = 0.001\n[var.x]\nkind = "tube"\n'
                       'value = "sin(t) + [-0.1, 0.1]"\n[[constraint]]\nkind = "expr"\nexpr = "x - x"\n')
    assert run("solve", problem, "--out", tmp_path / "dec").returncode == 0
    result = json.loads((tmp_path / "dec" / "results.json").read_text())
    assert result["decimated"] == 2 and len(result["times"]) == 10001
    rows = np.genfromtxt(tmp_path / "dec" / "x.csv", delimiter=",", names=True)
    assert len(rows) == 10001 + 10000
    spans = rows["t_ub"] - rows["t_lb"]
    assert np.allclose(spans[spans > 0], 0.002)
    assert run("solve", problem, "--out", tmp_path / "full", "--full-tubes").returncode == 0
    full = json.loads((tmp_path / "full" / "results.json").read_text())
    assert full["decimated"] == 1 and len(full["times"]) == 20001

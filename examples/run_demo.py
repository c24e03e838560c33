#!/usr/bin/env python3
"""Runs every sillage example (C++ and Python), gathers their figures into
OUT/index.html and prints a summary table (example, result, check, time).

Each example takes `--out DIR`, writes its figures there and ends its output
with one line `RESULT {"name": ..., "result": ..., "check": true/false,
"figures": [[file, caption], ...]}`, and exits non-zero when its check fails.
An example without its data (the real data sets live in ../shared/data beside
the repository) reports "skipped: no data": it is marked skipped, not ok.
"""
import argparse
import html
import json
import os
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent

# (label, kind, program) in the order of the thesis.
EXAMPLES = [
    ("rump", "cpp", "example_rump"),
    ("rump", "py", "rump.py"),
    ("beacons_static", "cpp", "example_beacons_static"),
    ("beacons_static", "py", "beacons_static.py"),
    ("sivia_two_beacons", "cpp", "example_sivia_two_beacons"),
    ("sivia_two_beacons", "py", "sivia_two_beacons.py"),
    ("outcome_budget", "cpp", "example_outcome_budget"),
    ("outcome_budget", "py", "outcome_budget.py"),
    ("dead_reckoning", "cpp", "example_dead_reckoning"),
    ("dead_reckoning", "py", "dead_reckoning.py"),
    ("causal_chain", "cpp", "example_causal_chain"),
    ("causal_chain", "py", "causal_chain.py"),
    ("sin_ivp", "cpp", "example_sin_ivp"),
    ("sin_ivp", "py", "sin_ivp.py"),
    ("lissajous", "cpp", "example_lissajous"),
    ("lissajous", "py", "lissajous.py"),
    ("kidnapped_robot", "cpp", "example_kidnapped_robot"),
    ("kidnapped_robot", "py", "kidnapped_robot.py"),
    ("lowcost_beacons", "cpp", "example_lowcost_beacons"),
    ("lowcost_beacons", "py", "lowcost_beacons.py"),
    ("drifting_clock", "cpp", "example_drifting_clock"),
    ("drifting_clock", "py", "drifting_clock.py"),
    ("plaza1", "cpp", "example_plaza1"),
    ("plaza1", "py", "plaza1.py"),
    ("plaza1_online", "cpp", "example_plaza1_online"),
    ("plaza1_online", "py", "plaza1_online.py"),
    ("problem_stream", "py", "problem_stream.py"),
    ("loops_survey", "cpp", "example_loops_survey"),
    ("loops_plaza1", "cpp", "example_loops_plaza1"),
    ("loops_plaza1", "py", "loops_plaza1.py"),
    ("loops_utias", "cpp", "example_loops_utias"),
    ("loops_lissajous", "py", "loops_lissajous.py"),
    ("outliers_ranges", "cpp", "example_outliers_ranges"),
    ("outliers_ranges", "py", "outliers_ranges.py"),
    ("bathymetry_mission", "cpp", "example_bathymetry_mission"),
    ("bathymetry_mission", "py", "bathymetry_mission.py"),
    ("problem_file", "py", "problem_file.py"),
    ("explain_empty", "py", "explain_empty.py"),
    ("problem_refinement", "py", "problem_refinement.py"),
    ("sweep_line_ranges", "py", "sweep_line_ranges.py"),
    ("temporal_slam_small", "py", "temporal_slam_small.py"),
    ("bathymetry_slam", "cpp", "example_bathymetry_slam"),
    ("bathymetry_slam", "py", "bathymetry_slam.py"),
    ("plaza1_slam", "cpp", "example_plaza1_slam"),
    ("plaza1_slam", "py", "plaza1_slam.py"),
]


def run_one(kind, program, build, out):
    if kind == "cpp":
        cmd = [str(build / "examples" / program), "--out", str(out)]
    else:
        cmd = [sys.executable, str(HERE / "python" / program), "--out", str(out)]
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True)
    elapsed = time.perf_counter() - t0
    result = None
    for line in proc.stdout.splitlines():
        if line.startswith("RESULT "):
            result = json.loads(line[len("RESULT "):])
    if result is None:
        result = {"name": program, "result": f"FAILED (exit {proc.returncode})", "check": False, "figures": []}
    if proc.returncode != 0:  # a failed check (with its RESULT line) or a crash
        result["check"] = False
        sys.stderr.write(proc.stdout + proc.stderr)
    result["status"] = status_of(result)
    result["time"] = elapsed
    result["kind"] = kind
    result["log"] = proc.stdout
    return result


def status_of(result):
    """ok, FAILED or skipped (an example without its data proves nothing: never ok)."""
    if not result["check"]:
        return "FAILED"
    if result.get("skipped") or str(result["result"]).startswith("skipped"):
        return "skipped"
    return "ok"


def write_index(results, out):
    parts = ["<!doctype html><html><head><meta charset='utf-8'><title>sillage demo</title>",
             "<style>body{font-family:sans-serif;max-width:1100px;margin:auto}"
             "figure{display:inline-block;margin:8px;vertical-align:top}"
             "img{max-width:520px;border:1px solid #ccc}td,th{padding:2px 10px}"
             "pre{background:#f4f4f4;padding:6px;font-size:12px}</style></head><body>",
             "<h1>sillage demo</h1><table><tr><th>example</th><th>lang</th><th>result</th>"
             "<th>check</th><th>time (s)</th></tr>"]
    for r in results:
        parts.append(f"<tr><td>{html.escape(r['name'])}</td><td>{r['kind']}</td>"
                     f"<td>{html.escape(str(r['result']))}</td><td>{r['status']}</td>"
                     f"<td>{r['time']:.3f}</td></tr>")
    parts.append("</table>")
    for r in results:
        parts.append(f"<h2>{html.escape(r['name'])} ({r['kind']})</h2><pre>{html.escape(r['log'])}</pre>")
        for fig, caption in r.get("figures", []):
            parts.append(f"<figure><img src='{html.escape(fig)}'><figcaption>{html.escape(caption)}"
                         "</figcaption></figure>")
    parts.append("</body></html>")
    (out / "index.html").write_text("\n".join(parts))


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="out")
    args = ap.parse_args()
    build, out = Path(args.build).resolve(), Path(args.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    env_path = str(build / "python")
    os.environ["PYTHONPATH"] = env_path + os.pathsep + os.environ.get("PYTHONPATH", "")
    os.environ.setdefault("MPLBACKEND", "Agg")

    results = [run_one(kind, prog, build, out) for _, kind, prog in EXAMPLES]
    write_index(results, out)

    w = max(len(r["name"]) for r in results)
    print(f"\n{'example':<{w}}  lang  {'check':<7} {'time':>8}  result")
    print("-" * (w + 60))
    for r in results:
        print(f"{r['name']:<{w}}  {r['kind']:<4}  {r['status']:<7} {r['time']:>7.3f}s  {r['result']}")
    counts = {s: sum(r["status"] == s for r in results) for s in ("ok", "skipped", "FAILED")}
    print(f"\n{counts['ok']} ok, {counts['skipped']} skipped (no data), {counts['FAILED']} failed")
    print(f"figures: {out / 'index.html'}")
    return 0 if counts["FAILED"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())

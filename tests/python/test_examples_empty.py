"""An example whose contractor network comes out empty says so and stops: it
prints `EMPTY:` with the explanation (which contractor emptied which named
domain), gives no truth or box figures computed from the empty domains, and
exits 1; in C++ (example_check.h: empty_exit, run from the build tree) as in
Python (example_args.empty_exit). Emptiness is forced as in
test_examples_exit_status.py: SILLAGE_EXAMPLE_TIGHTEN=0.001 makes the stated
bounds too tight (example_bound.h, example_args.bound)."""
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

import sillage

ROOT = Path(__file__).resolve().parents[2]
BUILD = Path(sillage.__file__).resolve().parents[2]  # <build>/python/sillage/__init__.py

# example: (the explanation, in both languages; patterns of what only a result on a non-empty network prints)
CASES = {
    "beacons_static": ("EMPTY: CtcFunction(sqrt((x1 - 2.5)^2 + (x2 - (-0.5))^2) - rho) emptied box 'x' at component 0",
                       ["final box", "contains (0, 0)", "iterations, box"]),
    "sin_ivp": ("delta = 0.1 (4.23): EMPTY: tube 'b' was empty on input at gate 0 (t = 0)",
                ["contains it", "truth inside", "Fig. 4.7", r"CtcIvp \("]),
    "drifting_clock": ("EMPTY: tube 'h' was empty on input at gate 0 (t = 0)",
                       ["fixed point verified", r"contracted \[t_i\]", "mean width", "truth h"]),
    "lowcost_beacons": ("EMPTY: CtcDeriv emptied tube 'x[0]' at gate 416 (t = 20.79",
                        ["fixed point verified", r"contracted \[t_i\]", "truth times", r"x\(0\) in"]),
    # The run from x0 alone is not empty and prints its results; the run with the final box is.
    "causal_chain": ("CtcIvp with the final box: EMPTY: CtcIvp: no trajectory from x0 with the inputs reaches the final "
                     "box", [r"with the final box: \d", r"\[ ?empty ?\]"]),
}


def command(language, name):
    if language == "cpp":
        exe = BUILD / "examples" / f"example_{name}"
        if not exe.exists():
            pytest.skip(f"{exe} is not built")
        return [str(exe)]
    return [sys.executable, str(ROOT / "examples" / "python" / f"{name}.py")]


@pytest.mark.parametrize("language", ["cpp", "python"])
@pytest.mark.parametrize("name", sorted(CASES))
def test_empty_network_says_why_and_exits_1(name, language, tmp_path):
    env = dict(os.environ, MPLBACKEND="Agg", SILLAGE_EXAMPLE_TIGHTEN="0.001")
    proc = subprocess.run([*command(language, name), "--out", str(tmp_path)], capture_output=True, text=True,
                          env=env, timeout=300)
    explanation, results = CASES[name]
    assert proc.returncode == 1, proc.stdout[-2000:]
    assert "EMPTY: " in proc.stdout and explanation in proc.stdout, proc.stdout[-2000:]
    assert '"check": false' in proc.stdout
    for pattern in results:
        assert not re.search(pattern, proc.stdout), pattern
    assert "%" not in proc.stdout  # no truth percentage


@pytest.mark.parametrize("language", ["cpp", "python"])
@pytest.mark.parametrize("value", ["abc", "-1", "nan", "0.5x"])
def test_a_bad_tighten_factor_is_bad_input(value, language, tmp_path):
    env = dict(os.environ, MPLBACKEND="Agg", SILLAGE_EXAMPLE_TIGHTEN=value)
    proc = subprocess.run([*command(language, "beacons_static"), "--out", str(tmp_path)], capture_output=True,
                          text=True, env=env, timeout=300)
    assert proc.returncode == 2, proc.stdout[-2000:] + proc.stderr[-2000:]
    assert f"SILLAGE_EXAMPLE_TIGHTEN: expected a number >= 0, got '{value}'" in proc.stderr

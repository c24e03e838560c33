"""The examples' command lines: an unknown option, a missing value or text
where a number is expected prints the problem and a usage line and exits with
status 2, in the C++ examples (example_args.h, run from the build tree) and in
their Python twins (argparse)."""
import os
import subprocess
import sys
from pathlib import Path

import pytest

import sillage

ROOT = Path(__file__).resolve().parents[2]
BUILD = Path(sillage.__file__).resolve().parents[2]  # <build>/python/sillage/__init__.py
BAD = [(["--dt", "abc"], "option --dt expects a number, got 'abc'"),
       (["--dt"], "option --dt needs a value"),
       (["--dt", "--ratio", "1"], "option --dt needs a value"),
       (["--bogus", "1"], "unknown option '--bogus'"),
       (["--dt", "0.5x"], "option --dt expects a number, got '0.5x'")]


@pytest.mark.parametrize("args, message", BAD)
def test_cpp_example_bad_options(args, message, tmp_path):
    exe = BUILD / "examples" / "example_drifting_clock"
    if not exe.exists():
        pytest.skip(f"{exe} is not built")
    r = subprocess.run([str(exe), *args], capture_output=True, text=True, cwd=tmp_path, timeout=60)
    assert r.returncode == 2
    assert r.stderr == f"drifting_clock: {message}\nusage: drifting_clock [--out DIR] [--dt X] [--ratio X]\n"
    assert r.stdout == ""


def test_cpp_example_without_options_rejects_them(tmp_path):
    exe = BUILD / "examples" / "example_sivia_two_beacons"
    if not exe.exists():
        pytest.skip(f"{exe} is not built")
    r = subprocess.run([str(exe), "--dt", "1"], capture_output=True, text=True, cwd=tmp_path, timeout=60)
    assert (r.returncode, r.stderr) == (2, "sivia_two_beacons: unknown option '--dt'\n"
                                            "usage: sivia_two_beacons [--out DIR]\n")


@pytest.mark.parametrize("args, _", BAD)
def test_python_example_bad_options(args, _, tmp_path):
    env = dict(os.environ, PYTHONPATH=str(BUILD / "python"))
    r = subprocess.run([sys.executable, str(ROOT / "examples" / "python" / "drifting_clock.py"), *args],
                       capture_output=True, text=True, cwd=tmp_path, timeout=60, env=env)
    assert r.returncode == 2
    assert r.stderr.startswith("usage: drifting_clock.py [-h] [--out OUT] [--dt DT] [--ratio RATIO]\n")


# An error bound is a magnitude: a negative one is refused with status 2 before any work, in the
# three plaza1 programs of each language (examples/cpp/plaza1_bounds.h, examples/python/plaza1_bounds.py).
NEGATIVE = [("--turn-max", "turn rate"), ("--gyro-in-run-drift", "gyro in-run drift")]


@pytest.mark.parametrize("option, name", NEGATIVE)
@pytest.mark.parametrize("program", ["plaza1", "loops_plaza1", "plaza1_slam"])
def test_cpp_plaza1_negative_bound(program, option, name, tmp_path):
    exe = BUILD / "examples" / f"example_{program}"
    if not exe.exists():
        pytest.skip(f"{exe} is not built")
    r = subprocess.run([str(exe), option, "-1"], capture_output=True, text=True, cwd=tmp_path, timeout=60)
    assert r.returncode == 2
    assert r.stderr.startswith(f"{program}: option {option} is an error bound ({name}), expected >= 0, got -1")
    assert r.stdout == ""


@pytest.mark.parametrize("option, _", NEGATIVE)
@pytest.mark.parametrize("program", ["plaza1", "loops_plaza1", "plaza1_slam"])
def test_python_plaza1_negative_bound(program, option, _, tmp_path):
    env = dict(os.environ, PYTHONPATH=str(BUILD / "python"))
    r = subprocess.run([sys.executable, str(ROOT / "examples" / "python" / f"{program}.py"), option, "-1"],
                       capture_output=True, text=True, cwd=tmp_path, timeout=60, env=env)
    assert r.returncode == 2
    assert f"argument {option}: an error bound must be >= 0, got -1" in r.stderr

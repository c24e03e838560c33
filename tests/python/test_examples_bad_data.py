"""The examples on real data with bad data: a broken copy of a data set in a temp dir (a renamed
column, an empty file, a cell that is not a number, an unknown beacon) or a wrong --data folder
is bad input: the message (file, line, column; or what is missing) on stderr and exit status 2,
in the C++ examples (example_args.h: example::run, example_data.h) and in their Python twins
(example_args.run, out_dir_and_data), never an abort or a traceback. Without --data, an absent
default folder is reported as skipped (exit 0), which the demo relies on. An empty network is not
bad input: EMPTY, exit 1."""
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import sillage

ROOT = Path(__file__).resolve().parents[2]
BUILD = Path(sillage.__file__).resolve().parents[2]  # <build>/python/sillage/__init__.py
DATA = ROOT.parent / "shared" / "data"
PLAZA1, UTIAS = DATA / "plaza1", DATA / "utias-mrclam7"
PLAZA1_PROGRAMS = ["plaza1", "loops_plaza1", "plaza1_slam", "plaza1_online"]

# ranges.csv broken in four ways: (its text from the real one, the message expected).
BROKEN_RANGES = {
    "renamed column": (lambda t: t.replace("beacon_id", "beacon", 1), "ranges.csv: no column 'beacon_id'"),
    "empty file": (lambda t: "", "ranges.csv: no header line"),
    "not a number": (lambda t: t.replace("\n", "\nabc,5,60.0\n", 1), "ranges.csv:2: column 't_s': 'abc' is not a finite number"),
    "unknown beacon": (lambda t: t.replace("\n", "\n3858.0620,9,65.4660\n", 1), "ranges.csv:2: beacon 9 is not in"),
}


def broken_copy(src, tmp_path, name, text_of):
    """A copy of the data set src in tmp_path (links to its files) with the file `name` rewritten."""
    dst = tmp_path / "data"
    shutil.copytree(src, dst, copy_function=os.symlink)
    target = dst / name
    text = target.read_text()
    target.unlink()
    target.write_text(text_of(text))
    return dst


def run_cpp(program, tmp_path, *args):
    exe = BUILD / "examples" / f"example_{program}"
    if not exe.exists():
        pytest.skip(f"{exe} is not built")
    return subprocess.run([str(exe), "--out", str(tmp_path / "out"), *args], capture_output=True, text=True,
                          timeout=300)


def run_python(program, tmp_path, *args, examples=ROOT / "examples" / "python"):
    env = dict(os.environ, PYTHONPATH=str(BUILD / "python"), MPLBACKEND="Agg")
    return subprocess.run([sys.executable, str(examples / f"{program}.py"), "--out", str(tmp_path / "out"), *args],
                          capture_output=True, text=True, timeout=300, env=env)


def assert_bad_input(r, program, message):
    assert r.returncode == 2, r.stdout[-2000:] + r.stderr[-2000:]
    assert message in r.stderr and r.stderr.startswith(program), r.stderr
    assert "Traceback" not in r.stderr and "terminate called" not in r.stderr


needs_plaza1 = pytest.mark.skipif(not (PLAZA1 / "ranges.csv").exists(), reason="no plaza1 data")


@needs_plaza1
@pytest.mark.parametrize("case", sorted(BROKEN_RANGES))
@pytest.mark.parametrize("program", PLAZA1_PROGRAMS)
@pytest.mark.parametrize("run", [run_cpp, run_python], ids=["cpp", "python"])
def test_broken_ranges_exit_2(run, program, case, tmp_path):
    text_of, message = BROKEN_RANGES[case]
    data = broken_copy(PLAZA1, tmp_path, "ranges.csv", text_of)
    assert_bad_input(run(program, tmp_path, "--data", str(data)), program, message)


@needs_plaza1
@pytest.mark.parametrize("run", [run_cpp, run_python], ids=["cpp", "python"])
def test_odometry_not_matching_the_ground_truth_exit_2(run, tmp_path):
    data = broken_copy(PLAZA1, tmp_path, "odometry.csv", lambda t: t.rsplit("\n", 2)[0] + "\n")  # one row less
    assert_bad_input(run("plaza1", tmp_path, "--data", str(data)), "plaza1", "rows, expected one per step of")


@pytest.mark.skipif(not (UTIAS / "robot1" / "odometry.csv").exists(), reason="no utias data")
def test_cpp_loops_utias_broken_odometry_exit_2(tmp_path):
    data = broken_copy(UTIAS, tmp_path, "robot1/odometry.csv", lambda t: t.replace("v_mps", "speed", 1))
    r = run_cpp("loops_utias", tmp_path, "--data", str(data), "--robot", "1")
    assert_bad_input(r, "loops_utias", "robot1/odometry.csv: no column 'v_mps'")


# A --data folder that is missing or holds another data set: exit 2 saying what is missing.
@pytest.mark.parametrize("program", PLAZA1_PROGRAMS)
@pytest.mark.parametrize("run", [run_cpp, run_python], ids=["cpp", "python"])
def test_wrong_data_folder_exit_2(run, program, tmp_path):
    assert_bad_input(run(program, tmp_path, "--data", str(tmp_path / "nowhere")), program,
                     f"--data {tmp_path / 'nowhere'}: no such folder (expected the plaza1 data set)")
    (tmp_path / "other").mkdir()
    (tmp_path / "other" / "odometry.csv").write_text("t_s\n")
    assert_bad_input(run(program, tmp_path, "--data", str(tmp_path / "other")), program,
                     "not the plaza1 data set (missing ground_truth.csv, ranges.csv, beacons.csv)")


def test_cpp_loops_utias_wrong_data_folder_exit_2(tmp_path):
    r = run_cpp("loops_utias", tmp_path, "--data", str(tmp_path), "--robot", "2")
    assert_bad_input(r, "loops_utias", "not the utias-mrclam7 data set (missing robot2/ground_truth.csv, "
                                       "robot2/odometry.csv)")


def test_python_default_data_folder_absent_is_skipped(tmp_path):
    # The examples copied where ../shared/data does not exist beside the repository.
    examples = tmp_path / "repo" / "examples" / "python"
    shutil.copytree(ROOT / "examples" / "python", examples)
    r = run_python("plaza1", tmp_path, examples=examples)
    assert r.returncode == 0, r.stderr
    assert "skipped: no data" in r.stdout and '"skipped": true' in r.stdout


# Ranges with no error: the network is empty. An answer, not bad input: EMPTY with the contractor
# and the domain it emptied (named as in the other language), no truth or box figures, exit 1.
@needs_plaza1
@pytest.mark.parametrize("run", [run_cpp, run_python], ids=["cpp", "python"])
def test_empty_network_says_empty_and_exits_1(run, tmp_path):
    r = run("plaza1", tmp_path, "--range-short", "0", "--range-long", "0", "--q-ranges", "-1")
    assert r.returncode == 1, r.stdout[-2000:] + r.stderr[-2000:]
    empty = [l for l in r.stdout.splitlines() if l.startswith("  odometry + ranges: EMPTY: CtcEvalList (")]
    assert len(empty) == 1 and "(range 0: beacon 5 seen at t = 3858.06) emptied tube 'p[0]'" in empty[0], r.stdout
    assert "- -" not in r.stdout
    after = r.stdout[r.stdout.index(empty[0]):]
    assert "truth inside" not in after.split("RESULT")[0]
    result = [l for l in r.stdout.splitlines() if l.startswith("RESULT ")][0]
    assert "odometry + ranges: EMPTY: " in result and '"check": false' in result

"""The bound audit of the real-data examples (examples/python/bound_audit.py and the plaza1 table,
examples/python/plaza1_bounds.py; the C++ twins are examples/cpp/bound_audit.h, plaza1_bounds.h):
it reports how much of each stated bound the truth used, and never changes a bound. The bounds
are options of the examples; a bound the truth violates makes the example fail."""
import argparse
import math
import subprocess
import sys
from pathlib import Path

import pytest

import sillage

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples" / "python"
DATA = ROOT.parent / "shared" / "data" / "plaza1"
BUILD = Path(sillage.__file__).resolve().parents[2]
sys.path.insert(0, str(EXAMPLES))
from bound_audit import AuditLine, print_audit  # noqa: E402
import plaza1_bounds  # noqa: E402

needs_data = pytest.mark.skipif(not (DATA / "odometry.csv").exists(), reason="no plaza1 data")


def test_audit_line_text_and_percent(capsys):
    line = AuditLine("turn rate", "rad/s", 4.0, 0.62, "true heading change per period")
    assert line.percent() == pytest.approx(15.5)
    assert line.text() == "turn rate: max 0.62 rad/s of 4 allowed (16 %; true heading change per period)"
    over = AuditLine("range long error", "m", 7.0, 7.5, "measured - true")
    assert over.text().endswith("<-- VIOLATED")
    unknown = AuditLine("time-stamp error", "s", 0.2, math.nan, "no independent clock")
    assert "not measurable" in unknown.text()
    assert print_audit("t", [line, unknown]) and not print_audit("t", [line, over])
    assert "bound audit (t)" in capsys.readouterr().out


def test_table_has_one_option_per_bound_and_matches_cpp():
    ap = argparse.ArgumentParser()
    plaza1_bounds.add_options(ap)
    args = ap.parse_args(["--gyro-turn-on-bias", "0.01", "--gyro-in-run-drift", "0.002", "--start-x", "3"])
    d = dict(x=[1.0], y=[2.0], heading=[0.5])
    b = plaza1_bounds.bounds(args, d)
    assert b.gyro_bias == 0.01 and b.gyro_drift == 0.002 and b.start_x == 3 and b.start_y == 2.0 and b.start_heading == 0.5
    assert b.turn_max == 4.0 and b.range_long == 10.0
    cpp = (ROOT / "examples" / "cpp" / "plaza1_bounds.h").read_text()
    for option, attr, name, unit, value, source in plaza1_bounds.TABLE:
        assert f'{{"{option}", "{name}", "{unit}", &Bounds::' in cpp, option


@needs_data
def test_plaza1_audit_uses_part_of_every_bound():
    sys.path.insert(0, str(EXAMPLES))
    import plaza1
    d = plaza1.load(DATA)
    b = plaza1_bounds.bounds(None, d)
    before = dict(vars(b))
    lines = {l.name: l for l in plaza1_bounds.audit(d, b)}
    assert vars(b) == before  # the audit changes no bound
    assert lines["turn rate"].used == pytest.approx(0.711, abs=1e-3)
    assert lines["range long error"].used == pytest.approx(6.567, abs=1e-3)
    assert lines["range short error"].used == pytest.approx(0.631, abs=1e-3)
    # stated from the sensor classes: none is used at more than 75 % on this file
    for l in lines.values():
        assert math.isnan(l.used) or l.percent() < 75, l.text()


@needs_data
@pytest.mark.parametrize("lang", ["python", "cpp"])
def test_a_violated_bound_fails_the_example(lang, tmp_path):
    """--gyro-turn-on-bias 1e-5 is below the drift of this file: the audit says so and the truth is lost."""
    if lang == "python":
        cmd = [sys.executable, str(EXAMPLES / "plaza1.py")]
    else:
        exe = BUILD / "examples" / "example_plaza1"
        if not exe.exists():
            pytest.skip(f"{exe} is not built")
        cmd = [str(exe)]
    r = subprocess.run(cmd + ["--out", str(tmp_path), "--gyro-turn-on-bias", "1e-5"], capture_output=True, text=True,
                       timeout=600)
    assert r.returncode == 1
    assert "gyro turn-on bias: max 0.0003445 rad/s of 1e-05 allowed" in r.stdout and "VIOLATED" in r.stdout

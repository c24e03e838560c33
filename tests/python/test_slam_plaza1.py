"""plaza1 as a range-only temporal SLAM without the beacon positions (examples/*/plaza1_slam.*).

The observation tubes built from the ranges hold the true ranges (the surveyed beacons are used
here only to check, never by the SLAM), and the example keeps the ground truth at every gate of
every iteration and exits 0. Skipped without the data (../shared/data/plaza1)."""
import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import sillage

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples" / "python"
DATA = ROOT.parent / "shared" / "data" / "plaza1"

pytestmark = pytest.mark.skipif(not (DATA / "odometry.csv").exists(), reason="no plaza1 data")


def load():
    sys.path.insert(0, str(EXAMPLES))
    import plaza1  # noqa: E402  (the example's loader)
    return plaza1.load(DATA)


def test_range_tubes_hold_the_true_ranges():
    d = load()
    td = sillage.TDomain(list(d["t"]))
    ids = sorted(d["beacons"])
    rb = sillage.RangeBounds(1.5, 10.0, 0.2, 6.0)  # the stated bounds of plaza1_bounds.py
    z = sillage.range_observation_tubes(td, list(d["rt"]), [int(i) for i in d["rid"]], list(d["r"]), ids, rb)
    assert z.size() == 4
    x, y = np.asarray(d["x"]), np.asarray(d["y"])
    for i, bid in enumerate(ids):
        bx, by = d["beacons"][bid]
        true_range = np.hypot(x - bx, y - by)
        g = z[i].gates_array()
        assert np.all((g[:, 0] <= true_range) & (true_range <= g[:, 1])), bid
        assert np.all(np.isfinite(g))  # bounded: every gate lies between two measurements or is clipped by one


def test_the_example_keeps_the_truth():
    env = dict(os.environ, MPLBACKEND="Agg")
    env.pop("SILLAGE_EXAMPLE_TIGHTEN", None)
    proc = subprocess.run([sys.executable, str(EXAMPLES / "plaza1_slam.py"), "--out", "/tmp/plaza1_slam_test",
                           "--eps", "10"], capture_output=True, text=True, env=env, timeout=600)
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr[-2000:]
    rows = [line for line in proc.stdout.splitlines() if line.startswith("| ") and "fast" in line or
            line.startswith("| ") and "accurate" in line]
    assert rows and all(line.rstrip(" |").endswith("9658 / 9658") for line in rows)
    result = json.loads(next(line for line in proc.stdout.splitlines() if line.startswith("RESULT "))[7:])
    assert result["check"] and not math.isnan(float(result["result"].split("mean box ")[1].split(" m")[0]))

"""The plaza1 example on the real data (skipped without ../shared/data/plaza1):
with the stated bounds every ground-truth sample is inside the position tube,
with and without the ranges, and the ranges make the tube much thinner."""
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT.parent / "shared" / "data" / "plaza1"
sys.path.insert(0, str(ROOT / "examples" / "python"))
plaza1 = pytest.importorskip("plaza1")


@pytest.mark.skipif(not (DATA / "odometry.csv").exists(), reason="no plaza1 data")
def test_truth_inside_and_ranges_help():
    d = plaza1.load(DATA)
    n = len(d["t"])
    _, stats0, _, inside0, mean0, _, _ = plaza1.solve(d, False)
    _, stats1, _, inside1, mean1, max1, nr = plaza1.solve(d, True)
    assert not stats0.empty and not stats1.empty
    assert inside0 == n and inside1 == n
    assert nr == 3529
    assert mean1 < 20 and max1 < 100 and mean1 < mean0 / 10

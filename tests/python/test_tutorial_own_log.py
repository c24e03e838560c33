"""docs/tutorial_own_log.md: the figures it quotes for examples/problems/tutorial_mrclam_ranges.toml
(UTIAS MRCLAM robot 1, ranges only), read off sillage.solve, var_sizes and audit_problem."""
from pathlib import Path

import pytest

import sillage

ROOT = Path(__file__).resolve().parents[2]
PROBLEM = ROOT / "examples" / "problems" / "tutorial_mrclam_ranges.toml"
DATA = ROOT.parent / "shared" / "data" / "utias-mrclam7" / "robot1" / "measurements.csv"


@pytest.mark.skipif(not DATA.exists(), reason="no MRCLAM data")
def test_the_tutorials_figures():
    p = sillage.load_problem(str(PROBLEM))
    r = sillage.solve_problem(p)
    truth = sillage.check_truth(p, r)
    assert (truth.inside, truth.samples) == (57731, 57731)
    pos = {s.name: s for s in sillage.var_sizes(p, r)}["p"]
    assert pos.unit == "m" and pos.over_time.samples == 8931
    assert round(pos.over_time.mean, 2) == 8.62 and round(pos.at_truth.mean, 2) == 8.66 and pos.over_time.max == 16
    audit = {line.name: line for line in sillage.audit_problem(p)}
    ranges = [line for name, line in audit.items() if "(eval)" in name]
    assert len(ranges) == 15 and sum(int(line.how.split(" rows")[0].split()[-1]) for line in ranges) == 2578
    violated = [name for name, line in audit.items() if line.percent() > 100]
    assert violated == ["constraint 10 (eval) on 'ranges' where subject_id = 13"]
    assert "worst ranges line 1839" in audit[violated[0]].how
    assert round(min(line.percent() for line in ranges)) == 45 and round(max(l.percent() for l in ranges if l.percent() <= 100)) == 96

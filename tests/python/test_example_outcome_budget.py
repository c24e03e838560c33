"""The outcome example (examples/*/outcome_budget): SIVIA stopped by its budget keeps a
paving that still encloses the full one's solutions, and contract_run() reports each round
to the progress hook; the Python twin draws both pavings (matplotlib), the C++ one (when
built) writes SVG figures."""
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import sillage

ROOT = Path(__file__).resolve().parents[2]
BUILD = Path(sillage.__file__).resolve().parents[2]  # <build>/python/sillage/__init__.py


def result_of(stdout):
    return json.loads(next(line for line in stdout.splitlines() if line.startswith("RESULT "))[7:])


def check_output(r, figures):
    assert r.returncode == 0, r.stdout[-2000:] + r.stderr[-2000:]
    assert "full    Converged" in r.stdout.replace("converged", "Converged")
    assert "sivia: budget exceeded: 401 boxes > max_boxes = 400" in r.stdout
    assert "ContractorNetwork::contract round 1: 2 contractor calls" in r.stdout
    assert "round 2:" in r.stdout and "budget exceeded: 13 contractor calls > max_boxes = 12" in r.stdout
    result = result_of(r.stdout)
    assert result["check"] and "network stopped after" in result["result"].lower()
    for f in figures:
        assert f.exists() and f.stat().st_size > 1000


pytest.importorskip("matplotlib")


def test_python_example(tmp_path):
    env = dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=str(BUILD / "python"))
    r = subprocess.run([sys.executable, str(ROOT / "examples" / "python" / "outcome_budget.py"), "--out",
                        str(tmp_path)], capture_output=True, text=True, env=env, timeout=300)
    check_output(r, [tmp_path / "outcome_budget_py.png"])


def test_cpp_example(tmp_path):
    exe = BUILD / "examples" / "example_outcome_budget"
    if not exe.exists():
        pytest.skip(f"{exe} is not built")
    r = subprocess.run([str(exe), "--out", str(tmp_path)], capture_output=True, text=True, timeout=300)
    check_output(r, [tmp_path / "outcome_budget_full.svg", tmp_path / "outcome_budget_stopped.svg"])

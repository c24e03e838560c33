"""The maps of the C++ loops examples on real data (skipped without the data or
the built examples) count their proven loops in the title: a run with none
says "no proven loop", never "the proven loops"."""
import json
import re
import subprocess
from pathlib import Path

import pytest
import sillage

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT.parent / "shared" / "data"
EXAMPLES = Path(sillage.__file__).resolve().parents[2] / "examples"


def run(program, data, tmp_path, *args):
    exe = EXAMPLES / f"example_{program}"
    if not exe.exists():
        pytest.skip(f"{exe} is not built")
    if not (DATA / data).is_dir():
        pytest.skip(f"no {data} data")
    proc = subprocess.run([str(exe), "--out", str(tmp_path), *args], capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stdout[-2000:]
    return json.loads(next(line for line in proc.stdout.splitlines() if line.startswith("RESULT "))[7:])


def check_titles(result, tmp_path):
    """Each map's caption and SVG title agree with the proofs counted in the result, in order."""
    proofs = [int(n) for n in re.findall(r"(\d+) proofs T", result["result"])]
    maps = [(f, c) for f, c in result["figures"] if f.endswith("_map.svg")]
    assert len(maps) == len(proofs) > 0
    for (name, caption), n in zip(maps, proofs):
        svg = (tmp_path / name).read_text()
        title = " ".join(re.findall(r'class="title">([^<]*)<', svg))
        for text in (caption, title):
            if n == 0:
                assert "no proven loop" in text and "of the" not in text, text
            else:
                assert f"of the {n} proven loop" in text, text
    return proofs


def test_utias_map_title_says_no_proven_loop(tmp_path):
    proofs = check_titles(run("loops_utias", "utias-mrclam7", tmp_path, "--robot", "1"), tmp_path)
    assert proofs == [0]  # robot 1 proves no loop with the stated bounds


def test_plaza1_map_titles_count_the_proofs(tmp_path):
    proofs = check_titles(run("loops_plaza1", "plaza1", tmp_path), tmp_path)
    assert 0 in proofs and any(n > 0 for n in proofs)

"""sillage.set_problem_key (a key of a problem file set to another value, the rest as written),
sillage.parse_problem and Problem.data_files: what a sweep and a remote task are built on."""
import os
from pathlib import Path

import pytest

import sillage

PROBLEMS = Path(__file__).resolve().parents[2] / "examples" / "problems"
LINE = PROBLEMS / "line_ranges.toml"


def text():
    return LINE.read_text()


def test_a_value_is_replaced_and_nothing_else():
    new = sillage.set_problem_key(text(), str(LINE), "constraint[1].time_error", "0.02")
    old_lines, new_lines = text().splitlines(), new.splitlines()
    changed = [i for i, (a, b) in enumerate(zip(old_lines, new_lines)) if a != b]
    assert len(old_lines) == len(new_lines) and len(changed) == 1
    assert new_lines[changed[0]] == "time_error = 0.02"


def test_inline_tables_strings_and_arrays():
    t = sillage.set_problem_key(text(), str(LINE), "constraint[1].errors.r", "0.5")
    assert "errors = { r = 0.5 }" in t
    t = sillage.set_problem_key(t, str(LINE), "var.v.value", '"cos(t) + [-0.1, 0.1]"')
    assert 'value = "cos(t) + [-0.1, 0.1]"' in t
    t = sillage.set_problem_key(t, str(LINE), "output.times", "[0, 20]")
    assert "times = [0, 20]" in t
    assert sillage.parse_problem(t, str(LINE)).nb_constraints == 2


@pytest.mark.parametrize("key, value, message", [
    ("constraint[1].time_eror", "0.1", r"no 'time_eror' in constraint\[1\] \(its keys: .*time_error"),
    ("constraint[5].time_error", "0.1", r"has 2 element\(s\)"),
    ("constraint[1].time_error", "[-1, 1", r"one TOML value"),
    ("constraint[1].time_error", "0.1\nq = 2", r"one TOML value"),
    ("var.x", "1", r"a whole table"),
    ("a..b", "1", r"the key \"a..b\""),
])
def test_unknown_keys_and_bad_values_say_what_is_there(key, value, message):
    with pytest.raises(sillage.Error, match=message):
        sillage.set_problem_key(text(), str(LINE), key, value)


def test_parse_problem_resolves_data_against_its_path():
    p = sillage.parse_problem(text(), str(LINE))
    assert p.data_files == {"ranges": str(PROBLEMS / "data" / "beacon_ranges.csv"),
                            "truth": str(PROBLEMS / "data" / "line_truth.csv")}
    assert os.path.isfile(p.data_files["ranges"])

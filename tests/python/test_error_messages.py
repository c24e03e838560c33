"""Errors that say what went wrong, from Python: parse errors on non-ASCII
text (never an empty message), the nesting limit, wrong types and indices
(sillage errors, not pybind11's generic cast errors), CSV files in the wrong
encoding, and printing of shared expressions in linear size."""
import math

import pytest

import sillage as sl


def test_error_classes():
    assert issubclass(sl.ArgumentTypeError, sl.Error) and issubclass(sl.ArgumentTypeError, TypeError)
    assert issubclass(sl.OutOfRangeError, sl.Error) and issubclass(sl.OutOfRangeError, IndexError)
    assert issubclass(sl.ParseError, sl.Error) and issubclass(sl.Error, ValueError)


@pytest.mark.parametrize("text, message", [
    ("x + é", "unexpected character 'é' (U+00E9) at column 5 in \"x + é\""),
    ("α*x", "unexpected character 'α' (U+03B1) at column 1 in \"α*x\""),
    ("x − 1", "unexpected character '−' (U+2212) at column 3 in \"x − 1\""),
    ("sin(x) 😀", "unexpected character '😀' (U+1F600) at column 8 in \"sin(x) 😀\""),
])
def test_non_ascii_parse_errors(text, message):
    with pytest.raises(sl.ParseError) as e:
        sl.Function(["x"], text)
    assert str(e.value) == message


def test_bytes_that_are_not_utf8():
    # Bytes reach the parser as they are; the message stays valid UTF-8 and non-empty.
    with pytest.raises(sl.ParseError) as e:
        sl.Function(["x"], b"x + \xe9")
    assert str(e.value) == "unexpected byte 0xE9 (the text is not valid UTF-8) at column 5 in \"x + \ufffd\""


@pytest.mark.parametrize("open_, close", [("(", ")"), ("sin(", ")"), ("-", "")])
def test_nesting_limit_is_500_levels(open_, close):
    ok = open_ * 500 + "x" + close * 500
    assert sl.Function(["x"], ok).nb_vars() == 1
    with pytest.raises(sl.ParseError, match=r"^expression nested too deeply \(more than 500 levels\) at column"):
        sl.Function(["x"], open_ * 501 + "x" + close * 501)


def test_shared_expressions_print_linearly():
    x = sl.ExprVar("x")
    e = x
    for _ in range(3):
        e = e * e + 1
    assert str(e) == "let a = x * x + 1; b = a * a + 1 in b * b + 1"
    assert repr(e) == "Expr(let a = x * x + 1; b = a * a + 1 in b * b + 1)"
    for _ in range(37):
        e = e * e + 1
    assert len(repr(e)) < 40 * 24  # 2^40 leaves as a tree
    f = sl.Function([x], e)
    assert sl.Function(["x"], f.expr_str()).expr_str() == f.expr_str()
    s = x
    for _ in range(200):
        s = sl.sin(s)
    assert len(str(sl.Function([x], s).diff())) < 200 * 60


def test_wrong_types_and_indices():
    a = sl.IntervalVector([[0, 1]])
    with pytest.raises(sl.ArgumentTypeError,
                       match=r"^contractor: expected a sillage.Ctc \(or a subclass\), got function$"):
        sl.ContractorNetwork().add(lambda x: x, [a])
    with pytest.raises(sl.ArgumentTypeError,
                       match="^sivia: f must return an IntervalVector or an Interval, got str$"):
        sl.sivia(sl.IntervalVector([[0, 1], [0, 1]]), lambda b: "abc", sl.Interval(0, 1), 0.1)
    tube = sl.Tube(sl.TDomain(0, 1, 0.1), sl.Interval(0, 1))
    with pytest.raises(sl.OutOfRangeError, match=r"^Tube.set\(y, k\): slice -1 is negative$"):
        tube.set(sl.Interval(0, 1), -1)
    with pytest.raises(sl.OutOfRangeError, match="^Tube.slice: slice -1 is negative$"):
        tube.slice(-1)
    with pytest.raises(sl.Error, match="^Tube.integral: t1 is NaN, expected a time or an Interval$"):
        tube.integral(math.nan)
    with pytest.raises(sl.Error, match="^Tube.integral: t2 is NaN, expected a time or an Interval$"):
        tube.integral(0, math.nan)
    with pytest.raises(sl.ArgumentTypeError, match="^Tube.integral: t1 must be an Interval or a number, got str$"):
        tube.integral("a")
    assert tube.integral(0.5) == sl.Interval(0, 0.5)
    t = sl.CsvTable.parse("a\n1\n2\n", "f.csv")
    with pytest.raises(sl.OutOfRangeError, match=r"^CsvTable.row: no row -1 \(the table has 2 rows: 0 to 1\)$"):
        t.row(-1)
    with pytest.raises(IndexError, match=r"^f.csv: no row 2 \(the table has 2 rows: 0 to 1\)$"):
        t.row(2)


def test_csv_encodings(tmp_path):
    path = tmp_path / "u16.csv"
    path.write_text("t,x\n1,2\n", encoding="utf-16")
    with pytest.raises(sl.ParseError) as e:
        sl.CsvTable.read(str(path))
    assert str(e.value) == f"{path}: the file is UTF-16 (it starts with a byte order mark); convert it to UTF-8"
    path.write_text("t,x\n1,2\n", encoding="utf-8-sig")
    assert sl.CsvTable.read(str(path)).columns() == ["t", "x"]
    assert sl.CsvTable.parse("t,x\r1,2\r3,4\r").nb_rows() == 2
    with pytest.raises(sl.ParseError, match="^<text>:1: columns 1 and 2 of the header have the same name 't'$"):
        sl.CsvTable.parse("t,t\n1,2\n")
    with pytest.raises(sl.ParseError) as e:
        sl.CsvTable.parse("t\n" + "é" * 1_000_000 + "\n").values("t")
    assert str(e.value) == "<text>:2: column 't': '" + "é" * 60 + "...' is not a finite number"

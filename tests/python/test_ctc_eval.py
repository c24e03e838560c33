"""CtcEval from Python (Prop. 5.1): in-place contraction of t, z and the tube,
the vector case, inconsistency, and both dynamics contractors in a
ContractorNetwork; CsvTable on the plaza1 dataset."""
import math
from pathlib import Path

import pytest
import sillage
from sillage import Interval, IntervalVector, TDomain, Tube, TubeVector


def test_known_time_shapes_the_gates():
    td = TDomain(0.0, 10.0, 1.0)
    y, w = Tube(td, Interval(-10, 10)), Tube(td, Interval(-1, 1))
    t, z = Interval(5.0), Interval(0.0)
    assert sillage.CtcEval().contract(t, z, y, w)
    assert y.gate(5) == Interval(0.0) and y.gate(8) == Interval(-3, 3)


def test_time_contracted_in_place_and_sampling():
    td = TDomain(0.0, 10.0, 0.5)
    y, w = Tube(td, "t"), Tube(td, Interval(1.0))
    t, z = Interval(0.0, 10.0), Interval(3.0, 3.25)
    sillage.CtcEval().contract(t, z, y, w)
    assert t.is_superset(Interval(3.0, 3.25)) and t.ub() < 3.26
    c = sillage.CtcEval()
    assert c.time_sampling()
    t2, z2 = Interval(2.25), Interval(-100, 100)
    c.contract(t2, z2, y, w)
    assert td.nb_slices() == 21 and z2.diam() < 1e-9


def test_vector_and_no_derivative_and_inconsistency():
    td = TDomain(0.0, 10.0, 0.5)
    y = TubeVector(td, "(t, 2*t)")
    t, z = Interval(0.0, 10.0), IntervalVector([Interval(0.0, 10.0), Interval(4.0, 5.0)])
    assert sillage.CtcEval().contract(t, z, y)
    assert t.is_subset(Interval(1.5, 3.0))
    y1 = Tube(td, Interval(5, 6))
    t1, z1 = Interval(1, 2), Interval(0.0)
    assert not sillage.CtcEval().contract(t1, z1, y1, Tube(td, Interval(-1, 1)))
    assert t1.is_empty() and z1.is_empty()


def test_network_with_deriv_and_eval():
    td = TDomain(0.0, 6.0, 0.05)
    x, v = Tube(td), Tube(td, "cos(t) + [-0.05, 0.05]")
    t, z = Interval(2.95, 3.05), Interval(math.sin(3.0) - 1e-3, math.sin(3.0) + 1e-3)
    cn = sillage.ContractorNetwork()
    cn.add(sillage.CtcDeriv(), [x, v])
    cn.add(sillage.CtcEval(), [t, z, x, v])
    s = cn.contract()
    assert not s.empty
    assert x.contains(sillage.Trajectory("sin(t)", Interval(0, 6)))
    assert x.gate(0).diam() < 1.0 and x.gate(td.nb_slices()).diam() < 1.0
    with pytest.raises(sillage.DimensionError):
        cn.add(sillage.CtcDeriv(), [x])


def test_csv_table():
    t = sillage.CsvTable.parse("a,b\n1,2\n3,4\n")
    assert list(t.values("b")) == [2.0, 4.0] and t.columns() == ["a", "b"]
    with pytest.raises(sillage.ParseError, match="^f.csv:3: column 'a': 'x' is not a finite number$"):
        sillage.CsvTable.parse("a\n1\nx\n", "f.csv").values("a")
    with pytest.raises(sillage.ParseError, match="^f.csv:2: 1 cells, the header"):
        sillage.CsvTable.parse("a,b\n1\n", "f.csv")
    t = sillage.CsvTable.parse("# c\na\n\n1\n2\n", "f.csv")  # each row's line, for messages about it
    assert (t.source(), t.line(0), t.line(1), t.where(1)) == ("f.csv", 4, 5, "f.csv:5")
    with pytest.raises(sillage.OutOfRangeError, match="CsvTable.line: no row -1"):
        t.line(-1)
    plaza = Path(__file__).resolve().parents[2].parent / "shared" / "data" / "plaza1" / "beacons.csv"
    if plaza.exists():
        assert sillage.CsvTable.read(str(plaza)).nb_rows() == 4


def test_csv_text_columns_kept_until_read():
    """A log's text columns (a frame name, a missing value) do not stop the table from being read; reading them does."""
    t = sillage.CsvTable.parse("t,frame,x\n0.5,base_link,1.5\n1.0,,2\n", "log.csv")
    assert list(t.values("x")) == [1.5, 2.0] and t.column("t") == 0
    assert t.is_numeric("x") and not t.is_numeric("frame") and t.has_column("frame")
    with pytest.raises(sillage.ParseError, match="^log.csv:2: column 'frame': 'base_link' is not a finite number$"):
        t.column("frame")
    with pytest.raises(sillage.ParseError, match="base_link"):
        t.values("frame")
    with pytest.raises(sillage.ParseError, match="base_link"):
        t.check_numeric(1)
    t.check_numeric(2)
    row = t.row(0)
    assert row[0] == 0.5 and math.isnan(row[1]) and row[2] == 1.5
    with pytest.raises(sillage.Error, match="no column 'y'"):
        t.is_numeric("y")


def test_csv_quoted_cells_and_signs():
    """Quoted names and cells (R, spreadsheets, pandas), commas inside quotes, a '+' sign."""
    t = sillage.CsvTable.parse('"t","label","x"\n1,"a, b",+0.5\n2,"say ""hi""","-2"\n')
    assert t.columns() == ["t", "label", "x"] and list(t.values("x")) == [0.5, -2.0]
    with pytest.raises(sillage.ParseError, match="^<text>:2: column 'label': 'a, b' is not a finite number$"):
        t.values("label")
    with pytest.raises(sillage.ParseError, match="^<text>:2: a quote opened at column 3 is not closed on its line$"):
        sillage.CsvTable.parse('t,x\n1,"2\n')


def test_inverse_within_a_time_interval_and_memory():
    td = TDomain(0.0, 10.0, 0.5)
    y, w = Tube(td, "t"), Tube(td, Interval(1.0))
    part = y.inverse(Interval(3, 7), w, Interval(2, 5))
    assert part.is_superset(Interval(3, 5)) and part.is_subset(Interval(2.999, 5.0))
    assert y.inverse(Interval(3, 7), w, Interval(8, 9)).is_empty()
    with pytest.raises(sillage.Error):
        y.inverse(Interval(3, 7), w, Interval(9, 11))
    assert y.memory_bytes() >= 32 * td.nb_slices()


def issue_case():
    """Slices of 2 over [-1, 7], w = -1, [-1, 1], -1, [-1, 1], nothing known of y."""
    td = TDomain([-1.0, 1.0, 3.0, 5.0, 7.0])
    w = Tube(td, [Interval(-1), Interval(-1, 1), Interval(-1), Interval(-1, 1)])
    return td, Tube(td), w


def test_time_inside_slices_gives_the_exact_set_of_the_definition():
    td, y, w = issue_case()
    c = sillage.CtcEval()
    c.enable_time_sampling(False)
    t, z = Interval(0.0, 6.0), Interval(-1.0, 1.0)
    assert c.contract(t, z, y, w)
    assert [y.gate(i) for i in range(5)] == [Interval(-1, 8), Interval(-3, 6), Interval(-4, 4), Interval(-6, 2),
                                             Interval(-8, 3)]
    assert y.eval(Interval(0.0), w) == Interval(-2, 7)


def test_time_bounds_as_gates_give_the_exact_set_everywhere():
    td, y, w = issue_case()
    t, z = Interval(0.0, 6.0), Interval(-1.0, 1.0)
    td.sample(t)  # gates at 0 and 6
    assert td.nb_slices() == 6
    assert sillage.CtcEval().contract(t, z, y, w)
    expected = {-1: (-1, 8), 0: (-2, 7), 1: (-3, 6), 3: (-4, 4), 5: (-6, 2), 6: (-7, 2), 7: (-8, 3)}
    for ti, (lo, hi) in expected.items():
        assert y.gate(td.time_index(ti)) == Interval(lo, hi), ti


def test_one_call_is_a_fixed_point():
    td = TDomain(0.0, 10.0, 0.7)
    y, w = Tube(td, "sin(t) + [-0.6, 0.6]"), Tube(td, "cos(t) + [-0.2, 0.2]")
    c = sillage.CtcEval()
    t, z = Interval(2.35, 4.1), Interval(0.5, 0.6)
    assert c.contract(t, z, y, w)
    gates = [y.gate(k) for k in range(td.nb_slices() + 1)]
    t1, z1 = Interval(t), Interval(z)
    assert c.contract(t, z, y, w)
    assert t == t1 and z == z1 and gates == [y.gate(k) for k in range(td.nb_slices() + 1)]


def test_network_adds_the_time_bounds_as_gates():
    td = TDomain(0.0, 10.0, 1.0)
    y, w = Tube(td), Tube(td, Interval(0, 1))
    t, z = Interval(3.5, 4.5), Interval(0.0)
    cn = sillage.ContractorNetwork()
    cn.add(sillage.CtcDeriv(), [y, w])
    ev = sillage.CtcEval()
    assert not ev.gates_at_time_bounds()
    ev.enable_gates_at_time_bounds(True)
    cn.add(ev, [t, z, y, w])
    assert td.nb_slices() == 10
    assert not cn.contract().empty
    assert td.nb_slices() == 12 and td.is_time_point(3.5) and td.is_time_point(4.5)
    assert y.eval(Interval(3.75), w) == Interval(-0.75, 0.25)  # the exact set of (5.6) there

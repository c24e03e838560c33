"""Problem files read as written (issue 37): a time is a decimal, a joined key
appears once, outputs never overwrite inputs, a bound with no value is a bad
input, and what a file states without meaning to comes back as warnings."""
from decimal import Decimal

import pytest

import sillage


def write(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def test_a_value_at_a_decimal_time_holds_there(tmp_path):
    path = write(tmp_path, "p.toml",
                 "[time]\ndomain = [1000000000, 1000000001]\ndelta = 0.25\n"
                 "[var.x]\nkind = \"tube\"\nat = [{ t = 1000000000.1, value = 100 }]\n"
                 "[var.v]\nkind = \"tube\"\nvalue = 1000\n"
                 "[[constraint]]\nkind = \"deriv\"\nx = \"x\"\nv = \"v\"\n")
    r = sillage.solve(path)
    assert not r.empty, r.why_empty
    x = r.domains["x"]
    for k in range(x.nb_slices() + 1):
        t = x.tdomain().t(k)
        truth = 100 + 1000 * (Decimal(t) - Decimal("1000000000.1"))  # exact
        g = x.gate(k)
        assert Decimal(g.lb()) <= truth <= Decimal(g.ub()), (k, g, truth)
    assert r.warnings == []


def test_a_join_key_twice_is_refused(tmp_path):
    write(tmp_path, "ranges.csv", "t,id,r\n1,3,9\n")
    write(tmp_path, "beacons.csv", "id,bx,by\n3,10,0\n3,-10,0\n")
    path = write(tmp_path, "p.toml",
                 "[time]\ndomain = [0, 2]\ndelta = 0.1\n"
                 "[data.ranges]\nfile = \"ranges.csv\"\n[data.beacons]\nfile = \"beacons.csv\"\n"
                 "[var.p]\nkind = \"tube_vector\"\ndim = 2\n[var.v]\nkind = \"tube_vector\"\ndim = 2\n"
                 "[[constraint]]\nkind = \"eval\"\ndata = \"ranges\"\njoin = { data = \"beacons\", on = \"id\" }\n"
                 "y = \"p\"\nv = \"v\"\ntime = \"t\"\nexpr = \"sqrt((p[0] - bx)^2 + (p[1] - by)^2) - r\"\n")
    with pytest.raises(sillage.Error, match=r"found the id 3 in two rows of 'beacons' with other values: "
                                                   r".*beacons.csv:2 and line 3"):
        sillage.load_problem(path)


def test_outputs_never_overwrite_inputs(tmp_path):
    write(tmp_path, "x.csv", "t,x\n0,1\n1,2\n")
    path = write(tmp_path, "p.toml", "[time]\ndomain = [0, 1]\ndelta = 0.5\n[data.logged]\nfile = \"x.csv\"\n"
                                     "[var.x]\nkind = \"tube\"\n[[constraint]]\nkind = \"expr\"\nexpr = \"x - 1\"\n")
    p = sillage.load_problem(path)
    assert sillage.output_names(p) == ["results.json", "report.html", "x.csv"]
    assert sillage.output_names(p, tube_files=True)[-1] == "x.tube"
    with pytest.raises(sillage.Error, match="would overwrite the table 'logged'"):
        sillage.check_output_dir(p, str(tmp_path))
    sillage.check_output_dir(p, str(tmp_path / "out"))


def test_an_empty_bound_is_a_bad_input(tmp_path):
    path = write(tmp_path, "p.toml", "[time]\ndomain = [0, 1]\ndelta = 0.5\n[var.x]\nkind = \"tube\"\n"
                                     "at = [{ t = 0, value = \"1/0\" }]\n[[constraint]]\nkind = \"expr\"\nexpr = \"x\"\n")
    with pytest.raises(sillage.Error, match=r'p.toml:6:25: found the bound "1/0", which is empty'):
        sillage.load_problem(path)


def test_warnings_of_a_header_only_table(tmp_path):
    write(tmp_path, "ranges.csv", "t,r\n")
    path = write(tmp_path, "p.toml",
                 "[time]\ndomain = [0, 1]\ndelta = 0.5\n[data.ranges]\nfile = \"ranges.csv\"\n"
                 "[var.x]\nkind = \"tube\"\nvalue = \"[-1, 1]\"\n[var.v]\nkind = \"tube\"\nvalue = \"[-1, 1]\"\n"
                 "[[constraint]]\nkind = \"deriv\"\nx = \"x\"\nv = \"v\"\n"
                 "[[constraint]]\nkind = \"eval\"\ndata = \"ranges\"\ny = \"x\"\nv = \"v\"\ntime = \"t\"\nexpr = \"x - r\"\n")
    p = sillage.load_problem(path)
    (w,) = sillage.problem_warnings(p)
    assert w.startswith("the table 'ranges' (") and "ranges.csv) has only its header: constraint 2 (eval)" in w
    assert "p.toml:16:1) states nothing" in w
    r = sillage.solve(path)
    assert r.warnings == [w]
    assert "warning: " + w in sillage.check_summary(p)


def test_a_named_contractor_is_named_in_the_emptiness():
    cn = sillage.ContractorNetwork()
    x = cn.create_dom(sillage.Interval(0, 1), "x")
    y = cn.create_dom(sillage.Interval(2, 3), "y")
    cn.add(sillage.CtcFunction(sillage.Function(["a", "b"], "a - b")), [x, y])
    cn.set_ctc_name(0, "ranges line 12")
    with pytest.raises(sillage.Error, match="no contractor 1"):
        cn.set_ctc_name(1, "none")
    s = cn.contract()
    assert s.emptiness == "CtcFunction(a - b) (ranges line 12) emptied interval 'x'"


def test_a_truth_in_time_order_and_a_solve_that_fits(tmp_path):
    write(tmp_path, "truth.csv", "t,x\n0,0\n1,1\n0.5,2\n")
    path = write(tmp_path, "p.toml", "[data.truth]\nfile = \"truth.csv\"\n[time]\ndomain = [0, 1]\ndelta = 0.5\n"
                                     "[var.x]\nkind = \"tube\"\n[[constraint]]\nkind = \"expr\"\nexpr = \"x\"\n"
                                     "[output]\ntruth = { data = \"truth\", time = \"t\", columns = { x = \"x\" } }\n")
    with pytest.raises(sillage.Error, match=r"found the stamps 1 at .*truth.csv:3 and 0.5 at line 4 of 'truth', "
                                            r"not increasing, expected a truth with strictly increasing times"):
        sillage.load_problem(path)
    huge = write(tmp_path, "huge.toml", "[time]\ndomain = [0, 1]\ndelta = 2.5e-8\n[var.x]\nkind = \"tube_vector\"\n"
                                        "dim = 1000\n[[constraint]]\nkind = \"expr\"\nexpr = \"x[0]\"\n")
    with pytest.raises(sillage.Error, match=r"gives 40000000 slices: about 5587.9 GiB of memory at the peak"):
        sillage.solve(huge)


def test_memory_estimate_and_stopped_stats(tmp_path):
    path = write(tmp_path, "p.toml", "[time]\ndomain = [0, 1]\ndelta = 0.5\n[var.x]\nkind = \"tube_vector\"\ndim = 1000\n"
                                     "[[constraint]]\nkind = \"expr\"\nexpr = \"x[0]\"\n")
    p = sillage.load_problem(path)
    assert sillage.peak_memory_estimate(p, 40_000_000) > 5e12
    sillage.check_memory(p, 2, "delta = 0.5")  # fits
    with pytest.raises(sillage.Error, match="--delta 1e-9 gives 40000000 slices"):
        sillage.check_memory(p, 40_000_000, "--delta 1e-9")
    cn = sillage.ContractorNetwork()
    x = cn.create_dom(sillage.Interval(0, 1e6), "x")
    y = cn.create_dom(sillage.Interval(0, 1e6), "y")
    cn.add(sillage.CtcFunction(sillage.Function(["a", "b"], "a - b")), [x, y])
    cn.add(sillage.CtcFunction(sillage.Function(["a", "b"], "b - 0.99999*a")), [x, y])
    cn.set_ratio(0)
    cn.set_budget(sillage.Budget(max_boxes=5))
    with pytest.raises(sillage.BudgetExceeded):
        cn.contract()
    assert cn.stopped_stats().contractor_calls == 5

"""Every class of the module has a repr of its own (none is Python's default
'<... object at 0x...>'), and none is patched on at import time."""
import inspect

import sillage as s
from sillage import _sillage


def classes():
    return [c for _, c in inspect.getmembers(_sillage, inspect.isclass) if not issubclass(c, BaseException)]


def test_every_class_has_its_own_repr():
    default = [c.__name__ for c in classes() if c.__repr__ is object.__repr__ or
               type(c.__repr__).__name__ == "wrapper_descriptor"]
    assert not default, f"classes with the default repr: {default}"


def test_reprs_come_from_the_compiled_module():
    patched = [c.__name__ for c in classes() if inspect.isfunction(c.__repr__)]
    assert not patched, f"reprs patched from Python: {patched}"


def test_option_and_result_reprs_name_their_fields():
    o = s.CountOptions()
    o.max_boxes = 7
    assert repr(o).startswith("CountOptions(") and "max_boxes=7" in repr(o)
    assert repr(s.CancelToken()) == "CancelToken(cancelled=False)"
    t = s.CancelToken()
    t.cancel()
    assert repr(t) == "CancelToken(cancelled=True)"


def test_small_reprs():
    assert repr(s.CsvTable.parse("a,b\n1,2\n3,4\n")) == "CsvTable(2 rows, columns=['a', 'b'])"
    assert repr(s.CtcEval()) == "<CtcEval>"
    assert repr(s.DefinitionCheck(s.Function(["x"], "sqrt(x)"))) == "DefinitionCheck(total=False)"
    assert repr(s.DefinitionCheck(s.Function(["x"], "x + 1"))) == "DefinitionCheck(total=True)"

    class Mine(s.TubeCtc):
        def contract(self, domains):
            return True

    assert repr(Mine()) == "<Mine (TubeCtc)>"
    td = s.TDomain(0.0, 1.0, 0.5)
    v = s.TubeVector(td, 2, s.Interval(-1, 1))
    assert repr(s.LoopFunction(v)) == "LoopFunction(t=[0, 1], from v)"

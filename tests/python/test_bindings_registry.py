"""The binding files register themselves (SILLAGE_BINDING, python/src/bindings.h):
every file's binding is called once, after the bindings it names, and it
names every binding whose classes it uses or whose functions it overloads; an
unknown name or a cycle is an error naming the binding."""
import re
from pathlib import Path

import pytest

from sillage import _sillage

SRC = Path(__file__).resolve().parents[2] / "python" / "src"
BINDING = re.compile(r"^SILLAGE_BINDING\((\w+)((?:,\s*\"\w+\")*)\)", re.M)


def declared():
    """{name: (file, set of names after)} from the sources."""
    out = {}
    for f in sorted(SRC.rglob("*.cpp")):
        for name, after in BINDING.findall(f.read_text()):
            assert name not in out, f"{name} registered in {out[name][0]} and {f}"
            out[name] = (f, set(re.findall(r'"(\w+)"', after)))
    return out


def code(text):
    """The C++ text without comments and string literals."""
    text = re.sub(r"//.*", "", text)
    return re.sub(r'"(?:[^"\\]|\\.)*"', '""', text)


def closure(decl, name):
    seen, todo = set(), list(decl[name][1])
    while todo:
        d = todo.pop()
        if d not in seen:
            seen.add(d)
            todo += decl[d][1]
    return seen


def test_one_binding_per_file():
    files = sorted(SRC.rglob("bind_*.cpp"))
    decl = declared()
    assert sorted(f.stem for f, _ in decl.values()) == sorted(f.stem for f in files)
    for name, (f, _) in decl.items():
        assert f.stem == f"bind_{name}", f"{f.name} registers {name}: name it bind_{name}.cpp"


def test_every_binding_called_once_after_its_dependencies():
    called = [name for name, _, _ in _sillage._bindings]
    decl = declared()
    assert sorted(called) == sorted(decl), "bindings registered in the sources but not called (or the reverse)"
    for i, (name, after, file) in enumerate(_sillage._bindings):
        assert set(after) == decl[name][1]
        assert file == str(decl[name][0].relative_to(SRC.parents[1])), file
        assert set(after) <= set(called[:i]), f"{name} called before {set(after) - set(called[:i])}"


def test_a_binding_names_the_bindings_of_the_classes_it_uses():
    """A class used before it is bound becomes a C++ type name in the signatures (or an
    ImportError for a base class or a default value): each file names the bindings of the
    Python classes it mentions, and one of two files that define the same module function
    comes after the other (the overload bound first is tried first)."""
    decl = declared()
    owner, functions = {}, {}
    for name, (f, _) in decl.items():
        text = f.read_text()
        for cls in re.findall(r"py::(?:class_|enum_)<[^;]*?>\s*\w*\s*\(\s*\w+\s*,\s*\"(\w+)\"", text, re.S):
            owner[cls] = name
        for fn in set(re.findall(r'\bm\.(?:def\(\s*"|SILLAGE_FN\(\s*)(\w+)', text)):  # SILLAGE_FN: bindings.h
            functions.setdefault(fn, []).append(name)
    assert {"Interval", "Tube", "NetworkCtc", "Ctc"} <= set(owner)
    missing = []
    for name, (f, _) in decl.items():
        text = f.read_text()
        body = code(text)
        for cls, other in owner.items():
            if other == name or other in closure(decl, name):
                continue
            if re.search(r"(?<![\w:.])" + cls + r"\b", body) or f'attr("{cls}")' in text:
                missing.append(f'{f.name} uses {cls}: add "{other}" to SILLAGE_BINDING({name}, ...)')
    for fn, names in functions.items():
        for a in names:
            for b in names:
                if a < b and a not in closure(decl, b) and b not in closure(decl, a):
                    missing.append(f"{a} and {b} both define {fn}(): one must come after the other")
    assert missing == []


def test_no_signature_names_a_cpp_type():
    """What a missing dependency looks like: pybind11 writes the C++ name of a class not bound
    yet into the signature."""
    bad = []
    for name in dir(_sillage):
        obj = getattr(_sillage, name)
        docs = [getattr(obj, "__doc__", None)]
        if isinstance(obj, type):
            docs += [getattr(v, "__doc__", None) for v in vars(obj).values()]
        bad += [f"{name}: {line.strip()}" for d in docs if isinstance(d, str)
                for line in d.splitlines() if "sillage::" in line and "(" in line]
    assert bad == []


def test_the_order_is_checked():
    order = _sillage._binding_order
    assert order([("b", ["a"]), ("a", []), ("c", ["b", "a"])]) == ["a", "b", "c"]
    with pytest.raises(Exception, match="'b' .* is declared after 'x', which no SILLAGE_BINDING registers"):
        order([("a", []), ("b", ["x"])])
    with pytest.raises(Exception, match="a cycle of dependencies: a -> b -> a"):
        order([("a", ["b"]), ("b", ["a"])])
    with pytest.raises(Exception, match="'a' is registered twice"):
        order([("a", []), ("a", [])])

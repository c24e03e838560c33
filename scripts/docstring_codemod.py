#!/usr/bin/python3
"""One-shot codemod: literal docstrings of python/src/**/bind_*.cpp -> DOC(...) from the headers.

    docstring_codemod.py FILE.cpp...          rewrites the files in place, prints what it did
    docstring_codemod.py --check FILE.cpp...  rewrites nothing; lists the literals it would
                                              replace, exit status 1 if there is any
    docstring_codemod.py --to-headers FILE.cpp...
        also writes, as a header comment, the literal of a binding whose C++ declaration has no
        comment (not for Python-specific texts: numpy, list, None, ...; not in FROZEN_HEADERS;
        not when the overload is ambiguous). Run it again (plain) to convert those too.

Re-running it is safe: a converted file is left unchanged. To convert a file that was exempt
(tests/python/test_docstrings.py, EXEMPT), run it on that file, build, and remove the file from
EXEMPT.

What it does, per statement of a binding file (preprocessor lines are skipped):
- the owner: the class of `py::class_<T, ...>(m, "Name", doc)` / `py::enum_<T>` that starts the
  statement, or of the variable `c` in `c.def(...)` (declared `py::class_<T...> c(...)`);
  `m.def(...)` (m a py::module_) binds a free function. Aliases (`using T = Tube;`) are followed.
  A template parameter (py::class_<C, ...> in a helper template) is no known class: skipped.
- the entity of each call: the class itself (the py::class_ constructor), `.def("name")`,
  `.def_static`, `.def_readonly/readwrite`, `.def_property_readonly` -> (T, name) with Python
  dunders mapped to the C++ operators (__call__ -> op_call, ...); `.def(py::init...)` -> (T, T);
  `.value("A", E::A, doc)` -> (E, A); `m.def("name")` -> (name).
- the docstring: the argument made of adjacent string literals after the name. A docstring held in
  a named constant, or given with a C++ name that no header documents (Python-only callables:
  __repr__, to_numpy, pickling, conveniences), stays as it is.
- overloads: the binding's parameter types are read from py::overload_cast<...>, static_cast<R
  (*)(...)>, py::init<...> or the lambda's parameters (self dropped), and matched to the header's
  overload tag (gen_docstrings.type_tag); failing that, the one overload with the same number of
  parameters; failing that, DOC(T, name) (the joined text of the overloads). A binding matched to
  an overload that has no comment keeps its literal.
- adds #include "docstrings.h" (the generated header) to a file it changed.
"""
import re
import sys
import textwrap
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import gen_docstrings as gd  # noqa: E402

DUNDERS = {
    "__call__": "op_call", "__getitem__": "op_index", "__eq__": "op_eq", "__ne__": "op_ne",
    "__lt__": "op_lt", "__le__": "op_le", "__gt__": "op_gt", "__ge__": "op_ge",
    "__add__": "op_add", "__sub__": "op_sub", "__mul__": "op_mul", "__truediv__": "op_div",
    "__iadd__": "op_iadd", "__isub__": "op_isub", "__imul__": "op_imul", "__itruediv__": "op_idiv",
    "__and__": "op_and", "__or__": "op_or", "__iand__": "op_iand", "__ior__": "op_ior",
    "__bool__": "op_bool",
}
DEF_CALLS = ("def", "def_static", "def_readonly", "def_readwrite", "def_property_readonly",
             "def_readonly_static", "value")
INCLUDE = '#include "docstrings.h"'


def skip_string(src, i):
    """Index after the string or char literal starting at i (raw strings included)."""
    if src.startswith('R"', i):
        m = re.match(r'R"([^(]*)\(', src[i:])
        end = src.find(")" + m.group(1) + '"', i)
        return end + len(m.group(1)) + 2
    q, j = src[i], i + 1
    while j < len(src) and src[j] != q:
        j += 2 if src[j] == "\\" else 1
    return j + 1


def code_chars(src, i=0, end=None):
    """(index, char) of the code of src[i:end]: comments and string literals skipped; a
    preprocessor line (continuations included) is skipped and reported as one '#'."""
    end = len(src) if end is None else end
    while i < end:
        c = src[i]
        if src.startswith("//", i):
            i = src.find("\n", i)
            i = end if i < 0 else i
        elif src.startswith("/*", i):
            i = src.find("*/", i) + 2
        elif c == "#" and src[src.rfind("\n", 0, i) + 1:i].strip() == "":
            while True:
                j = src.find("\n", i)
                if j < 0 or src[j - 1] != "\\":
                    break
                i = j + 1
            i = end if j < 0 else j
            yield i, "#"
        elif c == '"' or (c == "'" and not src[i - 1].isalnum()) or src.startswith('R"', i):
            i = skip_string(src, i)
        else:
            yield i, c
            i += 1


def statements(src):
    """[(start, end)] of the statements: split at ';', '{' and '}' outside parentheses;
    preprocessor lines are left out."""
    out, depth, start = [], 0, 0
    for i, c in code_chars(src):
        if c == "#":
            start = i
        elif c in "([":
            depth += 1
        elif c in ")]":
            depth -= 1
        elif c in "{};" and depth == 0:
            out.append((start, i))
            start = i + 1
    return out


def matching(src, i):
    """Index of the ')' closing the '(' at i."""
    depth = 0
    for j, c in code_chars(src, i):
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
            if depth == 0:
                return j
    return len(src)


def args(src, open_at, close_at):
    """[(start, end)] of the top-level arguments of the call whose parentheses are given."""
    out, depth, angle, start = [], 0, 0, open_at + 1
    for i, c in code_chars(src, open_at + 1, close_at):
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif c == "<" and depth == 0 and re.search(r"\w$", src[start:i]):  # a template argument list
            angle += 1
        elif c == ">" and depth == 0 and angle > 0 and src[i - 1] != "-":
            angle -= 1
        elif c == "," and depth == 0 and angle == 0:
            out.append((start, i))
            start = i + 1
    if src[start:close_at].strip():
        out.append((start, close_at))
    return out


LITERALS = re.compile(r'^\s*(?:(?://[^\n]*\n\s*)*"(?:[^"\\\n]|\\.)*"\s*)+$')


def is_literal(text):
    return LITERALS.match(text) is not None


def literal_value(text):
    return "".join(re.findall(r'"((?:[^"\\\n]|\\.)*)"', text))


def aliases_before(src, pos):
    """{alias: type} of the `using X = Y;` lines before pos (the last one wins)."""
    out = {}
    for m in re.finditer(r"\busing\s+(\w+)\s*=\s*([^;]+);", src[:pos]):
        out[m.group(1)] = " ".join(m.group(2).split())
    return out


def resolve(t, al):
    for _ in range(4):
        t2 = re.sub(r"\b(\w+)\b", lambda m: al.get(m.group(1), m.group(1)), t)
        if t2 == t:
            break
        t = t2
    return t


def class_of(template_args, al):
    first = gd.split_top(template_args)[0].strip()
    first = resolve(first, al)
    return re.sub(r"^.*::", "", first) if re.match(r"^[\w:]+$", first) else None


def fn_pointer_params(t):
    """Parameter types of a function pointer type `R (*)(A, B)` / `R (T::*)(A) const`."""
    m = re.search(r"\(\s*(?:\w+::)*\*\s*\)\s*\((.*)\)", t)
    if not m:
        return None
    inner = m.group(1).strip()
    return [gd.param_type(p) for p in gd.split_top(inner)] if inner else []


def binding_params(src, arg, al, owner, method):
    """Parameter types of the callable given as `arg` (text), self dropped for methods."""
    a = " ".join(arg.split())
    m = re.match(r"^py::overload_cast<(.*?)>\(", a)
    if m:
        inner = resolve(m.group(1), al)
        return [t.strip() for t in gd.split_top(inner)] if inner.strip() else []
    m = re.match(r"^static_cast<(.*)>\(", a)
    if m:
        return fn_pointer_params(resolve(m.group(1), al))
    m = re.match(r"^py::init<(.*)>\(\)$", a)
    if m:
        inner = resolve(m.group(1), al)
        return [t.strip() for t in gd.split_top(inner)] if inner.strip() else []
    m = re.match(r"^(?:py::init\()?\[[^\]]*\]\s*\(", a)
    if m:
        close = matching(a, m.end() - 1)
        inner = resolve(a[m.end():close], al)
        params = [gd.param_type(p) for p in gd.split_top(inner)] if inner.strip() else []
        if method and params and gd.short_type(params[0]) == owner:
            params = params[1:]
        return params
    return None


def choose(key, params, table, alltable):
    """The DOC arguments for entity key bound with these parameter types; None: no comment."""
    documented = table.get(key)
    if not documented:
        return None
    if params is not None and any("py::" in p for p in params):
        return None  # takes Python objects (numpy arrays, lists): a Python behaviour, its own text
    overloads = alltable.get(key, documented)
    if len({e.text for e in documented}) == 1 and len(overloads) == len(documented):
        return key
    if params is not None:
        tag = gd.type_tag(params)
        hits = [e for e in overloads if e.params is not None and gd.type_tag(e.params) == tag]
        if not hits:
            hits = [e for e in overloads if e.params is not None and len(e.params) == len(params)]
        if len(hits) == 1:
            return key + (gd.type_tag(hits[0].params),) if hits[0].text else None
        if hits and all(not e.text for e in hits):
            return None
    return key


class Edit:
    def __init__(self, start, end, new, key, old):
        self.start, self.end, self.new, self.key, self.old = start, end, new, key, old


def plan(path, table, alltable):
    """(edits, kept): the literal docstrings to replace, and [(name, why)] of those kept."""
    src = Path(path).read_text()
    edits, kept = [], []
    var_class, modules = {}, {"m"}
    for s, e in statements(src):
        stmt = src[s:e]
        al = aliases_before(src, s)
        m_var = re.search(r"py::(?:class_|enum_)<(.*?)>\s+(\w+)\s*\(", stmt)
        m_auto = re.search(r"\bauto\s+(\w+)\s*=\s*py::(?:class_|enum_)<(.*?)>\s*\(", stmt)
        if m_var:
            var_class[m_var.group(2)] = class_of(m_var.group(1), al)
        if m_auto:
            var_class[m_auto.group(1)] = class_of(m_auto.group(2), al)
        for m_mod in re.finditer(r"py::module_&?\s+(\w+)", stmt):
            modules.add(m_mod.group(1))
        lead = stmt.lstrip()
        owner, root_end = None, None
        m_cls = re.search(r"py::(class_|enum_)<", stmt)
        first_def = re.search(r"\.(%s)\(" % "|".join(DEF_CALLS), stmt)
        if m_cls and (first_def is None or m_cls.start() < first_def.start()):
            lt = s + m_cls.end() - 1
            depth, j = 0, lt
            while True:
                depth += src[j] == "<" and 1 or (src[j] == ">" and -1 or 0)
                if depth == 0:
                    break
                j += 1
            owner = class_of(src[lt + 1:j], al)
            k = j + 1
            m_name = re.match(r"\s*(\w+)?\s*\(", src[k:])
            if m_name:
                open_at = k + m_name.end() - 1
                close_at = matching(src, open_at)
                a = args(src, open_at, close_at)
                if owner and len(a) >= 3 and is_literal(src[a[2][0]:a[2][1]]):
                    edits_or_keep(edits, kept, (owner,), None, a[2], src, table, alltable, owner)
                root_end = close_at
        else:
            m_root = re.match(r"(\w+)\s*\.\s*(%s)\(" % "|".join(DEF_CALLS), lead)
            if not m_root:
                continue
            root = m_root.group(1)
            if root in modules:
                owner = ""
            elif root in var_class:
                owner = var_class[root]
            else:
                continue
        if owner is None:
            continue
        for m_def in re.finditer(r"\.\s*(%s)\s*\(" % "|".join(DEF_CALLS), src[s:e]):
            open_at = s + m_def.end() - 1
            if root_end is not None and open_at < root_end:
                continue
            if depth_at(src, s, open_at) != 0:
                continue
            close_at = matching(src, open_at)
            call(m_def.group(1), src, open_at, close_at, owner, al, edits, kept, table, alltable)
    return src, edits, kept


def depth_at(src, s, pos):
    """Parenthesis depth of pos inside the statement starting at s."""
    depth = 0
    for _, c in code_chars(src, s, pos):
        depth += c in "([{" and 1 or (c in ")]}" and -1 or 0)
    return depth


def call(kind, src, open_at, close_at, owner, al, edits, kept, table, alltable):
    a = args(src, open_at, close_at)
    if not a:
        return
    texts = [src[x:y].strip() for x, y in a]
    doc = next((i for i in range(1, len(a)) if is_literal(src[a[i][0]:a[i][1]])), None)
    if doc is None:
        return
    if texts[0].startswith("py::init"):
        if not owner:
            return
        key = (owner, owner)
        params = binding_params(src, texts[0], al, owner, False)
    elif is_literal(texts[0]):
        name = literal_value(texts[0])
        if kind == "value":
            m = re.match(r"^[\w:]*::(\w+)$", texts[1]) if len(texts) > 1 else None
            name = m.group(1) if m else name
        cname = DUNDERS.get(name, name)
        key = (owner, cname) if owner else (cname,)
        params = None
        if kind in ("def", "def_static") and len(texts) > 1:
            params = binding_params(src, texts[1], al, owner, kind == "def" and bool(owner))
    else:
        return
    edits_or_keep(edits, kept, key, params, a[doc], src, table, alltable, owner)


undocumented = []  # (key, params, literal) of the bindings kept for lack of a header comment


def edits_or_keep(edits, kept, key, params, span, src, table, alltable, owner):
    label = ".".join(key)
    if params is not None and any("py::" in p for p in params):
        kept.append((label, "Python objects"))  # numpy arrays, lists: a Python behaviour
        return
    chosen = choose(key, params, table, alltable)
    if chosen is None:
        kept.append((label, "no header comment" if key in alltable else "Python-only"))
        if key in alltable:
            undocumented.append((key, params, src[span[0]:span[1]].strip()))
        return
    x, y = span
    lead = len(src[x:y]) - len(src[x:y].lstrip())
    edits.append(Edit(x + lead, y - (len(src[x:y]) - len(src[x:y].rstrip())),
                      "DOC(" + ", ".join(chosen) + ")", chosen, src[x + lead:y].strip()))


# Words that make a docstring Python-specific: such a text is not moved into a C++ header.
PYTHON_WORDS = re.compile(r"numpy|\blists?\b|\btuples?\b|\bNone\b|Python|\bdict\b|\bstr\b|\bfloats?\b|"
                          r"sillage\.|\bself\b|KeyboardInterrupt|Ctrl-C|\bint\b|__\w+__|\bkw|\bpy\b")
FROZEN_HEADERS = ()  # headers the codemod must not edit (none now)


def unescape(v):
    return re.sub(r'\\(.)', lambda m: {"n": "\n", "t": "  "}.get(m.group(1), m.group(1)), v)


def overload_of(key, params, alltable):
    """The header declaration a binding of key with these parameter types binds, or None."""
    overloads = alltable.get(key, [])
    if len(overloads) == 1:
        return overloads[0]
    if params is None:
        return None
    tag = gd.type_tag(params)
    hits = [e for e in overloads if e.params is not None and gd.type_tag(e.params) == tag]
    if not hits:
        hits = [e for e in overloads if e.params is not None and len(e.params) == len(params)]
    return hits[0] if len(hits) == 1 else None


def to_headers(alltable):
    """Writes the literals of `undocumented` as the header comments they lack (the header becomes
    the one place of the text). Skipped: Python-specific texts, frozen headers, ambiguous overloads.
    Returns the number of comments written."""
    inserts = {}  # header -> {line: (indent, text)}
    for key, params, literal in undocumented:
        e = overload_of(key, params, alltable)
        if e is None or e.text or any(f in e.header for f in FROZEN_HEADERS):
            continue
        text = unescape(literal_value(literal)).strip()
        if not text or PYTHON_WORDS.search(text):
            continue
        text = re.sub(r"(?<=.)\bTrue\b", "true", re.sub(r"(?<=.)\bFalse\b", "false", text))
        inserts.setdefault(e.header, {}).setdefault(e.line, text)
    count = 0
    for header, at in inserts.items():
        lines = Path(header).read_text().splitlines(keepends=True)
        for line in sorted(at, reverse=True):
            decl = lines[line - 1]
            indent = decl[:len(decl) - len(decl.lstrip())]
            width = 100 - len(indent) - 3
            comment = []
            for para in at[line].split("\n"):
                comment += textwrap.wrap(para, width) or [""]
            lines[line - 1:line - 1] = [f"{indent}// {c}".rstrip() + "\n" for c in comment]
            count += 1
        Path(header).write_text("".join(lines))
    return count


def tables():
    ents = gd.entities(all_entities=True)
    return gd.table([e for e in ents if e.text]), gd.table(ents)


def apply(src, edits):
    for ed in sorted(edits, key=lambda ed: ed.start, reverse=True):
        src = src[:ed.start] + ed.new + src[ed.end:]
    if edits and INCLUDE not in src:
        incs = list(re.finditer(r'^#include "[^"]+"\n', src, re.M))
        at = incs[0].start() if incs else 0
        src = src[:at] + INCLUDE + "\n" + src[at:]
        # keep the quoted includes sorted
        block = re.search(r'(^#include "[^"]+"\n)+', src, re.M)
        lines = sorted(block.group(0).splitlines(keepends=True))
        src = src[:block.start()] + "".join(lines) + src[block.end():]
    return src


def main(argv):
    check = "--check" in argv
    headers = "--to-headers" in argv
    files = [a for a in argv if a not in ("--check", "--to-headers")]
    table, alltable = tables()
    total, status = 0, 0
    for f in files:
        src, edits, kept = plan(f, table, alltable)
        total += len(edits)
        if check:
            for ed in edits:
                print(f"{f}: {'.'.join(ed.key[:2])}: literal docstring, header comment exists: {ed.new}")
            status |= bool(edits)
        else:
            new = apply(src, edits)
            if new != src:
                Path(f).write_text(new)
            print(f"{f}: {len(edits)} converted, {len(kept)} literal kept "
                  f"({sum(w == 'Python-only' for _, w in kept)} Python-only)")
    if headers and not check:
        print(f"header comments written: {to_headers(alltable)} (run again without --to-headers after "
              f"regenerating, to convert them)")
    print(f"total: {total} {'convertible' if check else 'converted'}")
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

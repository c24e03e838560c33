#!/usr/bin/python3
"""Python docstrings written once: generated from the comments of the public headers.

    gen_docstrings.py OUTPUT.h HEADER.h...      writes the docstring header
    gen_docstrings.py --list [HEADER.h...]      prints the documented entities (default: include/sillage)

A documented entity is a class / struct / enum, a type alias (using X = ...), a method, constructor, data member or
enumerator of one, or a free function of namespace sillage (not detail, not private), with a
comment: the block of `//` lines right above its declaration (no blank line between), or the
`//` comment at the end of its declaration's last line (continued on the aligned `//` lines
below it). A section heading ('// ---- arithmetic ----') ends a block: only the lines after it
count; a lint marker ('NOLINT: implicit ...') is no text. A class without a comment of its own,
named like its header (Tube in tube.h), takes the header's top comment. The text, its line
breaks kept, becomes a string-literal macro of OUTPUT.h, used in the bindings as

    DOC(Tube)                  the class Tube (its comment block)
    DOC(Tube, volume)          the member volume of Tube; DOC(Tube, Tube) a constructor
    DOC(tube_from_bounds)      a free function
    DOC(Tube, op_call)         an operator: op_call, op_index, op_add, ... (OPERATORS below)

Overloads: DOC(Tube, inverse) is the text of every documented overload of that name, joined
(distinct texts in header order, separated by a blank line). Each documented overload also gets
its own text, named by its parameter types: DOC(Tube, inverse, Interval_Tube) is
`Interval inverse(const Interval& y, const Tube& v) const` (tag: the short type names joined by
'_'; `void` for no parameter; see type_tag). A docstring can take a Python-only suffix by string
literal concatenation: `DOC(Tube, slice) "\\nPython: negative k is an error."`.

Parsing is deliberately small (no libclang): one pass over the characters, braces tracked,
function bodies and initializers skipped. scripts/docstring_codemod.py and
tests/python/test_docstrings_once.py import entities() from here.
"""
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PUBLIC = ROOT / "include" / "sillage"

OPERATORS = {
    "()": "op_call", "[]": "op_index", "+": "op_add", "-": "op_sub", "*": "op_mul", "/": "op_div",
    "+=": "op_iadd", "-=": "op_isub", "*=": "op_imul", "/=": "op_idiv", "&": "op_and", "|": "op_or",
    "&=": "op_iand", "|=": "op_ior", "==": "op_eq", "!=": "op_ne", "<": "op_lt", "<=": "op_le",
    ">": "op_gt", ">=": "op_ge", "<<": "op_shl", "=": "op_assign", "!": "op_not", "bool": "op_bool",
}
KEYWORDS = {"const", "constexpr", "static", "inline", "virtual", "explicit", "friend", "noexcept",
            "override", "final", "typename", "unsigned", "signed", "volatile", "mutable", "struct",
            "class", "enum", "std", "sillage", "detail", "default", "delete", "nodiscard"}
SMART = {"shared_ptr", "unique_ptr", "weak_ptr", "optional", "reference_wrapper"}


class Entity:
    """One documented declaration: key = (class, name) or (name,) for a class / free function."""

    def __init__(self, key, text, params, header, line):
        self.key, self.text, self.params, self.header, self.line = key, text, params, header, line

    def __repr__(self):
        return f"{'::'.join(self.key)}({', '.join(self.params or [])}) {self.header}:{self.line}"


def split_top(s, sep=","):
    """s split at the separators outside (), <>, {}, []."""
    out, depth, cur = [], 0, ""
    for ch in s:
        if ch in "(<{[":
            depth += 1
        elif ch in ")>}]":
            depth -= 1
        if ch == sep and depth == 0:
            out.append(cur)
            cur = ""
        else:
            cur += ch
    if cur.strip():
        out.append(cur)
    return out


def short_type(t):
    """The short name of a C++ type: const, &, *, namespaces and smart pointers dropped,
    other templates as outer_inner (std::vector<Interval> -> vector_Interval)."""
    t = re.sub(r"\b(const|volatile|typename|struct|class)\b", " ", t)
    t = re.sub(r"\b[A-Za-z_]\w*::", "", t)  # namespaces and enclosing classes
    t = t.replace("&", " ").replace("*", " ").strip()
    m = re.match(r"^(\w+)\s*<(.*)>$", t)
    if m:
        inner = "_".join(short_type(a) for a in split_top(m.group(2)))
        return inner if m.group(1) in SMART else f"{m.group(1)}_{inner}"
    t = re.sub(r"\s+", "_", t)
    t = re.sub(r"\W", "_", t)
    return t.strip("_")


def param_type(p):
    """The type of one parameter declaration (default value and parameter name dropped)."""
    p = split_top(p, "=")[0].strip() if "=" in p else p.strip()
    p = re.sub(r"\[\[.*?\]\]", "", p).strip()
    m = re.match(r"^(.*?[\w>&*\s])\s*\b([A-Za-z_]\w*)$", p)
    if m and re.search(r"[\w>&*]", m.group(1)) and m.group(1).strip() not in ("const", "unsigned", "signed"):
        head = m.group(1).strip()
        if head and not head.endswith("::"):
            return head
    return p


def type_tag(params):
    """The overload tag of a parameter list: short types joined by '_' ('void' when none)."""
    return "_".join(short_type(p) for p in params) if params else "void"


def comment_text(lines):
    """The docstring of a comment: the lines after a section heading ('---- arithmetic ----')
    if there is one; a lint marker ('NOLINT: implicit, ...') is not documentation."""
    heads = [i for i, x in enumerate(lines) if x.lstrip().startswith("----")]
    if heads:
        lines = lines[heads[-1] + 1:]
    text = "\n".join(lines).strip()
    text = re.sub(r"^NOLINT(\([^)]*\))?:?\s*", "", text)
    return "" if text.startswith("implicit") else text


class Scanner:
    """Walks one header: scopes (namespace / class / enum), comments, declarations."""

    def __init__(self, path):
        self.path = path
        self.src = Path(path).read_text()
        self.out = []
        self.trailing_for_buf = None  # comments met inside the declaration being read

    def run(self):
        src, n = self.src, len(self.src)
        i, line = 0, 1
        scopes = [("file", None, "public")]  # (kind, name, access)
        buf, buf_line = "", None  # the declaration being read, the line it started on
        block, block_end = [], -10  # the current comment block, its last line
        lead, last_decl = None, None  # comment attached to buf; the last declaration (line, entity)
        ended_on = -1  # line on which the last declaration ended (for trailing comments)
        tline, tcol = -10, -1  # line and column of the last trailing comment
        while i < n:
            ch = src[i]
            if ch == "\n":
                line += 1
                i += 1
                continue
            if src.startswith("//", i):
                j = src.find("\n", i)
                j = n if j < 0 else j
                text = src[i + 2:j]
                text = text[1:] if text.startswith(" ") else text
                col = i - (src.rfind("\n", 0, i) + 1)
                if buf.strip() and buf_line is not None:  # trailing, inside a declaration
                    self.trailing_for_buf = (self.trailing_for_buf or []) + [text]
                elif ended_on == line and last_decl is not None:  # trailing, after `;`
                    if last_decl.text == "" or last_decl.trailing:
                        raw = (last_decl.raw + [text]) if last_decl.trailing else [text]
                        last_decl.raw, last_decl.text, last_decl.trailing = raw, comment_text(raw), True
                        tline, tcol = line, col
                elif line == tline + 1 and col == tcol and last_decl is not None and last_decl.trailing:
                    last_decl.raw.append(text)  # a trailing comment going on below, aligned
                    last_decl.text = comment_text(last_decl.raw)
                    tline = line
                else:
                    if block_end == line - 1 and block:
                        block.append(text)
                    else:
                        block = [text]
                    block_end = line
                i = j
                continue
            if src.startswith("/*", i):
                j = src.find("*/", i + 2)
                j = n if j < 0 else j + 2
                line += src.count("\n", i, j)
                i = j
                continue
            if ch == "#" and not buf.strip():
                j = src.find("\n", i)
                while j > 0 and src[j - 1] == "\\":
                    j = src.find("\n", j + 1)
                j = n if j < 0 else j
                i = j
                block = []
                continue
            if ch in "\"'":
                j = i + 1
                while j < n and src[j] != ch:
                    j += 2 if src[j] == "\\" else 1
                buf += src[i:j + 1]
                i = j + 1
                continue
            if not buf.strip() and not ch.isspace():
                buf_line = line
                lead = comment_text(block) if block and block_end == line - 1 else None
                block = []
                self.trailing_for_buf = None
            kind = scopes[-1][0]
            if ch == "{":
                head = " ".join(buf.split())
                m_ns = re.match(r"^(inline\s+)?namespace\s*(\w*)", head)
                # no "(" before a base clause: `struct S f(...) {` is a function; a base's template arguments may hold one
                m_cls = re.match(r"^(template\s*<.*>\s*)?(class|struct)\s+(?:\[\[.*?\]\]\s*)?(\w+)\b(?![^:]*\()", head)
                m_enum = re.match(r"^enum\s+(class\s+|struct\s+)?(\w+)", head)
                if m_ns and "(" not in head:
                    scopes.append(("ns", m_ns.group(2), "public"))
                elif m_cls:
                    name = m_cls.group(3)
                    ent = self.emit((name,), lead, None, buf_line, scopes, head)
                    scopes.append(("class", name, "private" if m_cls.group(2) == "class" else "public"))
                    last_decl = ent
                elif m_enum:
                    ent = self.emit((m_enum.group(2),), lead, None, buf_line, scopes, head)
                    scopes.append(("enum", m_enum.group(2), "public"))
                    last_decl = ent
                else:  # a function body, an initializer: skip the braces
                    j, depth = i, 0
                    while j < n:
                        c = src[j]
                        if c == "\n":
                            line += 1
                        elif c == "{":
                            depth += 1
                        elif c == "}":
                            depth -= 1
                            if depth == 0:
                                break
                        elif src.startswith("//", j):
                            k = src.find("\n", j)
                            j = (n if k < 0 else k) - 1
                        elif c in "\"'":
                            j += 1
                            while j < n and src[j] != c:
                                j += 2 if src[j] == "\\" else 1
                        j += 1
                    i = j + 1
                    paren = buf.count("(") - buf.count(")")
                    if paren == 0 and re.search(r"\)\s*(const|noexcept|override|final|\s)*(->\s*[\w:<>,\s&*]+)?\s*(:.*)?$",
                                                head, re.S):
                        last_decl = self.declaration(head, lead, buf_line, scopes)
                        ended_on = line
                        buf, buf_line, lead = "", None, None
                    else:
                        buf += "{}"
                    continue
                buf, buf_line, lead = "", None, None
                i += 1
                continue
            if ch == "}":
                if kind == "enum" and buf.strip():
                    last_decl = self.declaration(" ".join(buf.split()), lead, buf_line, scopes)
                if len(scopes) > 1:
                    scopes.pop()
                ended_on, last_decl = line, None
                buf, buf_line, lead = "", None, None
                i += 1
                continue
            if ch == ";" or (ch == "," and kind == "enum"):
                last_decl = self.declaration(" ".join(buf.split()), lead, buf_line, scopes)
                ended_on = line
                buf, buf_line, lead = "", None, None
                i += 1
                continue
            if ch == ":" and kind == "class" and re.match(r"^\s*(public|private|protected)\s*$", buf):
                scopes[-1] = (kind, scopes[-1][1], buf.strip())
                buf, buf_line, lead = "", None, None
                i += 1
                continue
            buf += ch
            i += 1
        return self.out

    def in_public_api(self, scopes):
        for kind, name, access in scopes:
            if kind == "ns" and name == "detail":
                return False
            if kind == "class" and access != "public":
                return False
        return any(k == "ns" and n == "sillage" for k, n, _ in scopes)

    def emit(self, key, text, params, line, scopes, head=""):
        trailing = self.trailing_for_buf
        ent = Entity(key, text or "", params, self.path, line)
        ent.trailing, ent.raw = False, []
        if trailing and not text:
            ent.text, ent.trailing = comment_text(trailing), True
        ent.public = self.in_public_api(scopes)
        self.out.append(ent)
        return ent

    def declaration(self, decl, lead, line, scopes):
        """Registers one declaration ended by ';' (or a function definition)."""
        kind, owner = scopes[-1][0], scopes[-1][1]
        decl = re.sub(r"^template\s*<.*?>\s*(?=[A-Za-z])", "", decl)
        m_alias = re.match(r"^using\s+(\w+)\s*=", decl)
        if m_alias and kind in ("class", "ns", "file"):  # a type alias (CountRun = RunResult<CountResult>)
            return self.emit((owner, m_alias.group(1)) if kind == "class" else (m_alias.group(1),), lead, None,
                             line, scopes)
        if not decl or decl.startswith(("using ", "typedef ", "friend ", "static_assert", "return ")) or \
                re.search(r"=\s*delete$", decl):
            self.trailing_for_buf = None
            return None
        if re.match(r"^(class|struct|enum)\b[^({=]*$", decl):  # forward declaration
            return None
        if kind == "enum":
            name = re.match(r"^(\w+)", decl)
            return self.emit((owner, name.group(1)), lead, None, line, scopes) if name else None
        if kind not in ("class", "ns", "file"):
            return None
        body = decl.split("{}")[0] if "{}" in decl and "(" not in decl.split("{}")[0] else decl
        m_op = re.search(r"\boperator\s*(\(\)|\[\]|[-+*/&|=!<>]+|bool)\s*\(", body)
        if m_op:
            name = OPERATORS.get(m_op.group(1).strip())
            if name is None:
                return None
            open_at = m_op.end() - 1
        else:
            m = re.search(r"(~?\b[A-Za-z_]\w*)\s*\(", body)
            if m is None or re.match(r"^[^(]*=", body[:m.start()]):  # a data member / constant
                m_var = re.match(r"^(.*?)\b([A-Za-z_]\w*)\s*(\[[^\]]*\])?\s*(=.*|\{.*\})?$", body)
                if m_var is None or m_var.group(2) in KEYWORDS:
                    return None
                key = (owner, m_var.group(2)) if kind == "class" else (m_var.group(2),)
                return self.emit(key, lead, None, line, scopes)
            name = m.group(1)
            if name.startswith("~") or name in KEYWORDS or name in ("decltype", "alignas", "sizeof"):
                return None
            open_at = m.end() - 1
        depth, j = 0, open_at
        while j < len(body):
            depth += body[j] == "(" and 1 or (body[j] == ")" and -1 or 0)
            if depth == 0:
                break
            j += 1
        inner = body[open_at + 1:j].strip()
        params = [param_type(p) for p in split_top(inner)] if inner and inner != "void" else []
        key = (owner, name) if kind == "class" else (name,)
        return self.emit(key, lead, params, line, scopes)


def file_comment(path):
    """The comment block at the top of a header (after #pragma once), or ''."""
    lines, started = [], False
    for raw in Path(path).read_text().splitlines():
        s = raw.strip()
        if s.startswith("#pragma") and not started:
            continue
        if s.startswith("//"):
            started = True
            lines.append(s[3:] if s.startswith("// ") else s[2:])
        elif started or s:
            break
    return comment_text(lines)


def snake(name):
    return re.sub(r"(?<=[a-z0-9])([A-Z])", r"_\1", name).lower()


def entities(headers=None, all_entities=False):
    """Every documented public entity of the headers (default: include/sillage/**/*.h).
    A class without a comment of its own named like its header (Tube in tube.h) takes the
    header's top comment. all_entities: the undocumented ones too (text '')."""
    headers = headers or sorted(PUBLIC.rglob("*.h"))
    out = []
    for h in headers:
        ents = [e for e in Scanner(str(h)).run() if e.public]
        for e in ents:
            if not e.text and len(e.key) == 1 and e.params is None and snake(e.key[0]) == Path(h).stem:
                e.text = file_comment(h)
        out += [e for e in ents if e.text or all_entities]
    return out


def table(ents):
    """{key: [entity, ...]} in header order."""
    t = {}
    for e in ents:
        t.setdefault(e.key, []).append(e)
    return t


def macro_name(key):
    return "SILLAGE_DOC_" + "_".join(key)


def c_literal(text):
    s = text.replace("\\", "\\\\").replace('"', '\\"')
    return '"' + s.replace("\n", '\\n"\n    "') + '"'


def joined(group):
    texts = []
    for e in group:
        if e.text not in texts:
            texts.append(e.text)
    return "\n\n".join(texts)


def render(ents):
    out = ["// Generated by scripts/gen_docstrings.py from the comments of include/sillage/**/*.h.",
           "// Do not edit: change the header comment (docs/python.md, 'Docstrings').",
           "#pragma once", "",
           "#define SILLAGE_DOC_PICK(_1, _2, _3, NAME, ...) NAME",
           "#define SILLAGE_DOC1(a) SILLAGE_DOC_##a",
           "#define SILLAGE_DOC2(a, b) SILLAGE_DOC_##a##_##b",
           "#define SILLAGE_DOC3(a, b, c) SILLAGE_DOC_##a##_##b##_##c",
           "#define DOC(...) SILLAGE_DOC_PICK(__VA_ARGS__, SILLAGE_DOC3, SILLAGE_DOC2, SILLAGE_DOC1, )(__VA_ARGS__)",
           ""]
    seen = {}
    for key, group in table(ents).items():
        names = [(key, joined(group))]
        if len(group) > 1 or group[0].params is not None:
            for e in group:
                if e.params is not None:
                    names.append((key + (type_tag(e.params),), e.text))
        for k, text in names:
            name = macro_name(k)
            if name in seen:
                if seen[name] != text:  # same tag twice (e.g. const / non-const): keep both texts
                    seen[name] = seen[name] + "\n\n" + text
                continue
            seen[name] = text
    for name, text in seen.items():
        out.append(f"#define {name} \\\n    {c_literal(text)}".replace('"\n    "', '" \\\n    "'))
    return "\n".join(out) + "\n"


def macro_names(ents):
    """The names of the macros render() defines."""
    return set(re.findall(r"^#define (SILLAGE_DOC_\w+) ", render(ents), re.M))


def used_names(text):
    """The macro names of the DOC(...) uses in a source text, those of the name-once macros of
    python/src/bindings.h included: SILLAGE_DEF(T, name, ...) uses DOC(T, name), SILLAGE_FIELDS(T, a, b)
    DOC(T, a) and DOC(T, b), SILLAGE_FN(name, ...) DOC(name)."""
    names = {macro_name(tuple(a.strip() for a in m.group(1).split(",")))
             for m in re.finditer(r"\bDOC\(([\w\s,]+)\)", text)}
    for m in re.finditer(r"\bSILLAGE_(DEF|DEF_STATIC|DEFS|FIELDS|READONLY_FIELDS|PROPERTIES)\(([\w\s,]+)", text):
        cls, *members = [a.strip() for a in m.group(2).split(",") if a.strip()]
        if m.group(1) in ("DEF", "DEF_STATIC"):
            members = members[:1]
        names |= {macro_name((cls, x)) for x in members}
    return names | {macro_name((m.group(1),)) for m in re.finditer(r"\bSILLAGE_FN\(\s*(\w+)", text)}


def main(argv):
    if argv[:1] == ["--list"]:
        for e in entities([Path(p) for p in argv[1:]] or None):
            print(e)
        return 0
    if len(argv) < 1:
        print(__doc__)
        return 2
    output, headers = Path(argv[0]), [Path(p) for p in argv[1:]]
    text = render(entities(headers or None))
    if not output.exists() or output.read_text() != text:
        output.parent.mkdir(parents=True, exist_ok=True)
        output.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

"""Every code block of README.md and docs/*.md runs.

```python blocks: run in order in one namespace per file (a block may use what
an earlier block of the same file defined), in a temporary directory.

```cpp blocks: a block with `int main` is a complete program, compiled and run
on its own. Any other block must be marked by an HTML comment on the line just
before it:

  <!-- doc-test: fragment -->   statements, wrapped in a main() that includes
                                 sillage/sillage.h and uses namespace sillage
  <!-- doc-test: continues -->  a fragment that goes on from the previous
                                 fragment (in a nested scope of it, so it
                                 sees its names and may reuse them)
  <!-- doc-test: skip -->       a synopsis (declarations, `...`): not compiled

All fragments go into one translation unit (one function per fragment, #line
directives point errors back at the .md file), so compiling stays cheap.

A python block whose first line is `# raises` must raise (sillage.Error or a
TypeError/ValueError); the blocks after it still run.
"""
import glob
import json
import os
import re
import shlex
import subprocess
import sys

import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
DOC_FILES = [os.path.join(ROOT, "README.md")] + sorted(glob.glob(os.path.join(ROOT, "docs", "*.md")))
BLOCK = re.compile(r"^```(python|cpp|c\+\+)[ \t]*\n(.*?)^```", re.S | re.M)
MARK = re.compile(r"<!--\s*doc-test:\s*(\w+)")


def blocks(path):
    """(language, code, first line number of the code, marker or None) for each block."""
    text = open(path, encoding="utf-8").read()
    out = []
    for m in BLOCK.finditer(text):
        before = text[: m.start()].rstrip("\n").splitlines()
        mark = MARK.search(before[-1]) if before else None
        lang = "cpp" if m.group(1) in ("cpp", "c++") else "python"
        line = text.count("\n", 0, m.start(2)) + 1
        out.append((lang, m.group(2), line, mark.group(1) if mark else None))
    return out


def rel(path):
    return os.path.relpath(path, ROOT)


PY_FILES = [p for p in DOC_FILES if any(b[0] == "python" for b in blocks(p))]


@pytest.mark.parametrize("path", PY_FILES, ids=rel)
def test_python_blocks_run(path, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    namespace = {"__name__": "__doc_block__"}
    for lang, code, line, _ in blocks(path):
        if lang != "python":
            continue
        where = f"{rel(path)}:{line}"
        compiled = compile("\n" * (line - 1) + code, rel(path), "exec")
        if code.lstrip().startswith("# raises"):
            with pytest.raises((ValueError, TypeError)):
                exec(compiled, namespace)
            continue
        try:
            exec(compiled, namespace)
        except Exception as e:  # noqa: BLE001 - report which block failed
            pytest.fail(f"python block at {where} raised {type(e).__name__}: {e}")
    try:
        import matplotlib.pyplot as plt

        plt.close("all")
    except ImportError:
        pass


def test_cpp_blocks_are_marked():
    unmarked = [
        f"{rel(p)}:{line}"
        for p in DOC_FILES
        for lang, code, line, mark in blocks(p)
        if lang == "cpp" and "int main" not in code and mark not in ("fragment", "continues", "skip")
    ]
    assert not unmarked, "C++ blocks that are neither programs nor marked (<!-- doc-test: ... -->): " + ", ".join(
        unmarked)


def build_dir():
    """The build tree of the compiled module on sys.path (build/python/sillage -> build)."""
    import sillage

    d = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(sillage.__file__))))
    return d if os.path.isfile(os.path.join(d, "compile_commands.json")) else None


def compile_flags(bdir):
    """The flags the library itself is compiled with that a consumer needs (-I, -D, -std, -m, -f)."""
    for entry in json.load(open(os.path.join(bdir, "compile_commands.json"))):
        if "/src/sillage/" in entry["file"]:
            args = entry.get("arguments") or shlex.split(entry["command"])
            keep = [a for a in args if a.startswith(("-I", "-D", "-std=", "-m", "-ffp-contract"))]
            return keep + ["-I" + os.path.join(ROOT, "src")]
    pytest.skip("no library entry in compile_commands.json")


def cpp_programs():
    """(name, source) of the complete programs and of one program holding all the fragments."""
    programs, functions = [], []
    for p in DOC_FILES:
        for lang, code, line, mark in blocks(p):
            if lang != "cpp" or mark == "skip":
                continue
            directive = f'#line {line} "{rel(p)}"\n'
            if "int main" in code:
                programs.append((f"{rel(p)}:{line}", directive + code))
            elif mark == "continues" and functions:  # in a nested scope: it may reuse names
                functions[-1][1].append("{\n" + directive + code + "\n}")
            elif mark in ("fragment", "continues"):
                functions.append((f"{rel(p)}:{line}", [directive + code]))
    if functions:
        src = ['#include <iostream>\n#include <memory>\n#include <vector>\n#include "sillage/sillage.h"\n'
               "using namespace sillage;\n"]
        for k, (_, parts) in enumerate(functions):
            src.append(f"static void fragment_{k}() {{\n" + "\n".join(parts) + "\n}\n")
        src.append("int main() {\n" + "".join(f"  fragment_{k}();\n" for k in range(len(functions))) + "}\n")
        programs.append(("fragments", "".join(src)))
    return programs


@pytest.mark.parametrize("name,source", [pytest.param(n, s, id=n) for n, s in cpp_programs()])
def test_cpp_blocks_compile_and_run(name, source, tmp_path):
    bdir = build_dir()
    if bdir is None:
        pytest.skip("no build tree next to the compiled module")
    # The umbrella's static libraries, in link order (CMakeLists.txt).
    libs = [os.path.join(bdir, f"libsillage_{t}.a") for t in ("problem", "missions", "figures", "core")]
    if not all(os.path.isfile(lib) for lib in libs):
        pytest.skip("the libsillage_*.a are not built")
    cpp = tmp_path / "block.cpp"
    cpp.write_text(source)
    exe = tmp_path / "block"
    cmd = ["g++", "-O0", *compile_flags(bdir), str(cpp), "-o", str(exe), *libs, "-ltbb", "-lpthread"]
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=tmp_path)
    assert r.returncode == 0, f"{name} does not compile:\n{r.stderr[-4000:]}"
    run = subprocess.run([str(exe)], capture_output=True, text=True, cwd=tmp_path, timeout=120)
    assert run.returncode == 0, f"{name} exits with {run.returncode}:\n{run.stdout[-2000:]}\n{run.stderr[-2000:]}"


if __name__ == "__main__":
    sys.exit(pytest.main([__file__, "-q"]))


def python_spans(path):
    """Inline `code` of the prose and the python blocks of a file (C++ blocks left out)."""
    text = open(path, encoding="utf-8").read()
    prose = re.sub(r"^```.*?^```", "", text, flags=re.S | re.M)
    return re.findall(r"`([^`\n]+)`", prose) + [code for lang, code, _, _ in blocks(path) if lang == "python"]


def test_docs_name_what_the_module_has():
    """`sillage.x` / `sl.x` and `Class.attr` of a sillage class, in the docs, exist in the module."""
    import inspect

    import sillage
    from sillage import _sillage

    submodules = {"plot", "plot_tube", "plot_loops", "testing", "_sillage", "h", "py", "cpp",  # and file names
                  "distributed", "distributed_tasks", "distributed_run", "distributed_grid", "distributed_report",
                  "distributed_paving"}
    missing = []
    for path in DOC_FILES:
        for span in python_spans(path):
            for name in re.findall(r"(?<![/\w.])(?:sl|sillage)\.([A-Za-z_]\w*)\b(?!/)", span):
                if name not in submodules and not hasattr(sillage, name):
                    missing.append(f"{rel(path)}: sillage.{name}")
            for cls, attr in re.findall(r"\b([A-Z][A-Za-z0-9]+)\.([a-z_]\w*)", span):
                obj = getattr(_sillage, cls, None)
                if inspect.isclass(obj) and not hasattr(obj, attr):
                    missing.append(f"{rel(path)}: {cls}.{attr}")
    assert not missing, "names in the docs that the module does not have:\n  " + "\n  ".join(sorted(set(missing)))

"""The public / internal split of the C++ headers.

Public headers live in include/sillage/ and are installed; internal ones live
beside the sources in src/sillage/, are never installed and declare their names
in namespace sillage::detail. sillage.h brings in every public header but the
contractor test kit (include/sillage/testing/, which needs GoogleTest). The
folders are grouped into library targets (the sillage_add_layers() lines of
CMakeLists.txt); a file includes only headers of its target and of the targets
below it.
"""
import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]
INCLUDE = ROOT / "include"
SRC = ROOT / "src"
TESTING = "sillage/testing/"  # installed, not in sillage.h (scripts/update_sillage_h.py)
INCLUDE_RE = re.compile(r'^\s*#\s*include\s+"(sillage/[^"]+)"', re.M)


def headers(base):
    return sorted(str(p.relative_to(base)) for p in (base / "sillage").rglob("*.h"))


def test_umbrella_header_includes_every_public_header():
    public = {h for h in headers(INCLUDE) if not h.startswith(TESTING)} - {"sillage/sillage.h"}
    umbrella = set(INCLUDE_RE.findall((INCLUDE / "sillage" / "sillage.h").read_text()))
    assert sorted(public - umbrella) == [], "missing from sillage.h: run scripts/update_sillage_h.py"
    assert sorted(umbrella - public) == [], "sillage.h includes headers that are not public (or the test kit)"


def test_the_test_kit_is_public_and_left_out_of_sillage_h():
    kit = [h for h in headers(INCLUDE) if h.startswith(TESTING)]
    assert "sillage/testing/contractor_kit.h" in kit
    umbrella = (INCLUDE / "sillage" / "sillage.h").read_text()
    assert "gtest" not in umbrella and TESTING not in umbrella


def test_public_headers_include_only_public_headers():
    public = set(headers(INCLUDE))
    bad = []
    for h in public:
        for inc in INCLUDE_RE.findall((INCLUDE / h).read_text()):
            if inc not in public:
                bad.append(f"{h} includes {inc}")
    assert bad == []


def test_a_header_is_either_public_or_internal():
    both = set(headers(INCLUDE)) & set(headers(SRC))
    assert sorted(both) == []


def test_sources_live_in_src_only():
    assert list((INCLUDE / "sillage").rglob("*.cpp")) == []


def test_internal_headers_declare_in_the_detail_namespace():
    bad = []
    for h in headers(SRC):
        text = (SRC / h).read_text()
        for ns in re.findall(r"^namespace ([\w:]+) \{", text, re.M):
            if ns != "sillage::detail":
                bad.append(f"{h}: namespace {ns}")
        for ns in re.findall(r"^\s+namespace (\w+) \{", text, re.M):
            bad.append(f"{h}: nested namespace {ns}")
    assert bad == []


def test_one_detail_namespace():
    """Internal names live in sillage::detail, not in namespaces of their own."""
    bad = []
    for base in (INCLUDE, SRC):
        for p in (base / "sillage").rglob("*"):
            if p.suffix not in (".h", ".cpp"):
                continue
            for ns in re.findall(r"namespace (?:sillage::)?(\w+) \{", p.read_text()):
                # kit: the contractor test kit's namespace (sillage::kit)
                if ns not in ("sillage", "detail", "rounding") and not (ns == "kit" and TESTING in str(p)):
                    bad.append(f"{p.relative_to(ROOT)}: namespace {ns}")
    assert bad == []


LAYERS_RE = re.compile(r"^sillage_add_layers\((\w+) FOLDERS ([^)]*?)(?: DEPENDS ([^)]*))?\)", re.M)


def targets():
    """{target: (folders, names of the targets it depends on)}, from CMakeLists.txt."""
    found = LAYERS_RE.findall((ROOT / "CMakeLists.txt").read_text())
    table = {name: (folders.split(), deps.split()) for name, folders, deps in found}
    # The contractor test kit: header-only (no library), installed, on the core.
    table["testing"] = (["testing"], ["core"])
    return table


def folder_of(path):
    """The layer folder of sillage/<folder>/x.h, "." for sillage/x.h."""
    parts = pathlib.PurePosixPath(path).parts
    return parts[1] if len(parts) > 2 else "."


def test_every_layer_folder_belongs_to_one_target():
    owners = [f for folders, _ in targets().values() for f in folders]
    assert len(owners) == len(set(owners)), f"a folder in two targets: {owners}"
    on_disk = {"."} | {p.name for base in (INCLUDE, SRC) for p in (base / "sillage").iterdir() if p.is_dir()}
    assert sorted(on_disk - set(owners)) == [], "folders of no target (not built): add them to CMakeLists.txt"


def test_includes_follow_the_targets():
    """A header or source of a lower target includes no header of a higher one (file:line)."""
    table = targets()
    target_of = {f: name for name, (folders, _) in table.items() for f in folders}

    def allowed(name):  # the target and everything it depends on, transitively
        out = {name}
        for dep in table[name][1]:
            out |= allowed(dep)
        return out

    bad = []
    for base in (INCLUDE, SRC):
        for p in sorted((base / "sillage").rglob("*")):
            if p.suffix not in (".h", ".cpp") or p == INCLUDE / "sillage" / "sillage.h":
                continue  # sillage.h: the umbrella header, of every target
            own = target_of[folder_of(p.relative_to(base))]
            for n, line in enumerate(p.read_text().splitlines(), 1):
                m = INCLUDE_RE.match(line)
                if m and target_of.get(folder_of(m.group(1))) not in allowed(own):
                    bad.append(f"{p.relative_to(ROOT)}:{n}: {own} includes {m.group(1)}")
    assert bad == [], "includes against the layering:\n  " + "\n  ".join(bad)

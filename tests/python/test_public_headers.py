"""The public / internal split of the C++ headers.

Public headers live in include/sillage/ and are installed; internal ones live
beside the sources in src/sillage/, are never installed and declare their names
in namespace sillage::detail. sillage.h brings in every public header but the
contractor test kit (include/sillage/testing/, which needs GoogleTest).
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

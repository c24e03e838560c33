#!/usr/bin/python3
"""Writes include/sillage/sillage.h: every public header, grouped by layer.

Run it after adding or removing a public header; tests/python/test_public_headers.py
fails while sillage.h and include/sillage/ disagree. The contractor test kit
(include/sillage/testing/, installed) is left out: it needs GoogleTest.
"""
import pathlib

ROOT = pathlib.Path(__file__).resolve().parents[1] / "include"
# Installed but not in sillage.h: included by a contractor's tests only.
NOT_IN_UMBRELLA = ["testing"]
LAYERS = ["interval", "expr", "ctc", "paving", "tube", "cn", "dynamics", "io", "loops", "slam",
          "problem", "figures", "missions"]


def main():
    headers = sorted(str(p.relative_to(ROOT)) for p in ROOT.rglob("*.h")
                     if p.name != "sillage.h" and p.relative_to(ROOT).parts[1] not in NOT_IN_UMBRELLA)
    lines = ["#pragma once",
             "// sillage: guaranteed state estimation by constraint programming over",
             "// intervals and tubes. This header brings in the whole public API: every",
             "// header under include/sillage/ (written by scripts/update_sillage_h.py).",
             ""]
    lines += [f'#include "{h}"' for h in headers if h.count("/") == 1]
    layers = LAYERS + sorted({h.split("/")[1] for h in headers if h.count("/") > 1} - set(LAYERS))
    for layer in layers:
        group = [h for h in headers if h.startswith(f"sillage/{layer}/")]
        if group:
            lines += [""] + [f'#include "{h}"' for h in group]
    (ROOT / "sillage" / "sillage.h").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()

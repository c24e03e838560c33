"""Shared helpers of the Python examples: the --out folder and the RESULT line
that examples/run_demo.py reads."""
import argparse
import json
from pathlib import Path


def out_dir(description):
    ap = argparse.ArgumentParser(description=description)
    ap.add_argument("--out", default="out", help="folder for the figures")
    args = ap.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    return out


def print_result(name, result, check, figures=()):
    print("RESULT " + json.dumps({"name": name, "result": result, "check": bool(check),
                                  "figures": [list(f) for f in figures]}))

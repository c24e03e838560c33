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


def out_dir_and_step(description, dt, ratio=0.0):
    """--out (created), --dt (slice width) and --ratio (network wake ratio): (out, args)."""
    ap = argparse.ArgumentParser(description=description)
    ap.add_argument("--out", default="out", help="folder for the figures")
    ap.add_argument("--dt", type=float, default=dt, help="slice width")
    ap.add_argument("--ratio", type=float, default=ratio, help="wake ratio of the network (0: true fixed point)")
    args = ap.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    return out, args


def out_dir_and_data(description, dataset, name, extra_args=None):
    """--out (created) and --data (default ../shared/data/<dataset> beside the repository):
    (out, folder, args), or None after reporting the example as skipped when the folder has no
    odometry.csv. extra_args(parser) may add options."""
    ap = argparse.ArgumentParser(description=description)
    ap.add_argument("--out", default="out", help="folder for the figures")
    ap.add_argument("--data", default=str(Path(__file__).resolve().parents[3] / "shared" / "data" / dataset),
                    help="the data folder")
    if extra_args:
        extra_args(ap)
    args = ap.parse_args()
    out, folder = Path(args.out), Path(args.data)
    out.mkdir(parents=True, exist_ok=True)
    if not (folder / "odometry.csv").exists():
        print(f"no {dataset} data at {folder} (pass --data DIR)")
        print_result(name, "skipped: no data", True)
        return None
    return out, folder, args


def print_result(name, result, check, figures=()):
    print("RESULT " + json.dumps({"name": name, "result": result, "check": bool(check),
                                  "figures": [list(f) for f in figures]}))


def rk4(f, x0, h, n):
    """n classical Runge-Kutta steps of size h of x' = f(t, x) from x0 at t = 0 (numpy
    arrays of any shape); returns the n+1 states stacked along a new first axis."""
    import numpy as np
    x = np.asarray(x0, dtype=float)
    out = np.empty((n + 1,) + x.shape)
    out[0] = x
    for j in range(n):
        t = j * h
        k1 = f(t, x)
        k2 = f(t + h / 2, x + h / 2 * k1)
        k3 = f(t + h / 2, x + h / 2 * k2)
        k4 = f(t + h, x + h * k3)
        x = x + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        out[j + 1] = x
    return out

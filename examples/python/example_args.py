"""Shared helpers of the Python examples: the --out folder, the RESULT line
that examples/run_demo.py reads, the exit status, and the checks.

Every example exits non-zero when its check fails (print_result). An empty
network is an answer, never a success: check_stats prints why it is empty
(stats.emptiness), and a truth check on an empty or unbounded enclosure fails
(enclosure_ok). SILLAGE_EXAMPLE_TIGHTEN=f (default 1) tightens the stated
error bounds that an example passes through bound(): with f = 0.001 the bounds
are too tight for the truth, so the check must fail (tests/python prove that
each example then exits non-zero)."""
import argparse
import json
import math
import os
import sys
import types
from pathlib import Path

import sillage


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


def out_dir_and_data(description, dataset, name, extra_args=None, files=()):
    """--out (created) and --data: (out, folder, args), or None after reporting the example as
    skipped. A folder named with --data must hold the data set (`files`, paths inside it): a missing
    folder or file is bad input (exit 2 with what is missing, data_error). Without --data the
    default ../shared/data/<dataset> beside the repository is read; when it is absent (a checkout
    without the data sets) the example is reported as skipped. extra_args(parser) may add options."""
    ap = argparse.ArgumentParser(description=description)
    ap.add_argument("--out", default="out", help="folder for the figures")
    ap.add_argument("--data", help=f"the {dataset} data folder (default: ../shared/data/{dataset} beside the "
                                   "repository)")
    if extra_args:
        extra_args(ap)
    args = ap.parse_args()
    out = Path(args.out)
    folder = Path(args.data) if args.data else Path(__file__).resolve().parents[3] / "shared" / "data" / dataset
    what = f"--data {folder}" if args.data else f"the data folder {folder}"
    if not args.data and not folder.exists():
        out.mkdir(parents=True, exist_ok=True)
        print(f"no {dataset} data at {folder} (pass --data DIR; the data sets live in ../shared/data "
              "beside the repository)")
        print_result(name, "skipped: no data", True, skipped=True)
        return None
    if not folder.is_dir():
        data_error(ap, f"{what}: no such folder (expected the {dataset} data set)")
    missing = [f for f in files if not (folder / f).is_file()]
    if missing:
        data_error(ap, f"{what}: not the {dataset} data set (missing {', '.join(missing)})")
    out.mkdir(parents=True, exist_ok=True)
    return out, folder, args


def data_error(ap, message):
    """Bad input in the data: "<program>: <message>" first, then the usage line, exit 2, as the
    C++ examples' usage_error (argparse's error() would put the usage first)."""
    print(f"{Path(sys.argv[0]).stem}: {message}", file=sys.stderr)
    ap.print_usage(sys.stderr)
    sys.exit(2)


def run(main):
    """The entry of every example: exits with main()'s status (None: 0). A sillage.Error that escapes
    the example is bad input (a data file with a missing column, no rows, a cell that is not a
    number: CsvTable names the file, line and column): its message on stderr and status 2, as
    argparse does for a bad command line, not a traceback. An empty result is not an Error: the
    examples print it and exit 1 (print_result)."""
    try:
        status = main()
    except sillage.Error as e:
        sys.stdout.flush()
        print(f"{Path(sys.argv[0]).stem}: {e}", file=sys.stderr)
        sys.exit(2)
    sys.exit(status)


def print_result(name, result, check, figures=(), skipped=False):
    """Prints the RESULT line; exits with status 1 when the check failed."""
    print("RESULT " + json.dumps({"name": name, "result": result, "check": bool(check), "skipped": bool(skipped),
                                  "figures": [list(f) for f in figures]}))
    if not check:
        sys.stdout.flush()
        print(f"{name}: check FAILED", file=sys.stderr)
        sys.exit(1)


def tighten_factor():
    """SILLAGE_EXAMPLE_TIGHTEN (default 1): the factor bound() applies."""
    text = os.environ.get("SILLAGE_EXAMPLE_TIGHTEN", "1")
    try:
        f = float(text)
    except ValueError:
        f = math.nan
    if not (math.isfinite(f) and f >= 0):  # bad input (exit 2), never a silent factor
        print(f"SILLAGE_EXAMPLE_TIGHTEN: expected a number >= 0, got {text!r}", file=sys.stderr)
        sys.exit(2)
    return f


def bound(x):
    """A stated error bound, tightened by f = SILLAGE_EXAMPLE_TIGHTEN: a number (a radius, an
    error magnitude) times f, or an Interval [a, b] reduced to [a, a + f (b - a)] (from one end,
    not about the middle, where the truth often is)."""
    f = tighten_factor()
    if f == 1:
        return x
    if hasattr(x, "lb") and hasattr(x, "ub"):
        if x.lb() == x.ub():
            return type(x).empty()  # a point bound cannot be tighter: nothing is left
        return type(x)(x.lb(), x.lb() + f * (x.ub() - x.lb()))
    return x * f


def empty_text(stats):
    """"EMPTY: <why>": the answer of an empty network, for the output and the RESULT line, which
    then give no truth or box figures: the domains keep their last values (ContractorNetwork), but
    no solution lies in them."""
    return (f"EMPTY: {stats.emptiness or stats.empty_domain} "
            "(no solution: the bounds or the data are inconsistent)")


def check_stats(stats, label=""):
    """True if the network is not empty; otherwise prints why (empty_text): no solution fits the
    data and the bounds, which is a failure of the example's check."""
    if not stats.empty:
        return True
    print(f"  {label + ': ' if label else ''}{empty_text(stats)}")
    return False


def ivp_stats(ok, why):
    """The fields of a ContractStats that check_stats and empty_exit read, for a contractor run
    outside a network (CtcIvp returns only a flag): empty when ok is False, explained by why."""
    return types.SimpleNamespace(empty=not ok, emptiness="" if ok else why, empty_domain=None)


def empty_exit(name, stats, label=""):
    """The end of an example whose network is empty: the explanation (check_stats) and a failed
    RESULT line, without the truth or box figures that the empty domains would give; exits 1
    (print_result)."""
    check_stats(stats, label)
    print_result(name, f"{label + ': ' if label else ''}{empty_text(stats)}", False)


def _flat(xs):
    for x in xs:
        yield from (_flat(x) if isinstance(x, (list, tuple)) else [x])


def enclosure_ok(*xs):
    """True if every enclosure (Interval, IntervalVector, Tube, TubeVector) is non-empty and
    bounded: a truth check is meaningful only on such enclosures ("100 % inside" an empty or
    unbounded one proves nothing)."""
    for x in xs:
        if x.is_empty():
            return False
        c = x.codomain() if hasattr(x, "codomain") else x
        bounds = [c.lb(), c.ub()]  # floats (Interval) or lists (IntervalVector)
        if not all(math.isfinite(b) for b in _flat(bounds)):
            return False
    return True


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


def deriv_vs_ivp_figure(deriv, ivp, filename, title, path=None):
    """[x1] x [x2] of the CtcDeriv network's tube (blue) and of CtcIvp's (orange, over it), with
    path (an array of rows (x1, x2, ...)) in red; matplotlib, saved to filename."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from sillage.plot_tube import plot_tube_vector_2d

    fig, ax = plt.subplots(figsize=(6, 6))
    plot_tube_vector_2d(ax, deriv, 0, 1, color="#a9cdf2", edgecolor="#2a6aa8")
    plot_tube_vector_2d(ax, ivp, 0, 1, color="#f6c28b", edgecolor="#c25e00", autoscale=False)
    if path is not None:
        ax.plot(path[:, 0], path[:, 1], color="#d62728", linewidth=1.0)
    ax.set_xlabel("x1")
    ax.set_ylabel("x2")
    ax.set_title(title)
    fig.savefig(filename, dpi=100)
    plt.close(fig)

"""Real data: CMU "Plaza 1" (../shared/data/plaza1, read in place; --data DIR
to point elsewhere). Dead reckoning from the odometry (distance and drifting
heading change per period), then the same plus the 3529 radio ranges to 4
beacons, each at an uncertain time (CtcEval; all of them one CtcEvalList node);
with --q-ranges Q also the ranges q-relaxed, at most Q of them wrong (one CtcQEval). The odometry increments tie
positions and heading both ways, over each period (CtcHeading) and over windows of
40 s (CtcHeadingWindow, --heading-window S; 0: none), which keeps the heading
bounded, even from an unknown start, whose start heading [-pi, pi] is cut into
--start-heading-pieces N pieces (default 2), one network each: a piece is proven empty or
contracted, and the answer is the hull of the non-empty pieces' tubes. The gyro's bias is one unknown b0 of the run
(--gyro-turn-on-bias) plus a small in-run drift (--gyro-in-run-drift;
CtcBiasedIncrement), printed at the end. The same network and stated error
bounds (plaza1_bounds.py, the table of examples/cpp/plaza1_bounds.h; each one an
option) as examples/cpp/plaza1.cpp; the check: every ground-truth sample lies in
the position tube. Figures: the map (tube, truth, beacons) and the thickness."""
import bisect
import math
import sys
import time
from types import SimpleNamespace

import sillage
import plaza1_bounds
from plaza1_data import FILES, load  # noqa: F401  (load: also the tests' loader)
from bound_audit import print_audit
from example_args import check_stats, empty_text, enclosure_ok, out_dir_and_data, print_result, run
from sillage import (CtcBiasedIncrement, CtcDeriv, CtcEvalList, CtcFunction, CtcHeading, CtcHeadingWindow, CtcIncrement, CtcQEval,
                     CtcSecondDeriv, Function,
                     Interval, IntervalVector, TDomain, Tube, TubeObservation, TubeVector)

def slice_tube(td, slices):
    """Per-slice values; gates are hulls of their two slices (no information of their own)."""
    n = len(slices)
    gates = [slices[max(k - 1, 0)] | slices[min(k, n - 1)] for k in range(n + 1)]
    return Tube(td, slices, gates)


# The length of the windows of CtcHeadingWindow, s (--heading-window; 0: none): long enough for a path of
# tens of metres against position boxes of about 20 m, short enough for the lawn-mower legs and the gyro
# drift (docs/plaza1.md).
HEADING_WINDOW = 40.0


def solve(d, with_ranges, b=None, q=-1, window=HEADING_WINDOW, heading=None, velocity=None, bias=None, td=None):
    """The position tube at the fixed point with the bounds b (default: the table); q >= 0: at most q
    ranges wrong (one CtcQEval instead of the CtcEvalList of all of them); window > 0: CtcHeadingWindow over windows
    of that many seconds. heading, velocity, bias: lists that receive the heading tube, the velocity tube,
    the gyro's turn-on bias b0 (an Interval, rad/s). td: the time domain (None: a new one on d["t"]; the
    pieces of solve_pieces share one, so that their tubes can be joined)."""
    b = b or plaza1_bounds.bounds(None, d)
    t0 = time.process_time()
    td = td or TDomain(list(d["t"]))
    n = td.nb_slices()
    widths = [td.slice_width(k) for k in range(n)]
    dpsi = [Interval(d["dpsi"][k]) + widths[k] * Interval(-b.gyro_bias, b.gyro_bias) for k in range(n)]
    dist = [(Interval(d["dist"][k]) * Interval(1 - b.dist_rel, 1 + b.dist_rel) + Interval(-b.dist_over, b.dist_under))
            & Interval(0, math.inf) for k in range(n)]
    psi, omega = Tube(td), Tube(td, Interval(-b.turn_max, b.turn_max))
    psi.set_gate(0, Interval(b.start_heading) + Interval(-b.heading0, b.heading0))
    speed, v, p = Tube(td, Interval(0, b.speed_max)), TubeVector(td, 2), TubeVector(td, 2)
    track = Tube(td, Interval(-b.track, b.track))
    p.set_gate(0, IntervalVector([Interval(b.start_x - b.pos0, b.start_x + b.pos0),
                                  Interval(b.start_y - b.pos0, b.start_y + b.pos0)]))
    cn = sillage.ContractorNetwork()
    dist_t, dpsi_t = slice_tube(td, dist), slice_tube(td, dpsi)
    cn.add(CtcIncrement(), [psi, dpsi_t])
    # the gyro's bias is one unknown b0 of the run plus an in-run drift: every span learns b0, and b0 narrows
    # the heading everywhere, and the increments dpsi_t that CtcIncrement and the windows read; a drift as large as the bias class states nothing more than the bias free at
    # every step (CtcIncrement above): no contractor then
    b0 = Interval(-b.gyro_bias, b.gyro_bias)
    if b.gyro_drift < b.gyro_bias:
        measured = slice_tube(td, [Interval(x) for x in d["dpsi"][:n]])
        cn.add(CtcBiasedIncrement(b.gyro_drift), [psi, b0, measured, dpsi_t])
    cn.add(CtcDeriv(), [psi, omega])
    # |psi''| <= alpha: inside a period the heading stays within alpha delta^2 / 8 of the chord of its gates
    cn.add(CtcSecondDeriv(), [psi, Tube(td, Interval(-b.turn_accel, b.turn_accel))])
    # the odometry increments, both ways: the heading gives the positions, the positions the heading
    cn.add(CtcHeading(b.track), [p, psi, dist_t, omega])
    # the same over windows, one every quarter of a window: the heading from the direction of travel
    # measured by the positions, against the gyro's relative heading
    if window > 0:
        stride = max(1, round(window / 4 / ((d["t"][-1] - d["t"][0]) / n)))
        cn.add(CtcHeadingWindow(window, b.track, b.turn_accel, stride), [p, psi, dist_t, dpsi_t, omega])
    cn.add(CtcFunction(Function(["a", "s", "h", "e"], "a - s*cos(h + e)")), [v[0], speed, psi, track])
    cn.add(CtcFunction(Function(["a", "s", "h", "e"], "a - s*sin(h + e)")), [v[1], speed, psi, track])
    cn.add(CtcDeriv(), [p, v])
    cn.set_name(p, "p")
    cn.set_name(v, "v")
    cn.set_name(psi, "psi")
    if b.gyro_drift < b.gyro_bias:  # the gyro's turn-on bias: what empties a wrong piece of the start heading
        cn.set_name(b0, "b0")
    obs = []  # the ranges: x(t) in z, |z - beacon| in the range, t within the stamp's error
    if with_ranges:
        dist_to = {}  # per beacon, parsed once: the ranges to one beacon share it
        for tj, bid, r in zip(d["rt"], d["rid"], d["r"]):
            t = Interval(tj - b.time_err, tj + b.time_err) & td.t0_tf()
            bx, by = d["beacons"][int(bid)]
            rng = Interval(r - b.range_long, r + b.range_short) & Interval(0, math.inf)
            if int(bid) not in dist_to:
                dist_to[int(bid)] = Function(["q1", "q2"], f"sqrt((q1 - {bx!r})^2 + (q2 - {by!r})^2)")
            ring = CtcFunction(dist_to[int(bid)], rng)
            # Named, so that an empty network says which range was inconsistent.
            obs.append(TubeObservation(t, IntervalVector(2), ring, f"range {len(obs)}: beacon {int(bid)} seen at t = {tj:.2f}"))
        # All true (one node for all of them), or at most q wrong; none within the run: nothing.
        if obs:
            cn.add(CtcQEval(q, obs) if q >= 0 else CtcEvalList(obs), [p, v])
    stats = cn.contract()
    cpu = time.process_time() - t0
    if heading is not None:
        heading.append(psi)
    if velocity is not None:
        velocity.append(v)
    if bias is not None:
        bias.append(b0)
    return (p, stats, cpu, *truth_and_boxes(d, p), len(obs))


def truth_and_boxes(d, p):
    """The number of time points whose ground truth lies in the position tube p, and the mean and max
    diameter of its boxes."""
    gx, gy = p[0].gates_array(), p[1].gates_array()
    n = len(gx)
    inside = sum(gx[k, 0] <= d["x"][k] <= gx[k, 1] and gy[k, 0] <= d["y"][k] <= gy[k, 1] for k in range(n))
    diam = [max(gx[k, 1] - gx[k, 0], gy[k, 1] - gy[k, 0]) for k in range(n)]
    return inside, sum(diam) / len(diam), max(diam)


def start_heading_pieces(b, pieces):
    """The start heading [start_heading +- heading0] cut into `pieces` equal intervals, each as bounds
    with its centre and half-width (plaza1::start_heading_pieces in C++). An unknown start heading
    [-pi, pi] as one interval learns nothing with the stated gyro class: its gates grow wider than a
    turn and a window whose cells lie a turn apart keeps the whole gate (docs/plaza1.md)."""
    lb, w = b.start_heading - b.heading0, 2 * b.heading0 / pieces
    return [SimpleNamespace(**dict(vars(b), start_heading=lb + (i + 0.5) * w, heading0=w / 2)) for i in range(pieces)]


def solve_pieces(d, with_ranges, b, q=-1, window=HEADING_WINDOW, pieces=1, heading=None, bias=None):
    """solve() once per piece of the start heading (start_heading_pieces), one after the other, on one
    time domain; the answer is the hull of the non-empty pieces' tubes, gate by gate and slice by
    slice (every solution starts in some piece: a guaranteed enclosure). Returns (p, stats, cpu,
    inside, mean, max, ranges, kept, parts): stats of the first non-empty piece (of the first piece if
    every piece is empty: then p is None, no solution), cpu of all of them, kept the number of
    non-empty pieces, parts a list of (start heading Interval, stats, cpu) per piece."""
    td = TDomain(list(d["t"]))
    parts, hull, cpu, nr = [], None, 0.0, 0
    for piece in start_heading_pieces(b, pieces):
        psi, b0 = [], []
        p, stats, t, _, _, _, nr = solve(d, with_ranges, piece, q, window, psi, bias=b0, td=td)
        cpu += t
        parts.append((Interval(piece.start_heading - piece.heading0, piece.start_heading + piece.heading0), stats, t))
        if not stats.empty:
            hull = (p, psi[0], b0[0], stats) if hull is None else (
                hull[0] | p, hull[1] | psi[0], hull[2] | b0[0], hull[3])
    if hull is None:
        return None, parts[0][1], cpu, 0, math.nan, math.nan, nr, 0, parts
    if heading is not None:
        heading.append(hull[1])
    if bias is not None:
        bias.append(hull[2])
    kept = sum(not s.empty for _, s, _ in parts)
    return (hull[0], hull[3], cpu, *truth_and_boxes(d, hull[0]), nr, kept, parts)


def times_after(t, n):
    """(dt, k): the first time index k at t0 + dt, for the times printed."""
    return [(dt, bisect.bisect_left(t, t[0] + dt)) for dt in (0, 10, 30, 60, 120, 300, 600, 1200)
            if bisect.bisect_left(t, t[0] + dt) < n]


def add_options(ap):
    """The bound options (plaza1_bounds.add_options) and --q-ranges."""
    plaza1_bounds.add_options(ap)
    ap.add_argument("--q-ranges", type=int, default=-1, metavar="Q",
                    help="Q >= 0: also solve with at most Q ranges wrong (CtcQEval), against the strict intersection")
    ap.add_argument("--start-heading-pieces", type=int, default=None, metavar="N",
                    help="the start heading cut into N pieces, one network each, the answer their hull "
                         "(default: 2 with --unknown-start 1, any heading; 1 otherwise)")
    ap.add_argument("--heading-window", type=float, default=HEADING_WINDOW, metavar="S",
                    help=f"CtcHeadingWindow over windows of S seconds (default {HEADING_WINDOW:g}; 0: none)")


def main():
    parsed = out_dir_and_data(__doc__, "plaza1", "plaza1", add_options, FILES)
    if parsed is None:
        return 0
    out, folder, args = parsed
    if not args.heading_window >= 0 or not math.isfinite(args.heading_window):
        print(f"plaza1: --heading-window takes a length >= 0 in seconds, got {args.heading_window}", file=sys.stderr)
        sys.exit(2)
    pieces = args.start_heading_pieces if args.start_heading_pieces is not None else 2 if args.unknown_start else 1
    if not 1 <= pieces <= 1000:
        print(f"plaza1: --start-heading-pieces takes a whole number from 1 to 1000, got {pieces}", file=sys.stderr)
        sys.exit(2)
    d = load(folder)
    b = plaza1_bounds.bounds(args, d)
    # The audit reports; it changes no bound. A bound the truth violates voids the guarantee,
    # even if the truth happens to stay inside: a failure.
    ok, summary, figures = print_audit("plaza1", plaza1_bounds.audit(d, b)), "", []
    truth = (sillage.Trajectory(list(d["t"]), list(d["x"])), sillage.Trajectory(list(d["t"]), list(d["y"])))
    runs = [-2, -1] + ([args.q_ranges] if args.q_ranges >= 0 else [])  # -2: odometry, -1: strict ranges, q
    strict = None
    for run in runs:
        with_ranges = run != -2
        heading, bias = [], []
        p, stats, cpu, inside, mean_d, max_d, nr, kept, parts = solve_pieces(
            d, with_ranges, b, run, args.heading_window, pieces, heading, bias)
        n = len(d["t"])
        label = (f"odometry + ranges, at most {run} wrong" if run >= 0
                 else "odometry + ranges" if with_ranges else "odometry only")
        print(f"{label}: {nr} ranges, {sum(s.iterations for _, s, _ in parts)} rounds, "
              f"{sum(s.contractor_calls for _, s, _ in parts)} contractor runs, {cpu:.2f} s CPU")
        if len(parts) > 1:  # each piece of the start heading: empty (and why) or kept in the hull
            for start, s, t in parts:
                print(f"  start heading piece [{start.lb():.4f}, {start.ub():.4f}] rad: "
                      f"{empty_text(s) if s.empty else 'not empty'}, {s.iterations} rounds, {t:.2f} s CPU")
            if kept == 0:  # every piece empty: inconsistent, with each piece's explanation
                why = "INCONSISTENT: every piece of the start heading is empty" + "".join(
                    f" [{start.lb():.4f}, {start.ub():.4f}] rad: {empty_text(s)};" for start, s, _ in parts)
                print("  INCONSISTENT: every piece of the start heading is empty (each piece says why above)")
                summary += f"{label}: {why} "
                ok = False
                continue
            print("  the tubes below: the hull of the non-empty pieces")
        # No solution, or an unbounded tube: an answer without truth or box figures, and a failed check.
        if not check_stats(stats, label) or not enclosure_ok(p):
            why = empty_text(stats) if stats.empty else "UNBOUNDED: the position tube is unbounded"
            if not stats.empty:
                print("  INCONSISTENT: every piece of the start heading is empty (each piece says why above)")
            summary += f"{label}: {why}; "
            ok = False
            continue
        print(f"  truth inside at {inside}/{n} time points; box diameter mean {mean_d:.2f} m, max {max_d:.2f} m")
        ok = inside == n and ok
        print("  heading half-width at t0 + " + "; ".join(
            f"{dt:.0f} s: {heading[0].gate(k).diam() / 2:.2f} rad" for dt, k in times_after(d["t"], n)))
        # the turn-on bias learnt (measured minus true rate); the truth's: the audit line "gyro turn-on bias"
        print(f"  gyro turn-on bias b0 in [{1e3 * bias[0].lb():.4f}, {1e3 * bias[0].ub():.4f}] mrad/s")
        if run == -1:
            strict = (mean_d, cpu)
        if run >= 0 and not strict:
            print(f"  q-relaxed (q = {run}): the strict intersection is empty")
        if run >= 0 and strict:
            print(f"  q-relaxed (q = {run}) against the strict intersection: mean box {mean_d:.2f} m vs "
                  f"{strict[0]:.2f} m (x {mean_d / strict[0]:.2f}), {cpu:.2f} s vs {strict[1]:.2f} s")
        summary += f"{label}: truth inside {100 * inside / n:.1f} %, mean/max diameter {mean_d:.2f}/{max_d:.2f} m; "
        tag = "qranges" if run >= 0 else "ranges" if with_ranges else "odometry"
        # the beacons as landmarks: inside the window, dots distinct from the truth's line, in the legend
        beacons = [[bx, by] for bx, by in d["beacons"].values()]
        fig = sillage.tube_vector_figure(p, 0, 1, f"plaza1 (Python): {label}", sillage.TubeStyle(), *truth, 600,
                                         beacons)
        fig.save(str(out / f"plaza1_map_{tag}_py.svg"))
        figures.append((f"plaza1_map_{tag}_py.svg", f"plaza1 map, {label} (beacons as yellow dots), Python"))
        th = sillage.thickness_figure(p, sillage.ThicknessMeasure.MaxDiameter,
                                      f"plaza1: position box diameter, {label}")
        th.save(str(out / f"plaza1_thickness_{tag}_py.svg"))
        figures.append((f"plaza1_thickness_{tag}_py.svg", f"plaza1 thickness, {label}, Python"))
    print_result("plaza1", summary, ok, figures)


if __name__ == "__main__":
    run(main)

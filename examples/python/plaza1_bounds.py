"""The error bounds of the plaza1 examples (plaza1.py and loops_plaza1.py) in one table: option,
name, unit, value and where it comes from; the same table as examples/cpp/plaza1_bounds.h. Every
value is stated from the class of the robot and of its sensors, never read off the data file it is
applied to (docs/plaza1.md). A robot of the same class drives at most 2 m/s, has a track of about
1 m, a low-cost heading (MEMS gyro or wheel odometry), wheel odometry and an RF ranging radio,
logged by an ordinary PC."""
import argparse
import bisect
import math
from types import SimpleNamespace

from bound_audit import AuditLine
from example_args import bound

NAN = float("nan")

# (option, attribute, name, unit, value, source): the start (nan = the first ground-truth sample)
# first, then the error magnitudes.
TABLE = [
    ("--start-x", "start_x", "start x", "m", NAN, "default: the first ground-truth sample (a surveyed mark)"),
    ("--start-y", "start_y", "start y", "m", NAN, "default: the first ground-truth sample"),
    ("--start-heading", "start_heading", "start heading", "rad", NAN, "default: the first ground-truth sample"),
    ("--start-pos-err", "pos0", "start position", "m", 0.1, "robot set on a surveyed mark by hand"),
    ("--start-heading-err", "heading0", "start heading", "rad", 0.05, "robot aligned by eye on a surveyed line, 3 deg"),
    ("--gyro-turn-on-bias", "gyro_bias", "gyro turn-on bias", "rad/s", 10.5e-3,
     "low-cost MEMS rate gyro, no calibration beyond its power-up null: bias up to 0.3 deg/s (5.2 mrad/s) at any "
     "time, the top of the rate grade (10 to 1000 deg/h; commercial grade 0.1 deg/s), times 2: 0.6 deg/s; "
     "one unknown constant b0 from turn-on (bias repeatability of the class)"),
    ("--gyro-in-run-drift", "gyro_drift", "gyro in-run drift", "rad/s", 1e-3,
     "variation of the bias during a 30 min run after turn-on, temperature-compensated MEMS gyro: bias instability "
     "<= 10 deg/h (0.05 mrad/s) + temperature sensitivity <= 0.005 deg/s/degC over a 5 degC change (0.44 mrad/s), "
     "times 2: 1 mrad/s; --gyro-in-run-drift equal to --gyro-turn-on-bias is the bias free at every step"),
    ("--turn-max", "turn_max", "turn rate", "rad/s", 4.0,
     "differential drive, wheels <= 2 m/s, track ~1 m: spinning in place at most 2 * 2 / 1 = 4 rad/s"),
    ("--odo-scale", "dist_rel", "odometer scale", "", 0.02, "wheel radius with tyre load and pressure, +-2 %"),
    ("--odo-over", "dist_over", "odometer over-count", "m/period", 0.1,
     "wheel slip: a wheel spinning at 0.5 m/s for a whole 0.2 s period"),
    ("--odo-under", "dist_under", "odometer under-count", "m/period", 0.01,
     "sliding or pushed with the wheels still: 5 cm/s over 0.2 s"),
    ("--speed-max", "speed_max", "speed per stamped period", "m/s", 6.0,
     "2 m/s robot class; a 0.2 s period may last 0.2 + 2 * 0.2 s of time-stamp jitter: 2 * 3 = 6 m/s"),
    ("--range-short", "range_short", "range short error", "m", 1.5,
     "RF ranging is never short by more than the antenna offsets (robot and beacon, 0.5 m each) and the noise (0.5 m)"),
    ("--range-long", "range_long", "range long error", "m", 10.0,
     "RF ranging is biased long: uncalibrated radio delay, multipath and non-line-of-sight, up to 10 m in an open "
     "plaza"),
    ("--time-jitter", "time_err", "time-stamp error", "s", 0.2,
     "logging PC (not real-time): reports of a serial radio reach it up to 0.2 s late or early"),
    ("--track-err", "track", "track error", "rad", 0.05,
     "direction of travel vs heading: side slip of a wheeled robot and heading noise, 3 deg"),
    ("--turn-accel", "turn_accel", "turn acceleration", "rad/s^2", 20.0,
     "tyre grip (friction coefficient <= 1): each wheel accelerates at most 9.8 m/s^2, so on a 1 m track the turn "
     "rate changes by at most 2 * 9.8 / 1 = 20 rad/s^2"),
]
# The same table as the C++ one (plaza1_bounds.h), option for option.


def magnitude(text):
    """An error bound from the command line: a number >= 0 (a negative one is a typo, not a model)."""
    value = float(text)
    if not value >= 0:
        raise argparse.ArgumentTypeError(f"an error bound must be >= 0, got {text}")
    return value


def add_options(ap):
    """One --option per bound (argparse), and --unknown-start."""
    ap.add_argument("--unknown-start", type=float, default=0, metavar="X",
                    help="1: start anywhere within 10 m of the beacons' bounding box, any heading")
    for option, attr, name, unit, value, source in TABLE:
        ap.add_argument(option, dest=attr, type=float if attr.startswith("start_") else magnitude, default=value,
                        metavar="X",
                        help=f"{name} [{unit or '1'}] (default {value:g}): {source}".replace("%", "%%"))


def bounds(args, d):
    """The bounds of the parsed options (defaults: the table), the start from the first ground-truth
    sample where not given; the error magnitudes go through example_args.bound (SILLAGE_EXAMPLE_TIGHTEN)."""
    b = SimpleNamespace()
    for option, attr, *_ in TABLE:
        value = getattr(args, attr, None) if args is not None else None
        default = next(v for o, a, n, u, v, s in TABLE if a == attr)
        setattr(b, attr, default if value is None else value)
        if not attr.startswith("start_"):
            setattr(b, attr, bound(getattr(b, attr)))
    if args is not None and getattr(args, "unknown_start", 0):
        bx, by = [p[0] for p in d["beacons"].values()], [p[1] for p in d["beacons"].values()]
        b.start_x, b.start_y = (min(bx) + max(bx)) / 2, (min(by) + max(by)) / 2
        b.pos0 = max(max(bx) - min(bx), max(by) - min(by)) / 2 + 10
        b.start_heading, b.heading0 = 0.0, math.pi
    b.start_x = d["x"][0] if math.isnan(b.start_x) else b.start_x
    b.start_y = d["y"][0] if math.isnan(b.start_y) else b.start_y
    b.start_heading = d["heading"][0] if math.isnan(b.start_heading) else b.start_heading
    return b


def wrap(a):
    return math.remainder(a, 2 * math.pi)


def audit(d, b):
    """How much of each bound the ground truth used (the same figures as plaza1::audit in C++).
    d needs t, x, y, heading, dist, dpsi (the drifting heading changes), rt, rid, r, beacons."""
    t, x, y, h = d["t"], d["x"], d["y"], d["heading"]
    n = len(d["dist"])
    r = [AuditLine("start position", "m", b.pos0, max(abs(x[0] - b.start_x), abs(y[0] - b.start_y)), "start vs truth"),
         AuditLine("start heading", "rad", b.heading0, abs(wrap(h[0] - b.start_heading)), "start vs truth")]
    # The gyro: e(t) = odometry heading (summed from the start) - truth = e(t0) + b0 (t - t0) + drift.
    # Turn-on bias: the least-squares slope of e (the truth's b0). In-run drift: the smallest d with
    # |e(t) - e(t0) - b0 (t - t0)| <= heading0 + d (t - t0) (the start error allowed, as for the bias before).
    # e is unwrapped (it changes by far less than pi from one sample to the next): a bias of a few mrad/s
    # adds several turns over a run, which a wrapped e would fold into (-pi, pi].
    psi, turn, e = h[0], 0.0, [0.0]
    for k in range(n):
        psi += d["dpsi"][k]
        e.append(e[-1] + wrap(psi - h[k + 1] - e[-1]))
        turn = max(turn, abs(wrap(h[k + 1] - h[k])) / (t[k + 1] - t[k]))
    tau = [tk - t[0] for tk in t]
    m, st, se = n + 1, sum(tau), sum(e)
    stt, ste = sum(x * x for x in tau), sum(x * y for x, y in zip(tau, e))
    b0 = (m * ste - st * se) / (m * stt - st * st)
    drift = max((abs(e[k] - e[0] - b0 * tau[k]) - b.heading0) / tau[k] for k in range(1, n + 1))
    r.append(AuditLine("gyro turn-on bias", "rad/s", b.gyro_bias, abs(b0),
                       "least-squares slope of odometry heading - truth"))
    r.append(AuditLine("gyro in-run drift", "rad/s", b.gyro_drift, max(drift, 0.0),
                       "(|heading error - slope (t - t0)| - start error) / (t - t0)"))
    r.append(AuditLine("turn rate", "rad/s", b.turn_max, turn, "true heading change per period"))
    accel = 0.0  # change of the mean turn rate between neighbouring periods
    for k in range(n - 1):
        w0 = wrap(h[k + 1] - h[k]) / (t[k + 1] - t[k])
        w1 = wrap(h[k + 2] - h[k + 1]) / (t[k + 2] - t[k + 1])
        accel = max(accel, abs(w1 - w0) / ((t[k + 2] - t[k]) / 2))
    r.append(AuditLine("turn acceleration", "rad/s^2", b.turn_accel, accel,
                       "change of the true mean turn rate between neighbouring periods"))
    dist = chord = under = still = speed = 0.0
    for k in range(n):
        c, dk = math.hypot(x[k + 1] - x[k], y[k + 1] - y[k]), d["dist"][k]
        dist, chord = dist + dk, chord + c
        under = max(under, c - dk * (1 + b.dist_rel))
        if c < 0.01:
            still = max(still, dk * (1 - b.dist_rel) - c)
        speed = max(speed, max(c, dk) / (t[k + 1] - t[k]))
    r.append(AuditLine("odometer scale", "", b.dist_rel, abs(chord / dist - 1), "whole run, truth steps / odometry"))
    r.append(AuditLine("odometer over-count", "m/period", b.dist_over, still, "periods where the truth moves < 1 cm"))
    r.append(AuditLine("odometer under-count", "m/period", b.dist_under, max(under, 0.0),
                       "truth step beyond the odometry (a lower bound of the need)"))
    r.append(AuditLine("speed per stamped period", "m/s", b.speed_max, speed,
                       "odometry and truth steps per stamped period"))
    lo = hi = 0.0
    for tj, bid, rj in zip(d["rt"], d["rid"], d["r"]):
        k = bisect.bisect_right(t, tj) - 1
        if k < 0 or k + 1 >= len(t):
            continue
        a = (tj - t[k]) / (t[k + 1] - t[k])
        px, py = x[k] + a * (x[k + 1] - x[k]), y[k] + a * (y[k + 1] - y[k])
        bx, by = d["beacons"][int(bid)]
        e = rj - math.hypot(px - bx, py - by)
        lo, hi = min(lo, e), max(hi, e)
    r.append(AuditLine("range short error", "m", b.range_short, -lo, "measured - true, truth at the stamp"))
    r.append(AuditLine("range long error", "m", b.range_long, hi, "measured - true, truth at the stamp"))
    r.append(AuditLine("time-stamp error", "s", b.time_err, NAN, "the truth shares the clock of the data"))
    return r


def track_audit(d, track, reverse_below, glitch_above):
    """Direction of travel of the truth against its own heading (plaza1::track_audit in C++): over
    each stretch of at least 1 m (shorter ones are dominated by the position noise of the truth),
    the direction of the line from its start to its end against the hull of the headings over the
    stretch; stretches with a period below reverse_below (the robot may back up) or above
    glitch_above (a time-stamp glitch) are left out."""
    t, x, y, h, dist = d["t"], d["x"], d["y"], d["heading"], d["dist"]
    n, used = len(dist), 0.0
    for k in range(n):
        lo = hi = acc = 0.0
        for m in range(k, n):
            speed = dist[m] / (t[m + 1] - t[m])
            if speed < reverse_below or speed > glitch_above:
                break
            acc += wrap(h[m + 1] - h[m])
            lo, hi = min(lo, acc), max(hi, acc)
            dx, dy = x[m + 1] - x[k], y[m + 1] - y[k]
            if math.hypot(dx, dy) < 1.0:
                continue
            a = wrap(math.atan2(dy, dx) - h[k])
            used = max(used, lo - a, a - hi)
            break
    return AuditLine("direction of travel vs heading", "rad", track, used,
                     "truth over stretches of 1 m at speeds between the reverse and glitch speeds")

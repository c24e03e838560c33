"""Loops of a synthetic trajectory (thesis ch. 6): a robot on the open
Lissajous curve p(t) = (A sin(a t), B sin(b t + phi)), t in [0, 30 min],
which crosses its own path 36 times at 1-2 m/s. Its velocity is known to
within +-E per axis: [v](t) = p'(t) + [-E, E]. The t-plane finds the loop
detections (Alg. 6) and the degree test T and the Newton test N prove loops
(Alg. 7-10). The true crossings come from the path sampled every 0.05 s.

Printed: lambda_N (loops proven by N), lambda_T (loops proven by T, their
counts when known) and lambda* (true crossings in complete detections, as in
the thesis: those in detections touching the border are left out). Checks:
every proof holds a true crossing, every true crossing lies in a detection,
every loop count equals the true crossings inside.

Then the (p, w) form (7.28): positions known to within +-(0.5 + 0.001 t) m
(a fix now and then) as well as the velocities; its detections lie inside
those from v alone, with far fewer leaves (split into more, smaller
components). Figures: the two t-planes, and the map."""
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import sillage
from example_args import bound, out_dir, print_result, run
from sillage import Interval, TDomain, TPlane, TubeVector
from sillage.plot_loops import plot_loops_map, plot_tplane

A, B, FA, FB, PHI = 100.0, 70.0, 0.013, 0.021, 1.1  # m, m, rad/s, rad/s, rad
TF, DT = 1800.0, 0.5                                 # s: the mission, the slice width
EPS = TF / 1000                                      # s: precision of the t-plane
E = 0.02                                             # m/s: velocity error per axis
POS0, POS_RATE = 0.5, 0.001                          # m, m/s: position error (p, w) form
TOL_S = 0.01                                         # s: time resolution of the sampled crossings


def r(x):
    """A float written back exactly into an expression."""
    return repr(float(x))


def tubes(td):
    """[v] = p' + [-E, E], and [p] = p + [-1, 1] (POS0 + POS_RATE t): both hold the truth."""
    e = bound(Interval(-E, E))
    v = TubeVector(td, f"({r(A * FA)}*cos({r(FA)}*t) + [{r(e.lb())}, {r(e.ub())}], "
                       f"{r(B * FB)}*cos({r(FB)}*t + {r(PHI)}) + [{r(e.lb())}, {r(e.ub())}])")
    err = f"[-1, 1]*({r(POS0)} + {r(POS_RATE)}*t)"
    p = TubeVector(td, f"({r(A)}*sin({r(FA)}*t) + {err}, {r(B)}*sin({r(FB)}*t + {r(PHI)}) + {err})")
    return v, p


def holds(loop, crossings):
    """Mask of the true crossings in the loop's boxes widened by TOL_S."""
    if not crossings:
        return np.zeros(0, bool)
    t = np.array([(c.t1, c.t2) for c in crossings])
    b = np.asarray(loop.boxes_array())
    inside = ((t[:, None, 0] >= b[None, :, 0, 0] - TOL_S) & (t[:, None, 0] <= b[None, :, 0, 1] + TOL_S)
              & (t[:, None, 1] >= b[None, :, 1, 0] - TOL_S) & (t[:, None, 1] <= b[None, :, 1, 1] + TOL_S))
    return inside.any(axis=1)


def loop_table(tp, crossings):
    """lambda_N, lambda_T, lambda* and the checks of one t-plane."""
    loops = tp.detections()
    masks = [holds(l, crossings) for l in loops]
    in_detection = np.any(masks, axis=0) if masks else np.zeros(len(crossings), bool)
    complete = [m for l, m in zip(loops, masks) if l.complete()]
    lam_star = int(np.any(complete, axis=0).sum()) if complete else 0
    # Proven sub-loops (tp.proofs()): whole detections, or proven pieces of split ones.
    lam_t = sum(p.count() if p.count() is not None else 1 for p in tp.proofs())
    proofs_hit = all(m.any() for l, m in zip(loops, masks) if l.proven() or l.proven_newton())
    proofs_hit = proofs_hit and all(holds(p, crossings).any() for p in tp.proofs())
    counts_ok = all(l.count() == int(m.sum()) for l, m in zip(loops, masks) if l.proven() and l.count() is not None)
    return dict(lam_n=tp.nb_newton_proofs(), lam_t=lam_t, lam_star=lam_star, proofs_hit=proofs_hit,
                counts_ok=counts_ok, all_detected=bool(in_detection.all()),
                counted=sum(l.proven() and l.count() is not None for l in loops))


def leaves(tp):
    """(k, 2, 2) array of all the detection boxes."""
    arrays = [np.asarray(l.boxes_array()) for l in tp.detections()]
    return np.concatenate(arrays) if arrays else np.zeros((0, 2, 2))


def covered(inner, outer):
    """Each box of `inner` is covered by the union of the (disjoint) boxes of `outer`."""
    lo = np.maximum(inner[:, None, :, 0], outer[None, :, :, 0])
    hi = np.minimum(inner[:, None, :, 1], outer[None, :, :, 1])
    overlap = np.prod(np.clip(hi - lo, 0, None), axis=2).sum(axis=1)
    area = np.prod(inner[:, :, 1] - inner[:, :, 0], axis=1)
    return bool(np.all(overlap >= area * (1 - 1e-9)))


def main():
    out = out_dir(__doc__)
    t = np.arange(0, TF + 1e-9, 0.05)
    x, y = A * np.sin(FA * t), B * np.sin(FB * t + PHI)
    speed = np.hypot(A * FA * np.cos(FA * t), B * FB * np.cos(FB * t + PHI))
    crossings = sillage.self_crossings(list(t), list(x), list(y))
    print(f"lissajous loops: p(t) = ({A:g} sin({FA:g} t), {B:g} sin({FB:g} t + {PHI:g})), t in [0, {TF:g}] s, "
          f"speed {speed.mean():.2f} m/s mean, {speed.max():.2f} max; {len(crossings)} true crossings")
    print(f"  [v] = p' + [-{E:g}, {E:g}] m/s, slices of {DT:g} s, eps = {EPS:g} s; "
          f"(p, w): [p] = p +- ({POS0:g} + {POS_RATE:g} t) m, w = [v]")

    td = TDomain(0.0, TF, DT)
    v, p = tubes(td)
    runs = {}
    for form, args in (("v", (v,)), ("(p, w)", (p, v))):
        t0 = time.perf_counter()
        tp = TPlane(td)
        tp.compute_detections(EPS, *args)
        tp.compute_proofs(*args)
        runs[form] = (tp, loop_table(tp, crossings), time.perf_counter() - t0)

    print(f"\n  {'form':<7} {'detections':>10} {'complete':>9} {'leaves':>7} {'area (s^2)':>11} "
          f"{'lambda_N':>9} {'lambda_T':>9} {'lambda*':>8} {'counted':>8} {'time':>7}")
    ok = True
    for form, (tp, c, seconds) in runs.items():
        b = leaves(tp)
        area = float(np.prod(b[:, :, 1] - b[:, :, 0], axis=1).sum())
        print(f"  {form:<7} {tp.nb_detections():>10} {tp.nb_complete_detections():>9} {len(b):>7} {area:>11.0f} "
              f"{c['lam_n']:>9} {c['lam_t']:>9} {c['lam_star']:>8} {c['counted']:>8} {seconds:>6.2f}s")
        good = c["proofs_hit"] and c["all_detected"] and c["counts_ok"]
        print(f"    every proof holds a true crossing: {c['proofs_hit']}; every true crossing in a detection: "
              f"{c['all_detected']}; loop counts equal the crossings inside: {c['counts_ok']}")
        ok = ok and good
    subset = covered(leaves(runs["(p, w)"][0]), leaves(runs["v"][0]))
    # Positions cut the components of v into smaller ones: more detections, far fewer leaves.
    print(f"  (p, w) detections inside the detections from v alone: {subset}")
    ok = ok and subset

    figures = []
    fig, axes = plt.subplots(1, 2, figsize=(13, 6.5))
    for ax, (form, (tp, c, _)) in zip(axes, runs.items()):
        plot_tplane(ax, tp, truth=crossings)
        ax.set_title(f"t-plane from {form}: {tp.nb_detections()} detections, "
                     f"lambda_T = {c['lam_t']}, lambda* = {c['lam_star']}", fontsize=10)
    fig.tight_layout()
    fig.savefig(out / "loops_lissajous_tplane.png", dpi=100)
    plt.close(fig)
    figures.append(("loops_lissajous_tplane.png", "loops_lissajous: t-planes from v (left) and from (p, w) (right), "
                                                  "true crossings in blue"))
    # The map boxes of the (p, w) form are absolute positions, tight enough to draw.
    fig, ax = plt.subplots(figsize=(9, 7))
    plot_loops_map(ax, runs["(p, w)"][0], positions=np.column_stack([x, y]), times=t, crossings=crossings,
                   show_partial=False)
    ax.set_title("loops_lissajous: path, true crossings (red), map boxes of the (p, w) detections", fontsize=10)
    fig.savefig(out / "loops_lissajous_map.png", dpi=100)
    plt.close(fig)
    figures.append(("loops_lissajous_map.png", "loops_lissajous: map with the (p, w) detections "
                                               "(orange: proven, black: not proven, grey: partial)"))

    (tv, cv, _), (tpw, cpw, _) = runs["v"], runs["(p, w)"]
    print_result("loops_lissajous",
                 f"{len(crossings)} crossings; from v: {tv.nb_detections()} detections, lambda_N {cv['lam_n']}, "
                 f"lambda_T {cv['lam_t']}, lambda* {cv['lam_star']}; from (p, w): {tpw.nb_detections()} detections, "
                 f"lambda_N {cpw['lam_n']}, lambda_T {cpw['lam_t']}, lambda* {cpw['lam_star']}", ok, figures)
    return 0 if ok else 1


if __name__ == "__main__":
    run(main)

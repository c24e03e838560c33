"""Why a problem has no solution: examples/problems/plaza1.toml (CMU Plaza 1, real data) with its
start heading flipped by pi, as a log whose heading column points backwards states it. The solve
finds no solution, and the contractor that emptied a domain (CtcHeading, 86 s later) is not the
cause. explain_empty relaxes the file's statements one at a time and names the start heading
first, proving the value stated impossible given the rest of the file. Figure: the heading tube
just before the contradiction (SolveResult.before_empty) with the stated start heading (red) and
the values the rest of the file proves for it (green), and the positions before the
contradiction. Exits non-zero unless the heading gate comes first, its stated value is proven
impossible and the truth's start heading is kept. The range errors go through bound()."""
import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import sillage  # noqa: E402
from example_args import bound, out_dir_and_data, print_result, run  # noqa: E402
from plaza1_data import FILES  # noqa: E402

PROBLEM = Path(__file__).resolve().parents[1] / "problems" / "plaza1.toml"
STATED = "-2.060753 + [-0.05, 0.05]"  # the file's start heading: the first ground-truth sample
FLIPPED = f"{-2.060753 + math.pi:.6f} + [-0.05, 0.05]"
TRUE_HEADING = -2.060753


def flipped_problem(folder, out):
    """plaza1.toml reading `folder`, its start heading flipped by pi and its range error bounds
    through bound() (SILLAGE_EXAMPLE_TIGHTEN)."""
    text = PROBLEM.read_text().replace("${SILLAGE_DATA:-../../../shared/data}/plaza1", str(folder))
    assert STATED in text
    error = bound(sillage.Interval(-1.5, 10))
    text = text.replace(STATED, FLIPPED).replace("range_m + [-1.5, 10]", f"range_m + [{error.lb()!r}, {error.ub()!r}]")
    path = out / "plaza1_flipped.toml"
    path.write_text(text)
    return sillage.load_problem(str(path))


def heading_panel(ax, psi, value, t0):
    """The heading tube before the contradiction over its first 150 s, the stated start heading and
    what the relaxed problem proves of it."""
    td = psi.tdomain()
    ts = [td.t(k) for k in range(td.nb_slices() + 1) if td.t(k) <= t0 + 150]
    lo = [max(psi(t).lb(), -8) for t in ts]
    hi = [min(psi(t).ub(), 8) for t in ts]
    ax.fill_between(ts, lo, hi, color="#a9cdf2", label="[ψ] before the contradiction")
    w = 1.5
    ax.add_patch(plt.Rectangle((t0 - w, value.stated.lb()), 2 * w, value.stated.diam(), color="#e53935",
                               label=f"stated ψ(t0) = {FLIPPED}"))
    for k, piece in enumerate(value.pieces or [value.proven]):
        ax.add_patch(plt.Rectangle((t0 - w, piece.lb()), 2 * w, piece.diam(), color="#43a047", alpha=0.7,
                                   label="ψ(t0) proven with the gate relaxed" if k == 0 else None))
    ax.axhline(TRUE_HEADING, color="k", lw=0.6, ls=":", label="ground truth ψ(t0)")
    ax.set_xlim(t0 - 5, t0 + 150)
    ax.set_ylim(-4.5, 4.5)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("ψ (rad)")
    ax.legend(fontsize=7, loc="lower right")


def main():
    args = out_dir_and_data(__doc__, "plaza1", "explain_empty", files=FILES)
    if args is None:
        return 0
    out, folder, _ = args
    p = flipped_problem(folder, out)
    r = sillage.solve_problem(p)
    print("plaza1.toml, start heading flipped by pi:", "NO SOLUTION" if r.empty else "solved")
    if r.empty:
        print(f"  {r.why_empty}")
    e = sillage.explain_empty(p, r)
    print(e)
    first = e.items[e.relaxations[0].items[0]] if e.relaxations else None
    value = e.relaxations[0].values[0] if first is not None and e.relaxations[0].values else None
    kept = value is not None and any(x.contains(TRUE_HEADING) or x.contains(TRUE_HEADING + 2 * math.pi)
                                     for x in (value.pieces or [value.proven]))
    ok = (r.empty and first is not None and first.label == "[var.psi] at t = 3856.8573" and value.disjoint()
          and kept and r.before_empty is not None)
    figures = []
    if r.before_empty is not None and value is not None:
        fig, axes = plt.subplots(1, 2, figsize=(13, 4.8))
        t0 = r.before_empty["psi"].tdomain().t0_tf().lb()
        heading_panel(axes[0], r.before_empty["psi"], value, t0)
        axes[0].set_title(f"Blamed: {first.label} ({Path(first.file).name}:{first.line})", fontsize=9)
        pos = r.before_empty["p"]
        td = pos.tdomain()
        for k in range(0, td.nb_slices() + 1, 10):
            if td.t(k) > t0 + 90:
                break
            bx, by = pos[0](td.t(k)), pos[1](td.t(k))
            axes[1].add_patch(plt.Rectangle((bx.lb(), by.lb()), bx.diam(), by.diam(), fill=False, lw=0.5,
                                            color=plt.cm.viridis((td.t(k) - t0) / 90)))
        truth = sillage.CsvTable.read(str(folder / "ground_truth.csv"))
        tt, tx, ty = truth.values("t_s"), truth.values("x_m"), truth.values("y_m")
        near = [i for i, t in enumerate(tt) if t <= t0 + 90]
        axes[1].plot([tx[i] for i in near], [ty[i] for i in near], "r-", lw=1.2, label="ground truth (first 90 s)")
        axes[1].autoscale_view()
        axes[1].set_aspect("equal")
        axes[1].set_xlabel("x (m)")
        axes[1].set_ylabel("y (m)")
        axes[1].legend(fontsize=7)
        axes[1].set_title("[p] before the contradiction, every 10th gate of the first 90 s (dark: early)", fontsize=9)
        name = "explain_empty_py.png"
        fig.tight_layout()
        fig.savefig(out / name, dpi=90)
        figures.append((name, "The flipped start heading, blamed: the heading before the contradiction (matplotlib)"))
    result = (f"blamed {first.str() if first else 'nothing'}; {len(e.trials)} trials in {e.seconds:.1f} s"
              + (f"; {value.what} proven in {value.proven_text()}" if value is not None else ""))
    print_result("explain_empty", result, ok, figures)
    return 0


if __name__ == "__main__":
    run(main)

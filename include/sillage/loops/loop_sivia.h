#pragma once
// proprioLoopSIVIA (thesis Alg. 6): a paving of the t-plane square
// [t0, tf]^2 whose outer approximation (Inner ∪ Boundary leaves) encloses
// the feasible loops T = {(t1, t2) | t1 < t2, 0 ∈ [f](t1, t2)} of a
// LoopFunction, at precision eps (seconds).
//
// Tests on a t-box [t] = [t1] x [t2]:
//  - t1 < t2: only the part with t1 <= ub[t2] and t2 >= lb[t1] may hold a
//    loop; the rest is cut off as Outside (this contraction makes the
//    bisection of the square never produce boxes below the diagonal, beside
//    boxes straddling it);
//  - on or against the diagonal (ub[t1] >= lb[t2]), f(t, t) = 0 lies in
//    [f], and only the injectivity test (6.9) can decide: if
//    0 ∉ [v]([lb t1, ub t2]) (some component of the velocity keeps one sign
//    over the whole span, so that component of p is strictly monotonic
//    there), p is injective on the span and the box is Outside;
//  - strictly above the diagonal: outside (6.8) if 0 ∉ [f]([t]); else inner
//    (6.10), velocity form only, if on both components the range of ∫v^- is
//    <= 0 and that of ∫v^+ is >= 0: for every (t1, t2) some velocity of the
//    tube integrates to 0 (the components of a velocity tube are
//    independent, and each integral sweeps the whole interval between ∫v^-
//    and ∫v^+); else (6.9) as above. With positions (7.28) the positions
//    constrain the velocities jointly over time, so no leaf is Inner.
// Undecided boxes are bisected (largest side, midpoint) down to width eps.
// Parallel with oneTBB; the paving never depends on the thread count.
#include "sillage/loops/loop_function.h"
#include "sillage/paving/sivia.h"

namespace sillage {

// Error if eps <= 0 or NaN, if `square` is not a bounded 2-D box [a, b]^2
// with a < b, or if it is not inside the time domain of f. The options (parallel,
// budget) are those of sivia.h.
Paving loop_sivia(const LoopFunction& f, const IntervalVector& square, double eps,
                  const SiviaOptions& options = {});
// The same keeping the paving so far when the budget is spent or the run
// cancelled (SiviaResult, sivia.h): the t-boxes not yet classified are
// Boundary leaves, so its outer approximation still encloses every feasible
// loop. NoSolution: every t-box is proven outside (no loop at all).
SiviaResult loop_sivia_run(const LoopFunction& f, const IntervalVector& square, double eps,
                           const SiviaOptions& options = {});

namespace detail {
// (6.10), velocity form only: t1 < t2 surely and, on both components, the
// range of ∫v^- is <= 0 and that of ∫v^+ is >= 0, so that every (t1, t2) of
// the box is a feasible loop. Always false with positions (see above).
bool is_inner_box(const LoopFunction& f, const IntervalVector& t);
// loop_sivia_run in parallel for a caller named `where` whose budget
// argument is called "budget" (error messages).
SiviaResult run_loop_paving(const LoopFunction& f, const IntervalVector& square, double eps, const Budget& budget,
                            const char* where);
}  // namespace detail

}  // namespace sillage

#pragma once
// The engine shared by every SIVIA variant. Each variant is expressed as a
// separation of a box [x] into x_in (what is left once the part proven inside
// X is removed) and x_out (what is left once the part proven outside X is
// removed); a plain inclusion test removes all or nothing.
//
// For a box [x] the engine stores, as a chain of binary nodes whose first
// child is a leaf slab: [x] \ x_out (Outside), then x_out \ x_in (Inner); what
// remains, r = x_in ∩ x_out, becomes a Boundary leaf if width(r) < eps,
// otherwise it is bisected and both halves are processed again (Alg. 1 with
// the contraction placed before the bisection, thesis 2.4.3).
//
// Bisection: the component of largest diameter (the first one on ties, i.e.
// the smallest index) is split at its midpoint. A box that floating point
// cannot split further becomes a Boundary leaf.
//
// Parallelism: the subtrees of the first kParallelDepth bisection levels are
// grown as oneTBB tasks into separate chunks, spliced afterwards in
// pre-order. The tree therefore never depends on the number of threads.
//
// Budget (budget.h): every node stored counts as a box; the tasks share one
// BudgetMeter, so exceeding the budget or a cancellation stops them all: the
// boxes they were about to separate or bisect become Boundary leaves (the
// paving so far stays an enclosure), and run_paving says so in its Summary.
#include <functional>

#include "sillage/budget.h"
#include "sillage/paving/paving.h"
#include "sillage/paving/sivia.h"

namespace sillage::detail {

using Separation = std::function<void(IntervalVector& x_in, IntervalVector& x_out)>;

inline constexpr int kParallelDepth = 12;

// Throws for eps <= 0 or NaN, a zero-dimensional or unbounded x0.
void check_sivia_input(const IntervalVector& x0, double eps, const char* where);

// The paving of x0 by `separate` at precision eps (an empty paving if x0 is
// empty), with how the run ended (SiviaResult). `where` names the caller in
// error messages, `option` the setting that holds the budget (see BudgetMeter).
SiviaResult run_paving(const IntervalVector& x0, double eps, const Separation& separate, bool parallel,
                       const Budget& budget, const char* where, const char* option = "options.budget");
// The same, throwing BudgetExceeded or Cancelled unless the run finished.
Paving build_paving(const IntervalVector& x0, double eps, const Separation& separate, bool parallel,
                    const Budget& budget, const char* where, const char* option = "options.budget");

// The inclusion tests of Alg. 1 and Alg. 2 as separations of x (x_in and
// x_out hold [x]): Outside empties x_out, Inner empties x_in. `may_be_inner`
// false forbids the Inner verdict (e.g. f not proven defined on [x]).
// image_test: [f]([x]) = fx against Y (dimension checked, `where` in errors).
void image_test(const IntervalVector& fx, const IntervalVector& y, bool may_be_inner, IntervalVector& x_in,
                IntervalVector& x_out, const char* where);
// kernel_test: lo = [f-]([x]), hi = [f+]([x]).
void kernel_test(const IntervalVector& lo, const IntervalVector& hi, bool may_be_inner, IntervalVector& x_in,
                 IntervalVector& x_out, const char* where);

}  // namespace sillage::detail

#pragma once
// The generators of CtcIvp's zonotopes (dynamics/ivp_step.h): the set is
// c + A·[r] + Σ g_j w_j, one symbol w_j ∈ [-1, 1] per generator g_j (a
// point vector), each symbol in one generator only. These helpers move
// uncertainty between generators and a symmetric box `extra` (whose sides
// the caller turns into generators along the axes) without losing any
// point of the set.
#include <cstddef>
#include <vector>

#include "sillage/interval/interval_vector.h"

namespace sillage::detail {

// [-|x|, |x|]: x times a symbol w in [-1, 1].
Interval symmetric(const Interval& x);

// The point part of an interval generator; the rest, times w ∈ [-1, 1],
// goes to the box `extra`.
Vector split_generator(const IntervalVector& g, IntervalVector& extra);

// A symmetric box as generators along the axes (the zero sides skipped).
void box_to_generators(const IntervalVector& box, std::vector<Vector>& G);

// Past `max_generators`, reduces G to about 3/4 of it.
// First, when some states are passive (passive[i]: no state's derivative
// depends on x_i, so a box on them is never sheared into the others), pairs
// of generators whose active parts are parallel and born at neighbouring
// steps (neighbours in G) are merged: g_a w_a + g_b w_b = (g_a + g_b) w +
// Σ (g_k - d_k ḡ) w_k with d the active weight, w = Σ d_k w_k / Σ d_k and
// ḡ = (g_a + g_b) / Σ d_k; the residual has no active part and goes to
// `extra` (the cheapest pairs first, in rounds). Then, if still too many, Girard's
// criterion (‖g‖₁ - ‖g‖∞) boxes the cheapest generators into `extra`.
void reduce_generators(std::vector<Vector>& G, IntervalVector& extra, const std::vector<bool>& passive,
                       std::size_t max_generators);

}  // namespace sillage::detail

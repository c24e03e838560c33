#pragma once
// The q-relaxed intersection (Jaulin, "robust set inversion"): of m sets,
// the points that belong to at least m - q of them ("at most q of the m
// constraints are wrong"). q = 0 is the plain intersection; q >= m is the
// whole space. On intervals the hull of that set is computed exactly; on
// boxes it is taken component by component, an outer approximation of the
// q-relaxed intersection of the boxes (a point in >= m - q boxes has each
// coordinate in >= m - q of the corresponding intervals).
// Only comparisons of bounds: no rounding, the results are exact.
#include <vector>

#include "sillage/interval/interval_vector.h"

namespace sillage {

// Throws sillage::Error naming `where` when q < 0.
void check_q(int q, const char* where);

// The hull of {x real : x belongs to at least m - q of the m intervals};
// an empty interval is a set no point belongs to. The whole line when q >= m.
// Throws Error for an empty list or q < 0.
Interval q_inter(const std::vector<Interval>& xs, int q);

// Component by component: [q_inter of the k-th components] for each k, where
// an empty box contributes to no component (a box is one constraint, a point
// out of it in any coordinate violates it). Empty as soon as one component is.
// Throws Error for an empty list or q < 0, DimensionError for mixed sizes.
IntervalVector q_inter(const std::vector<IntervalVector>& boxes, int q);

}  // namespace sillage

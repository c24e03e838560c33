#pragma once
// Tubes built from data (thesis 3.3.2, (3.13)). Each builder returns a tube
// that contains every trajectory compatible with the stated assumptions,
// rounding included.
#include <memory>

#include "sillage/interval/interval.h"
#include "sillage/tube/trajectory.h"
#include "sillage/tube/tube.h"

namespace sillage {

// Assumption: |x(t) - d(t)| <= error for all t, d being the trajectory
// (typically sampled: its piecewise-linear interpolation). Slice k is
// d([t_k, t_{k+1}]) + [-error, error], gate k is d(t_k) + [-error, error].
// Error if error < 0 or NaN, or if d's domain does not cover the TDomain.
Tube tube_from_data(std::shared_ptr<TDomain> td, const Trajectory& d, double error = 0.0);

// Assumption: lb(t) <= x(t) <= ub(t) for all t. Slice k is
// [min of lb over the slice, max of ub over the slice] (empty where lb > ub
// over the whole slice). Error if a domain does not cover the TDomain.
Tube tube_from_bounds(std::shared_ptr<TDomain> td, const Trajectory& lb, const Trajectory& ub);

// Assumptions (thesis 3.3.2, solution 1): each sample (t_i, y_i) of the
// sampled trajectory `data` satisfies |x(t_i) - y_i| <= error, and
// x'(t) ∈ dx for all t. Then, between samples,
//   x(t) ∈ (y_i + [-e,e] + (t - t_i) dx) ∩ (y_{i+1} + [-e,e] - (t_{i+1} - t) dx),
// and before the first / after the last sample only the one bound applies
// (so the TDomain may extend beyond the data). Each slice gets the hull of
// that intersection over its time span, tight up to rounding (the polygon
// between samples is not over-approximated by its bounding box).
// Error if data is not sampled, error < 0 or NaN, or dx is empty.
Tube tube_from_data(std::shared_ptr<TDomain> td, const Trajectory& data, double error, const Interval& dx);

}  // namespace sillage

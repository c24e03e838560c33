#pragma once
// Tube::eval(t, v) for a t known to lie in one slice (internal header;
// tube_eval_deriv.cpp), for callers that already know the slice: CtcEval's
// sweeps read the part of [t] in each slice of its region.
#include <cstddef>
#include <span>

#include "sillage/interval/interval.h"
#include "sillage/tube/tdomain.h"

namespace sillage::detail {

// The hull of slice k's polygon (the trajectories with x' in v) and of
// [x](k) over [c1, c2], t_k <= c1 <= c2 <= t_{k+1}; empty if the slice
// holds no trajectory. The bits of Tube::eval(Interval(c1, c2), v) when
// c1 < c2 or when c1 is inside the slice, without its checks and search.
Interval eval_in_slice(const TubeData& x, const TubeData& v, std::span<const double> ts, std::size_t k, double c1,
                       double c2);

}  // namespace sillage::detail

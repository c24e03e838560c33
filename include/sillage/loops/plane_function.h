#pragma once
// The maps of the t-plane (thesis ch. 6): an inclusion function [f] : IR^2 ->
// IR^2 (for loops, [f]([t1], [t2]) = ∫_{[t1]}^{[t2]} [v], (6.6), or its
// tighter form (7.28)) and an inclusion function of its Jacobian [J_f] :
// IR^2 -> IR^{2x2} ((6.18) for loops). The zero tests of this folder only
// ever see these callables: they hold for every f* whose values and
// Jacobian lie in the enclosures, i.e. for the unknown true f*.
#include <functional>

#include "sillage/interval/interval_matrix.h"
#include "sillage/interval/interval_vector.h"

namespace sillage {

// Must be an inclusion function: f*(t) ∈ f([t]) for every t in [t]. May be
// called concurrently from several threads.
using PlaneFunction = std::function<IntervalVector(const IntervalVector&)>;
// Must enclose the Jacobian of f* over the box: J_f*(t) ∈ J([t]).
using PlaneJacobian = std::function<IntervalMatrix(const IntervalVector&)>;

}  // namespace sillage

#pragma once
// A function of t evaluated over the time elements of a TDomain, written
// straight into the slices and gates of tubes (internal header): the tube
// constructors from an expression.
#include <span>

#include "sillage/expr/function.h"
#include "sillage/tube/tdomain.h"

namespace sillage::detail {

// For each output i of f (one variable t): slices[i][k] = f([t_k, t_k+1])
// for k < N, gates[i][k] = f(t_k) for k <= N, with unknown_where_undefined
// (tube.h). Batches of the time elements go through Function::eval_batch
// with no intermediate copy of the whole domain.
void eval_into_tubes(const TDomain& td, const Function& f, std::span<Interval* const> slices,
                     std::span<Interval* const> gates);

}  // namespace sillage::detail

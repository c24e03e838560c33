#pragma once
// A function of t evaluated over the time elements of a TDomain, written
// straight into the storage of tubes (internal header): the tube
// constructors from a function.
#include <span>

#include "sillage/expr/function.h"
#include "sillage/tube/tdomain.h"

namespace sillage::detail {

// For each output i of f (one variable t): out[i]->slices[k] = f([t_k, t_k+1])
// for k < N, out[i]->gates[k] = f(t_k) for k <= N, with
// unknown_where_undefined (tube.h); the storage is replaced. Batches of the
// time elements go through Function::eval_batch into a buffer that stays in
// cache, then are appended: each element of the tubes is written once.
void eval_into_tubes(const TDomain& td, const Function& f, std::span<TubeData* const> out);

}  // namespace sillage::detail

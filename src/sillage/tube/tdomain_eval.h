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
// unknown_where_undefined (tube.h); the storage is replaced. Chunks of the
// time elements go through Function::eval_batch straight into the tubes
// (each element written once), shared among threads from 2048 elements on;
// the values are the same for any number of threads.
void eval_into_tubes(const TDomain& td, const Function& f, std::span<TubeData* const> out);

}  // namespace sillage::detail

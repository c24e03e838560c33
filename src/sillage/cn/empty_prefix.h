#pragma once
// Where along time a tube contractor found a tube inconsistent: it empties
// the whole tube, so the network cannot tell by looking. first_empty_prefix
// finds the earliest atom (2k: gate k, 2k+1: slice k) such that the tube
// restricted to its atoms up to that one (the later ones released to the
// whole line) is already proven empty: where the constraint and the tube
// stop being consistent. A binary search, O(log N) contractions of copies,
// run after a failure only.
#include <cstddef>
#include <functional>

#include "sillage/tube/tube.h"

namespace sillage::detail {

// `contract` returns false on emptiness (CtcDeriv, CtcIncrement, ...). Returns
// 2N+1 (no atom) when even the whole of x is not proven empty by a new run.
std::size_t first_empty_prefix(const Tube& x, const std::function<bool(Tube&)>& contract);

}  // namespace sillage::detail

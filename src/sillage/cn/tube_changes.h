#pragma once
// For network nodes that contract whole tubes (CtcDeriv, CtcEval): the atoms
// of a tube that shrank between a copy taken before the contraction and the
// tube after it, reported to the network as node positions.
#include <cstddef>
#include <vector>

#include "sillage/tube/tube.h"

namespace sillage {

// Appends offset + atom (atom 2k: gate k, 2k+1: slice k) for each slice or gate of
// `after` that shrank by more than `ratio` from `before` (shrink.h).
void report_tube_changes(const TubeData& before, const Tube& after, std::size_t offset, double ratio,
                         std::vector<std::size_t>& changed);

}  // namespace sillage

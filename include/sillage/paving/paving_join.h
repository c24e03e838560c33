#pragma once
// Pavings built from pieces. A set inversion split over processes
// (python/sillage/distributed_paving.py) paves the sub-boxes of SIVIA's first
// bisections apart and joins the pieces here into the tree one process builds:
// the same nodes in the same pre-order, so that the joined paving is == to it.
#include <cstdint>
#include <string>
#include <vector>

#include "sillage/interval/interval_vector.h"
#include "sillage/paving/paving.h"
#include "sillage/paving/paving_tag.h"

namespace sillage {

// The paving of one leaf: box with its tag. Error for an empty or 0-dimensional box.
Paving leaf_paving(const IntervalVector& box, PavingTag tag);

// The paving whose root is box, an internal node whose left and right
// subtrees are the pavings left and right (their domains the two halves of
// box). Error if a piece is empty, if the dimensions differ, or if the
// pieces' domains are not inside box.
Paving join_pavings(const IntervalVector& box, const Paving& left, const Paving& right);

// The paving top with its leaves of pre-order indices `leaves` (increasing)
// replaced by the pavings `pieces` (one each, its domain that leaf's box), in
// one pass: the join of many sub-pavings without copying them at every level.
// Error if a leaf is not one, the counts differ, or a piece's domain is not
// its leaf's box.
// The pieces are read, never copied whole (they may hold hundreds of MB).
Paving graft_pavings(const Paving& top, const std::vector<std::size_t>& leaves,
                     const std::vector<const Paving*>& pieces);

// A paving as plain arrays and back (pickling): per node its right-child
// offset and its kind, per node dim() pairs of bounds (lb, ub). Bit for bit.
struct PavingArrays {
  std::size_t dim = 0;
  std::vector<std::uint32_t> right;
  std::vector<std::uint8_t> kind;
  std::vector<double> bounds;  // 2 * dim per node
};
PavingArrays paving_arrays(const Paving& p);
// Error naming what is inconsistent (sizes, an offset past the end, a kind that is no tag).
Paving paving_from_arrays(const PavingArrays& a);

}  // namespace sillage

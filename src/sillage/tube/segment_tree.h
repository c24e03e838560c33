#pragma once
// Bottom-up segment trees over blocks of leaves (internal to the synthesis
// tree): nodes[nb + b] summarizes block b, nodes[p] = fold(nodes[2p],
// nodes[2p+1]) for 1 <= p < nb; 2·nb nodes for nb blocks, any nb >= 1. The
// folds used (min, max) are exact and associative, so the result does not
// depend on the grouping.
#include <cstddef>
#include <vector>

namespace sillage::detail {

// Fills the inner nodes once the block nodes nodes[nb, 2nb) are set.
template <class Node, class Fold>
void build_inner_nodes(std::vector<Node>& nodes, Fold fold) {
  const std::size_t nb = nodes.size() / 2;
  for (std::size_t p = nb - 1; p >= 1; --p) nodes[p] = fold(nodes[2 * p], nodes[2 * p + 1]);
}

// acc folded with the blocks first .. end-1: acc = fold(acc, node) over
// O(log nb) nodes. Branch-free: at each level both candidate nodes are
// folded, the one not in the range through pick(take, node) = node or a
// neutral element (which side of a level is taken is a coin toss for random
// ranges, a branch would be mispredicted half the time).
template <class Node, class Acc, class Fold, class Pick>
Acc fold_blocks(const std::vector<Node>& nodes, std::size_t first, std::size_t end, Acc acc, Fold fold, Pick pick) {
  const std::size_t nb = nodes.size() / 2;
  for (std::size_t l = first + nb, r = end + nb; l < r; l = (l + 1) >> 1, r >>= 1) {
    acc = fold(acc, pick((l & 1) != 0, nodes[l]));
    acc = fold(acc, pick((r & 1) != 0, nodes[r - 1]));
  }
  return acc;
}

// Requests (prefetches) the nodes fold_blocks(nodes, first, end, ...) reads.
template <class Node>
void prefetch_blocks(const std::vector<Node>& nodes, std::size_t first, std::size_t end) {
  const std::size_t nb = nodes.size() / 2;
  for (std::size_t l = first + nb, r = end + nb; l < r; l = (l + 1) >> 1, r >>= 1) {
    __builtin_prefetch(&nodes[l]);
    __builtin_prefetch(&nodes[r - 1]);
  }
}

}  // namespace sillage::detail

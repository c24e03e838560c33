#include "sillage/cn/dirty_atoms.h"

#include <algorithm>
#include <bit>

namespace sillage::detail {

void DirtyAtoms::add_node(const CnNode& node, std::vector<std::size_t>& bit_of) {
  // Each node starts on a word of its own: take() scans only its words.
  std::size_t bit = words_.size() * 64;
  bit_of.assign(node.ranges().size(), 0);
  for (std::size_t g = 0; g < node.ranges().size(); ++g) {
    const AtomRange& w = node.watched()[g];
    if (w.count == 0) continue;
    bit_of[g] = bit;
    spans_.push_back({bit, w.count, node.offset(g) + (w.first - node.ranges()[g].first)});
    bit += w.count;
  }
  words_.resize((bit + 63) / 64, 0);
  first_span_.push_back(spans_.size());
  wakes_.push_back(0);
}

void DirtyAtoms::clear_nodes() {
  words_.clear();
  spans_.clear();
  first_span_.assign(1, 0);
  wakes_.clear();
}

void DirtyAtoms::reset() {
  std::fill(words_.begin(), words_.end(), 0);
  std::fill(wakes_.begin(), wakes_.end(), 0);
}

void DirtyAtoms::take(std::size_t node, std::vector<std::size_t>& out) {
  out.clear();
  wakes_[node] = 0;
  for (std::size_t s = first_span_[node]; s < first_span_[node + 1]; ++s) {
    const Span& sp = spans_[s];
    const std::size_t end = sp.bit + sp.count;
    for (std::size_t b = sp.bit; b < end;) {
      // The bits of this span in the word holding b.
      const std::size_t word = b >> 6, lo = b & 63, hi = std::min<std::size_t>(64, lo + (end - b));
      const std::uint64_t mask = (hi == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << hi) - 1) & (~std::uint64_t{0} << lo);
      std::uint64_t bits = words_[word] & mask;
      words_[word] &= ~mask;
      while (bits) {
        const auto j = static_cast<std::size_t>(std::countr_zero(bits));
        out.push_back(sp.pos + (word * 64 + j - sp.bit));
        bits &= bits - 1;
      }
      b = word * 64 + hi;
    }
  }
}

}  // namespace sillage::detail

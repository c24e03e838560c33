#include "sillage/cn/dirty_atoms.h"

#include <algorithm>
#include <bit>

namespace sillage::detail {

std::size_t DirtyAtoms::lay_out(const CnNode& node, Span* spans) {
  std::size_t bit = 0;
  for (std::size_t g = 0; g < node.ranges().size(); ++g) {
    const AtomRange& w = node.watched()[g];
    spans[g] = {w.first, w.count, bit};
    bit += w.count;
  }
  return bit;
}

void DirtyAtoms::add_node(const CnNode& node) {
  first_span_.push_back(spans_.size());
  spans_.resize(spans_.size() + node.ranges().size());
  const std::size_t bits = lay_out(node, spans_.data() + first_span_.back());
  words_.emplace_back((bits + 63) / 64, 0);
  wakes_.push_back(0);
}

void DirtyAtoms::relayout_node(std::size_t i, const CnNode& node) {
  for (std::size_t g = 0; g < node.ranges().size(); ++g) {
    if (spans_[first_span_[i] + g].lo < spans_[first_span_[i] + g].hi) --marked_spans_;
  }
  const std::size_t bits = lay_out(node, spans_.data() + first_span_[i]);
  words_[i].assign((bits + 63) / 64, 0);
  wakes_[i] = 0;
}

void DirtyAtoms::clear_nodes() {
  words_.clear();
  spans_.clear();
  first_span_.clear();
  wakes_.clear();
  marked_spans_ = 0;
}

void DirtyAtoms::reset() {
  if (marked_spans_ == 0) {  // nothing marked: only the counters
    std::fill(wakes_.begin(), wakes_.end(), 0);
    return;
  }
  for (std::size_t i = 0; i < words_.size(); ++i) {
    const std::size_t end = i + 1 < first_span_.size() ? first_span_[i + 1] : spans_.size();
    for (std::size_t g = first_span_[i]; g < end; ++g) clear(words_[i], spans_[g]);
  }
  std::fill(wakes_.begin(), wakes_.end(), 0);
}

void DirtyAtoms::clear(std::vector<std::uint64_t>& words, Span& s) {
  if (s.lo < s.hi) {
    std::fill(words.begin() + static_cast<std::ptrdiff_t>(s.lo), words.begin() + static_cast<std::ptrdiff_t>(s.hi), 0);
    --marked_spans_;
  }
  s.lo = kNoWord, s.hi = 0;
}

void DirtyAtoms::take(std::size_t node, const CnNode& n, std::vector<std::size_t>& out) {
  out.clear();
  wakes_[node] = 0;
  std::vector<std::uint64_t>& words = words_[node];
  for (std::size_t g = 0; g < n.ranges().size(); ++g) {
    Span& sp = spans_[first_span_[node] + g];
    if (sp.lo >= sp.hi) continue;
    // Bit b of the span is the node's position pos + (b - sp.bit); only its marked words are read.
    const std::size_t pos = n.offset(g) + (sp.first - n.ranges()[g].first);
    const std::size_t end = std::min(sp.bit + sp.count, 64 * sp.hi);
    const std::size_t begin = std::max(sp.bit, 64 * sp.lo);
    sp.lo = kNoWord, sp.hi = 0;
    --marked_spans_;
    for (std::size_t b = begin; b < end;) {
      // The bits of this span in the word holding b.
      const std::size_t word = b >> 6, lo = b & 63, hi = std::min<std::size_t>(64, lo + (end - b));
      const std::uint64_t mask = (hi == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << hi) - 1) & (~std::uint64_t{0} << lo);
      std::uint64_t bits = words[word] & mask;
      words[word] &= ~mask;
      while (bits) {
        const auto j = static_cast<std::size_t>(std::countr_zero(bits));
        out.push_back(pos + (word * 64 + j - sp.bit));
        bits &= bits - 1;
      }
      b = word * 64 + hi;
    }
  }
}

}  // namespace sillage::detail

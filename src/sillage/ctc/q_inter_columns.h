#pragma once
// QInterColumns: many q-relaxed intersections (q_inter.h) at once, each fed
// one interval at a time. CtcQEval's node needs one per atom of its tubes,
// over the values the observations that changed the atom left: on plaza1's
// first run that is 17 million values, which a list to sort made cost
// 0.7 GB and most of the run. A column keeps instead its q + 1 largest
// lower bounds and q + 1 smallest upper bounds, which decide its q'-relaxed
// hull exactly for every q' <= q (see hull): memory (q + 1) · 16 bytes per
// column, and no sort.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sillage/interval/interval.h"

namespace sillage::detail {

class QInterColumns {
 public:
  QInterColumns() = default;
  // `columns` empty columns, each able to answer for every q' <= q (q >= 0).
  QInterColumns(std::size_t columns, int q) { reset(columns, q); }
  // Empties it and sets the layout, keeping the memory it had (a network
  // node reuses one per thread: no page to fault in again at every run).
  void reset(std::size_t columns, int q);

  // Adds x (possibly empty: a constraint no point satisfies) to a column.
  void add(std::size_t column, const Interval& x);
  // The number of intervals added to the column.
  std::size_t count(std::size_t column) const { return count_[column]; }
  // q_inter of the column's intervals with q' (0 <= q' <= q): the hull of the
  // points in at least count - q' of them; the whole line when q' >= count.
  Interval hull(std::size_t column, int q_prime) const;

 private:
  std::size_t k_ = 1;  // q + 1 bounds kept per side
  std::vector<std::uint32_t> count_, empties_;
  // k_ per column: lows_ descending, highs_ ascending; the first
  // min(count - empties, k_) of each are set.
  std::vector<double> lows_, highs_;
};

}  // namespace sillage::detail

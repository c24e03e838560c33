#include "sillage/expr/hc4_rows.h"

#include <algorithm>
#include <vector>

#include "sillage/expr/function_impl.h"
#include "sillage/expr/tape.h"

namespace sillage::detail {

namespace {

// One row of kMaxBoxes intervals per slot of the largest tape met, per thread.
Interval* thread_rows(std::size_t slots) {
  thread_local std::vector<Interval> rows;
  if (rows.size() < slots * Hc4Rows::kMaxBoxes) rows.resize(slots * Hc4Rows::kMaxBoxes);
  return rows.data();
}

}  // namespace

Hc4Rows::Hc4Rows(const Function& f) : tape_(f.impl_->tape), rows_(thread_rows(f.impl_->tape.size())) {}

Interval* Hc4Rows::var_row(std::size_t i, std::size_t count) const { return rows_ + i * count; }

void Hc4Rows::contract(std::size_t count, const IntervalVector& y, std::uint8_t* ok) const {
  std::fill(ok, ok + count, y.is_empty() ? 0 : 1);
  const std::size_t n = tape_.nb_vars();
  thread_local std::vector<const Interval*> cols;
  cols.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Interval* const r = var_row(i, count);
    for (std::size_t j = 0; j < count; ++j)
      if (r[j].is_empty()) ok[j] = 0;
    cols[i] = r;
  }
  tape_.forward_batch(cols.data(), count, rows_, nullptr);
  tape_.backward_batch(rows_, count, y.components().data(), ok);
}

}  // namespace sillage::detail

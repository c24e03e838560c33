#include "sillage/expr/hc4_rows.h"

#include <algorithm>
#include <vector>

#include "sillage/expr/function_impl.h"
#include "sillage/expr/tape.h"

namespace sillage::detail {

namespace {

// The thread's rows, and whether an Hc4Rows holds them.
struct ThreadRows {
  std::vector<Interval> rows;
  bool held = false;
};

ThreadRows& thread_rows() {
  thread_local ThreadRows r;
  return r;
}

}  // namespace

Hc4Rows::Hc4Rows(const Function& f) : tape_(f.impl_->tape), shared_(!thread_rows().held) {
  const std::size_t size = tape_.size() * kMaxBoxes;
  std::vector<Interval>& rows = shared_ ? thread_rows().rows : own_;
  if (rows.size() < size) rows.resize(size);
  rows_ = rows.data();
  if (shared_) thread_rows().held = true;
}

Hc4Rows::~Hc4Rows() {
  if (shared_) thread_rows().held = false;
}

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

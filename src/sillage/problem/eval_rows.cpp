#include "sillage/problem/eval_rows.h"

#include "sillage/interval/rounding.h"

namespace sillage::detail {

// rounding.h's steps rather than std::nextafter: the same doubles without a
// libm call (plaza1.toml reads about 10 000 cells; nextafter was 5 % of its build).
Interval csv_cell(double d) { return Interval(rounding::next_down(d), rounding::next_up(d)); }

bool eval_row_kept(const ConstraintSpec& c, const CsvTable& table, const std::vector<double>& values) {
  for (const auto& [col, value] : c.where)
    if (values[table.column(col)] != value) return false;
  return true;
}

Interval eval_row_time(const ConstraintSpec& c, const CsvTable& table, const std::vector<double>& values,
                       const Interval& terr, const Interval& domain) {
  if (c.time_columns.empty()) return domain;
  Interval t = csv_cell(values[table.column(c.time_columns[0])]);
  if (c.time_columns.size() == 2) t |= csv_cell(values[table.column(c.time_columns[1])]);
  return (t + Interval(-1, 1) * terr) & domain;
}

RowObservation::RowObservation(std::shared_ptr<const Ctc> obs, std::shared_ptr<const std::vector<int>> slots,
                               std::size_t nz, IntervalVector values)
    : Ctc(nz), obs_(std::move(obs)), slots_(std::move(slots)), values_(std::move(values)) {}

void RowObservation::contract(IntervalVector& z) const {
  check_dim(z);
  thread_local IntervalVector box(1);  // scratch, per thread
  const std::vector<int>& slots = *slots_;
  if (box.size() != slots.size()) box = IntervalVector(slots.size());
  std::size_t v = 0;
  for (std::size_t k = 0; k < slots.size(); ++k) box[k] = slots[k] >= 0 ? z[static_cast<std::size_t>(slots[k])] : values_[v++];
  obs_->contract(box);
  for (std::size_t k = 0; k < slots.size(); ++k)
    if (slots[k] >= 0) z[static_cast<std::size_t>(slots[k])] &= box[k];
}

}  // namespace sillage::detail

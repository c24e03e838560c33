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

}  // namespace sillage::detail

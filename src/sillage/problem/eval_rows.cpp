#include "sillage/problem/eval_rows.h"

#include <cmath>

namespace sillage::detail {

Interval csv_cell(double d) { return Interval(std::nextafter(d, -INFINITY), std::nextafter(d, INFINITY)); }

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

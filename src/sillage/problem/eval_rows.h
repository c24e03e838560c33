#pragma once
// The rows of an eval constraint: which are kept and at what time (internal;
// shared by load_eval.cpp, which checks the times against [t0, tf], and
// build_network.cpp, which builds one CtcEval per row).
#include <vector>

#include "sillage/interval/interval.h"
#include "sillage/io/csv.h"
#include "sillage/problem/problem.h"

namespace sillage::detail {

// A CSV cell as written: its decimal text is within half an ulp of the
// double read, so the double's neighbours enclose it.
Interval csv_cell(double d);

// True if the row passes the constraint's `where` filter.
bool eval_row_kept(const ConstraintSpec& c, const CsvTable& table, const std::vector<double>& values);

// The time of a row: the stamp ± terr, or [lb, ub] ± terr, or the whole
// domain (no time column: unknown), within the domain (empty: outside it).
Interval eval_row_time(const ConstraintSpec& c, const CsvTable& table, const std::vector<double>& values,
                       const Interval& terr, const Interval& domain);

}  // namespace sillage::detail

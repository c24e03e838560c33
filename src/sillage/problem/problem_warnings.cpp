#include "sillage/problem/problem_warnings.h"

#include <algorithm>

#include "sillage/problem/eval_rows.h"

namespace sillage {

std::vector<std::string> problem_warnings(const Problem& p) {
  std::vector<std::string> out;
  for (const ConstraintSpec& c : p.constraints) {
    if (c.kind != ConstraintKind::Eval) continue;
    const CsvTable& t = p.table(c.data)->table;
    std::size_t used = 0;
    for (std::size_t row = 0; row < t.nb_rows(); ++row) used += detail::eval_row_kept(c, t, t.row(row));
    used -= std::min(used, c.nb_outside);
    if (used > 0) continue;
    const std::string why = t.nb_rows() == 0 ? "the table '" + c.data + "' (" + t.source() + ") has only its header"
                                             : "none of the " + std::to_string(t.nb_rows()) + " rows of '" + c.data +
                                                   "' is used ('where', outside = \"skip\")";
    out.push_back(why + ": " + c.label + " (" + c.pos.str() + ") states nothing, and the problem is solved without it");
  }
  for (const VarSpec& v : p.vars) {
    if (!v.is_tube() || p.deriv_of(v.name)) continue;
    const bool between = v.gates || std::any_of(v.at.begin(), v.at.end(), [](const GateSpec& g) { return g.t_lo != g.t_hi; });
    if (!between) continue;
    const SourcePos& at = v.gates ? v.gates->value.pos : v.pos;
    out.push_back("the values of " + v.name + " at times between two doubles (" + at.str() +
                  ": a decimal such as 0.1, or a table's stamps) bound no gate of " + v.name +
                  ", which has no deriv constraint: only a bound on " + v.name + "' carries a value from the time as "
                  "written to the time point next to it");
  }
  return out;
}

}  // namespace sillage

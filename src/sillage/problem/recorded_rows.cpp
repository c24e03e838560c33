// The rows of a problem's own tables in the order a robot receives them
// (OnlineProblem::recorded_rows, what `sillage replay` feeds).
#include <algorithm>
#include <cmath>

#include "online_problem_impl.h"

namespace sillage {

using detail::EvalPlan;
using detail::kInf;
using detail::Waiting;

std::vector<StreamRow> OnlineProblem::recorded_rows() const {
  const detail::OnlineProblemImpl& m = *impl_;
  struct Keyed {
    double key;
    int rank;  // clock rows before the observations of their time
    StreamRow row;
  };
  std::vector<Keyed> rows;
  const auto row_of = [&](const std::string& name, std::size_t i) {
    const CsvTable& t = m.p.table(name)->table;
    StreamRow r{name, std::nullopt, {}};
    const std::span<const double> v = t.row(i);
    for (std::size_t c = 0; c < v.size(); ++c) r.columns[t.columns()[c]] = v[c];
    return r;
  };
  const std::vector<double>& pts = m.p.time.points;
  if (m.delta > 0) {
    const auto n = static_cast<std::size_t>(std::ceil((m.p.time.tf - m.p.time.t0) / m.delta));
    for (std::size_t k = 1; k <= n; ++k) {
      const double t = m.p.time.t0 + static_cast<double>(k) * m.delta;
      rows.push_back({t, 0, StreamRow{"", t, {}}});
    }
  } else {
    const CsvTable& clock = m.p.table(m.clock)->table;
    const bool periods = !m.inputs.empty();  // row k: the period [t_k, t_k+1]
    for (std::size_t k = periods ? 0 : 1; k + 1 < pts.size() + (periods ? 0 : 1) && k < clock.nb_rows(); ++k) {
      StreamRow r = row_of(m.clock, k);
      r.t = periods ? pts[k + 1] : pts[k];
      rows.push_back({*r.t, 0, std::move(r)});
    }
  }
  for (const auto& [name, plans] : m.evals) {
    if (name == m.clock) continue;
    const CsvTable& t = m.p.table(name)->table;
    for (std::size_t i = 0; i < t.nb_rows(); ++i) {
      double stamp = kInf;  // no time column: after the whole run
      for (const EvalPlan& e : plans) {
        if (e.c->time_columns.empty()) continue;
        double s = -kInf;
        for (const std::string& col : e.c->time_columns) s = std::max(s, t.row(i)[t.column(col)]);
        stamp = std::min(stamp, s);
      }
      StreamRow r = row_of(name, i);
      if (std::isfinite(stamp)) r.t = std::max(stamp, m.p.time.t0);
      rows.push_back({stamp, 1, std::move(r)});
    }
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Keyed& a, const Keyed& b) {
    return a.key < b.key || (a.key == b.key && a.rank < b.rank);
  });
  // An observation goes after the clock row that reaches its stamp.
  std::vector<StreamRow> out;
  std::vector<StreamRow> held;
  double reached = m.p.time.t0;
  for (Keyed& k : rows) {
    if (k.rank == 0) {
      out.push_back(std::move(k.row));
      reached = k.key;
      for (StreamRow& h : held) out.push_back(std::move(h));
      held.clear();
    } else if (k.key <= reached) {
      out.push_back(std::move(k.row));
    } else {
      held.push_back(std::move(k.row));
    }
  }
  for (StreamRow& h : held) out.push_back(std::move(h));
  return out;
}

}  // namespace sillage

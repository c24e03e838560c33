#include "sillage/problem/online_problem.h"

#include <cmath>

#include "online_problem_impl.h"
#include "sillage/error.h"
#include "sillage/problem/eval_rows.h"
#include "sillage/tube/tube.h"

namespace sillage {

using detail::csv_cell;
using detail::EvalPlan;
using detail::kInf;
using detail::Waiting;

OnlineOptions online_options(const Problem& p) {
  OnlineOptions o;
  o.window = p.online.window.value_or(kInf);
  o.forget_every = p.online.forget_every;
  if (p.network.ratio) o.ratio = *p.network.ratio;
  return o;
}

// The row's values in its table's column order (NaN where not given);
// every column the constraints read given, no unknown one, none NaN.
std::vector<double> detail::OnlineProblemImpl::values_of(const StreamRow& row) const {
  const CsvTable& table = p.table(row.table)->table;
  for (const auto& [name, value] : row.columns) {
    if (!table.has_column(name)) throw Error("a row of " + row.table + ": no column " + name + " in that table");
    if (std::isnan(value)) throw Error("a row of " + row.table + ": " + name + " is NaN");
  }
  std::vector<double> values(table.columns().size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < values.size(); ++i)
    if (const auto it = row.columns.find(table.columns()[i]); it != row.columns.end()) values[i] = it->second;
  if (const auto it = needed.find(row.table); it != needed.end())
    for (const std::string& col : it->second)
      if (!row.columns.count(col)) throw Error("a row of " + row.table + " without its column " + col);
  return values;
}


// Time advances to t with the clock row's inputs (none for a tick).
void detail::OnlineProblemImpl::advance(double t, const std::vector<std::pair<std::string, IntervalVector>>& given) {
  est->advance(t, given);
  release();
  report();
}

// The estimate to the callback, when it changed since the last report.
void detail::OnlineProblemImpl::report() {
  const std::size_t n = est->stats().updates;
  if (n == reported) return;
  reported = n;
  if (updated) updated();
}

// The waiting observations whose time has begun.
void detail::OnlineProblemImpl::release() {
  std::vector<Waiting> still;
  for (Waiting& w : waiting) {
    if (w.t.lb() <= est->now()) est->observe(w.t, w.states, std::move(w.ctc));
    else still.push_back(std::move(w));
  }
  waiting = std::move(still);
}

// δ: to the first grid point at or after t.
void detail::OnlineProblemImpl::tick(double t) {
  if (delta == 0) {
    throw Error("time advances with the rows of " + (clock.empty() ? p.time.points_data : clock) +
                " (the [time] points), not by a row of no table");
  }
  while (est->now() < t) {
    ++ticks;
    advance(p.time.t0 + static_cast<double>(ticks) * delta, {});
  }
}

void detail::OnlineProblemImpl::clock_row(const StreamRow& row, const std::vector<double>& values) {
  if (!row.t) throw Error("a row of " + row.table + " without \"t\", the end of its period");
  const double t = *row.t;
  if (!(t > est->now())) throw Error("a row of " + row.table + " at t = " + number_text(t) + ", not after now = " + number_text(est->now()));
  std::vector<std::pair<std::string, IntervalVector>> given;
  IntervalVector args(values.size() + 1);
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isnan(values[i])) args[i] = csv_cell(values[i]);  // a column not given is not read
  const Interval period(est->now(), t);
  args[values.size()] = Interval(t) - Interval(est->now());
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const VarSpec* v = inputs[i];
    Interval x = input_values[i].eval(args);
    if (input_bounds[i]) x &= detail::unknown_where_undefined(input_bounds[i]->eval(IntervalVector{period}));
    if (x.is_empty()) throw Error("a row of " + row.table + " gives " + v->name + " an empty value over [" +
                                  number_text(period.lb()) + ", " + number_text(t) + "]");
    given.emplace_back(v->name, IntervalVector{x});
  }
  advance(t, given);
}

void detail::OnlineProblemImpl::observation_rows(const StreamRow& row, const std::vector<double>& values) {
  const CsvTable& table = p.table(row.table)->table;
  std::vector<Waiting> obs;
  const double arrived = row.t.value_or(est->now());
  for (const EvalPlan& e : evals.at(row.table)) {
    const ConstraintSpec& c = *e.c;
    if (!detail::eval_row_kept(c, table, values)) continue;
    std::span<const double> join_values;
    const CsvTable* joined = c.join_data.empty() ? nullptr : &p.table(c.join_data)->table;
    if (joined) {
      const auto j = e.join_rows.find(values[table.column(c.join_on)]);
      if (j == e.join_rows.end())
        throw Error("a row of " + row.table + ": " + c.join_on + " = " + detail::cell_text(values[table.column(c.join_on)]) +
                    " is in no row of " + c.join_data);
      join_values = joined->row(j->second);
    }
    const Interval t = c.time_columns.empty()
                           ? Interval(est->window_start(), std::min(arrived, est->now()))
                           : detail::eval_row_time(c, table, values, e.terr, Interval(-kInf, kInf));
    if (t.lb() < est->window_start())
      throw Error("a row of " + row.table + " at t in " + t.str() + ": older than the window [" +
                  number_text(est->window_start()) + ", " + number_text(est->now()) + "]");
    if (t.lb() > est->now() + p.online.lead)
      throw Error("a row of " + row.table + " at t in " + t.str() + ": beyond now = " + number_text(est->now()) +
                  " + lead " + number_text(p.online.lead) + " s ([online] lead)");
    std::vector<Interval> measured;
    for (const std::string& col : e.measured) {
      const auto err = e.errors.find(col);
      const double v = table.has_column(col) ? values[table.column(col)] : join_values[joined->column(col)];
      measured.push_back(csv_cell(v) + Interval(-1, 1) * (err == e.errors.end() ? Interval(0) : err->second));
    }
    obs.push_back({t, c.ys, std::make_shared<detail::RowObservation>(e.obs, e.slots, e.nz, IntervalVector(measured))});
  }
  for (Waiting& w : obs) waiting.push_back(std::move(w));
  release();
}

OnlineProblem::OnlineProblem(const Problem& p, std::optional<OnlineOptions> options) : impl_(std::make_unique<detail::OnlineProblemImpl>(p)) {
  detail::OnlineProblemImpl& m = *impl_;
  m.est = std::make_unique<OnlineEstimator>(p.time.t0, options.value_or(online_options(p)));
  m.est->network().set_scheduling(p.network.scheduling);
  if (p.time.points.empty()) m.delta = *p.time.delta;
  m.declare_vars();
  m.parse_inputs();
  m.declare_constraints();
  if (m.clock.empty() && m.delta == 0) m.clock = p.time.points_data;
}

OnlineProblem::~OnlineProblem() = default;

void OnlineProblem::feed(const StreamRow& row) {
  detail::OnlineProblemImpl& m = *impl_;
  if (row.t && !std::isfinite(*row.t)) throw Error("a row at t = " + number_text(*row.t) + ": not finite");
  if (row.table.empty()) {
    if (!row.t) throw Error("a row of no table (a tick) without \"t\"");
    m.tick(*row.t);
    return;
  }
  if (!m.p.table(row.table)) throw Error("no table " + row.table + " in " + m.p.file);
  const bool is_clock = row.table == m.clock, observed = m.evals.count(row.table) > 0;
  if (!is_clock && !observed)
    throw Error("the table " + row.table + " is read by no online constraint (the clock is " +
                (m.clock.empty() ? "a slice width" : m.clock) + ")");
  const std::vector<double> values = m.values_of(row);
  if (is_clock) {
    m.clock_row(row, values);
  } else if (row.t && m.delta > 0) {
    m.tick(*row.t);
  }
  if (observed) m.observation_rows(row, values);
  m.report();
}

void OnlineProblem::on_update(std::function<void()> f) { impl_->updated = std::move(f); }

const std::vector<std::string>& OnlineProblem::outputs() const { return impl_->outputs; }

std::size_t OnlineProblem::waiting() const { return impl_->waiting.size(); }

OnlineEstimator& OnlineProblem::estimator() { return *impl_->est; }

const OnlineEstimator& OnlineProblem::estimator() const { return *impl_->est; }

}  // namespace sillage

#include "sillage/problem/solve_problem.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "sillage/problem/before_empty.h"
#include "sillage/problem/eval_rows.h"
#include "sillage/problem/problem_warnings.h"
#include "sillage/problem/refined_points.h"

namespace sillage {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

std::string explain(const Problem& p, const BuiltProblem& b, const ContractStats& s) {
  std::string why = s.emptiness;
  if (s.empty_node >= b.first_value_node && s.empty_node < b.first_value_node + b.value_nodes.size()) {
    why += "; by " + b.value_nodes[s.empty_node - b.first_value_node];
  } else if (s.empty_node < b.cn->nb_ctc() && !b.first_node.empty()) {
    const ConstraintSpec& c = p.constraints[b.constraint_of_node(s.empty_node)];
    why += "; by " + c.label + " (" + c.pos.str() + ")";
  } else if (s.empty_node == static_cast<std::size_t>(-1)) {
    why += "; the initial bounds are empty (" + p.file + ": [var." + s.empty_domain_name + "])";
  }
  return why;
}

}  // namespace

double SolveResult::build_seconds() const {
  double s = 0;
  for (const ScheduleStep& st : schedule) s += st.build_seconds;
  return s;
}

double SolveResult::contract_seconds() const {
  double s = 0;
  for (const ScheduleStep& st : schedule) s += st.contract_seconds;
  return s;
}

double mean_thickness(const BuiltProblem& b) {
  double sum = 0;
  const double duration = b.td->tf() - b.td->t0();
  for (const VarDomain& v : b.vars) {
    if (!v.tubes) continue;
    for (std::size_t i = 0; i < v.tubes->size(); ++i) {
      const double vol = (*v.tubes)[i].volume();
      if (std::isfinite(vol)) sum += vol / duration;
    }
  }
  return sum;
}

namespace {

// "expected no delta: ...", for a delta given to a problem with time points from a table.
std::string no_delta(const Problem& p) {
  return "expected no delta: the time points of this problem are the stamps of the table '" + p.time.points_data +
         "' ([time] points at " + p.time.pos.str() + "), one slice per period of the data";
}

}  // namespace

void check_delta(const Problem& p, double delta, const std::string& name) {
  if (!p.time.points.empty()) throw Error(name + ": found " + detail::cell_text(delta) + ", " + no_delta(p));
  const double span = p.time.tf - p.time.t0;
  if (!(delta > 0) || !(delta <= span))
    throw Error(name + ": found " + number_text(delta) + ", expected a slice width in (0, " + number_text(span) +
                "] (tf - t0 of the problem's [time] domain)");
  if (span / delta > kMaxSlices)
    throw Error(name + ": found " + number_text(delta) + " (" + number_text(std::ceil(span / delta)) +
                " slices), expected a larger delta (at most " + number_text(kMaxSlices) + " slices)");
}

void check_solve_options(const Problem& p, const SolveOptions& o, const std::string& prefix) {
  if (o.delta) check_delta(p, *o.delta, prefix + "delta");
  if (o.auto_delta && !p.time.points.empty()) throw Error(prefix + "delta: found auto, " + no_delta(p));
  const bool automatic = p.time.points.empty() && (o.auto_delta || (!o.delta && !p.time.delta));
  if (o.refinement == DeltaRefinement::Regions && !automatic)
    throw Error(prefix + "refine: found regions, expected it with an automatic delta (" + prefix +
                "delta auto, or delta = \"auto\" in [time]): a fixed delta is not refined");
}

namespace {

// The steps of the solve, into r: a fixed δ, or δ refined until the result settles.
void solve_steps(const Problem& p, const SolveOptions& o, SolveResult& r) {
  std::optional<double> fixed = o.delta ? o.delta : p.time.delta;
  if (o.auto_delta) fixed.reset();
  if (!p.time.points.empty())
    fixed = (p.time.tf - p.time.t0) / static_cast<double>(p.time.points.size() - 1);  // the mean period, for the reports
  const auto start = std::chrono::steady_clock::now();
  double delta = fixed ? *fixed : (p.time.tf - p.time.t0) / 64;
  std::vector<double> points;  // regions: the time points of the next step (none: the uniform δ)
  for (;;) {
    ScheduleStep step;
    step.delta = delta;
    auto t0 = std::chrono::steady_clock::now();
    check_memory(p, points.empty() ? nb_slices_for(p, delta) : points.size() - 1,
                 points.empty() ? "delta = " + number_text(delta) : "the refined time points");
    BuiltProblem b = points.empty() ? build_network(p, delta) : build_network(p, points);
    step.build_seconds = seconds_since(t0);
    step.slices = b.td->nb_slices();
    if (o.scheduling) b.cn->set_scheduling(*o.scheduling);
    b.cn->set_budget(o.budget);
    r.scheduling = b.cn->scheduling();
    if (!points.empty()) {
      step.delta = INFINITY;
      for (std::size_t k = 0; k < step.slices; ++k) step.delta = std::min(step.delta, b.td->t(k + 1) - b.td->t(k));
    }
    t0 = std::chrono::steady_clock::now();
    try {
      step.stats = b.cn->contract();
    } catch (const BudgetExceeded& e) {  // the domains contracted so far are still enclosures: an answer
      r.stopped = e.what();
      step.stats = b.cn->stopped_stats();
    }
    step.contract_seconds = seconds_since(t0);
    step.mean_thickness = step.stats.empty ? 0 : mean_thickness(b);
    r.schedule.push_back(step);
    if (o.on_step) o.on_step(step);
    r.built = std::move(b);
    if (!r.stopped.empty()) return;
    if (step.stats.empty) {
      r.empty = true;
      r.why_empty = explain(p, r.built, step.stats);
      if (o.keep_before_empty) r.before_empty = detail::before_empty(p, points, delta, o, step.stats);
      return;
    }
    if (fixed) return;
    if (r.schedule.size() >= 2) {
      const double prev = r.schedule[r.schedule.size() - 2].mean_thickness, cur = step.mean_thickness;
      if (std::abs(prev - cur) <= o.tolerance * std::abs(prev)) return;
    }
    std::size_t next_slices = 2 * step.slices;
    if (o.refinement == DeltaRefinement::Regions) {
      points = detail::refined_points(r.built, o.split_quantile);
      next_slices = points.size() - 1;
    }
    // The next step, estimated in proportion to its slices.
    const double last = step.build_seconds + step.contract_seconds;
    const double growth = static_cast<double>(next_slices) / static_cast<double>(step.slices);
    if (seconds_since(start) + growth * last > o.budget_seconds) return;
    if (next_slices > o.max_slices || next_slices == step.slices) return;
    delta /= 2;
  }
}

// The summary of the solve: the status of its last step, the counters of all.
Summary solve_summary(const SolveResult& r, double seconds) {
  Summary s;
  s.status = !r.stopped.empty() ? Status::Stopped : r.empty ? Status::NoSolution : Status::Converged;
  s.reason = !r.stopped.empty() ? r.stopped : r.why_empty;
  for (const ScheduleStep& step : r.schedule) {
    s.rounds += step.stats.summary.rounds;
    s.work += step.stats.summary.work;
  }
  s.seconds = seconds;
  return s;
}

}  // namespace

SolveResult solve_problem(const Problem& p, const SolveOptions& o) {
  check_solve_options(p, o, "");
  SolveResult r;
  r.warnings = problem_warnings(p);
  const auto start = std::chrono::steady_clock::now();
  solve_steps(p, o, r);
  r.summary = solve_summary(r, seconds_since(start));
  return r;
}

}  // namespace sillage

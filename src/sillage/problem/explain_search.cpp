#include "sillage/problem/explain_search.h"

#include <cmath>
#include <limits>

#include "sillage/expr/function.h"
#include "sillage/problem/eval_rows.h"

namespace sillage::detail {

namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

ExplainSearch::ExplainSearch(const Problem& problem, const ExplainOptions& options, const SolveResult& failed)
    : p(problem), o(options), start_(std::chrono::steady_clock::now()) {
  if (!(o.max_seconds >= 0)) throw Error("explain_empty: max_seconds: found " + number_text(o.max_seconds) + ", expected >= 0 (0: no limit)");
  if (o.min_rows == 0) throw Error("explain_empty: min_rows: found 0, expected a number of rows >= 1");
  check_budget(o.budget, "explain_empty");
  e.empty = failed.empty;
  e.why_empty = failed.why_empty;
  if (!failed.stopped.empty()) e.stopped = "the problem's own solve stopped before its fixed point: " + failed.stopped;
  const ScheduleStep& last = failed.schedule.back();
  e.slices = last.slices;
  e.delta = o.delta ? *o.delta : (p.time.tf - p.time.t0) / static_cast<double>(last.slices);
  if (p.time.points.empty() && !o.delta) {
    // The failing step's own δ when its slices are uniform (halving: exactly it).
    if (nb_slices_for(p, last.delta) == last.slices) e.delta = last.delta;
    trial_options_.delta = e.delta;
  } else if (o.delta) {
    trial_options_.delta = *o.delta;
  }
  trial_options_.scheduling = o.scheduling ? o.scheduling : std::optional<Scheduling>(failed.scheduling);
  trial_options_.budget = o.budget;
  trial_options_.keep_before_empty = false;
  check_solve_options(p, trial_options_, "");
}

double ExplainSearch::seconds_left() const {
  return o.max_seconds > 0 ? o.max_seconds - since(start_) : std::numeric_limits<double>::infinity();
}

bool ExplainSearch::out_of_time() const { return seconds_left() <= 0; }

TrialOutcome ExplainSearch::trial(const std::vector<std::size_t>& relaxed, Relaxation* found) {
  if (out_of_time()) {
    ++not_run_;
    return TrialOutcome::Stopped;
  }
  return run(relaxed_problem(p, e.items, relaxed), relaxed, found);
}

TrialOutcome ExplainSearch::run(const Problem& q, const std::vector<std::size_t>& relaxed, Relaxation* found,
                                const std::string& probe) {
  const double left = seconds_left();
  if (left <= 0) {
    ++not_run_;
    return TrialOutcome::Stopped;
  }
  SolveOptions so = trial_options_;
  if (std::isfinite(left)) so.budget.max_seconds = so.budget.max_seconds > 0 ? std::min(so.budget.max_seconds, left) : left;
  const auto t0 = std::chrono::steady_clock::now();
  SolveResult r;
  std::string error;
  try {
    r = solve_problem(q, so);
  } catch (const Error& x) {  // a relaxation the build refuses: undecided, the search goes on
    error = x.what();
  }
  const TrialOutcome outcome = !error.empty() || !r.stopped.empty() ? TrialOutcome::Stopped
                               : r.empty                           ? TrialOutcome::Empty
                                                                   : TrialOutcome::NotEmpty;
  const double seconds = since(t0);
  if (found && outcome == TrialOutcome::NotEmpty) {
    found->items = relaxed;
    found->values = proven_values(p, q, e.items, relaxed, r.built);
    found->seconds = seconds;
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  e.trials.push_back({relaxed, outcome, seconds, probe, error});
  return outcome;
}

void ExplainSearch::finish() {
  std::size_t stopped = 0, errors = 0;
  std::string first_error;
  for (const ExplainTrial& t : e.trials) {
    stopped += t.outcome == TrialOutcome::Stopped && t.error.empty();
    errors += !t.error.empty();
    if (first_error.empty()) first_error = t.error;
  }
  const std::size_t not_run = not_run_.load();
  e.complete = e.stopped.empty() && stopped == 0 && errors == 0 && not_run == 0;
  if (e.stopped.empty() && !e.complete) {
    e.stopped = std::to_string(e.trials.size() - stopped - errors) + " trials decided";
    if (stopped || not_run)
      e.stopped += ", " + std::to_string(stopped) + " stopped by a budget, " + std::to_string(not_run) +
                   " not run: the search's " + number_text(o.max_seconds) +
                   " s were spent (ExplainOptions::max_seconds; sillage --explain-seconds) or a contraction's budget";
    if (errors) e.stopped += ", " + std::to_string(errors) + " not solvable once relaxed (" + first_error + ")";
  }
  e.seconds = since(start_);
}

namespace {

Interval constant_value(const std::string& expr, const Interval& t) {
  return Function({"t"}, expr).eval(IntervalVector{t});
}

std::string component(const VarSpec& v, std::size_t i) {
  return v.dim > 1 ? v.name + "[" + std::to_string(i) + "]" : v.name;
}

}  // namespace

std::vector<ProvenValue> proven_values(const Problem& p, const Problem& q, const std::vector<ExplainItem>& items,
                                       const std::vector<std::size_t>& relaxed, const BuiltProblem& b) {
  std::vector<ProvenValue> out;
  const Interval domain(p.time.t0, p.time.tf);
  for (const std::size_t k : relaxed) {
    const ExplainItem& it = items[k];
    if (it.kind != ItemKind::Bound && it.kind != ItemKind::Gate) continue;
    const VarSpec& v = *p.var(it.var);
    const VarDomain& d = b.var(it.var);
    if (it.kind == ItemKind::Bound) {
      const std::size_t i = it.index;
      const Interval proven = d.tubes ? (*d.tubes)[i].codomain() : d.interval ? *d.interval : (*d.box)[i];
      out.push_back({component(v, i) + (d.tubes ? " over [t0, tf]" : ""), constant_value(v.value[i].expr, domain), proven,
                     Interval(), {}});
      continue;
    }
    // A gate: the tube over the time as written (between two doubles), through its derivative
    // when a deriv constraint of the relaxed problem q gives one, as the report's results.
    const GateSpec& g = v.at[it.index];
    const Interval at = Interval(g.t_lo, g.t_hi) & b.td->t0_tf();  // a decimal t0 may lie below the double t0
    const ConstraintSpec* dv = q.deriv_of(v.name);
    for (std::size_t i = 0; i < v.dim; ++i) {
      const Tube& x = (*d.tubes)[i];
      const Interval proven = dv ? x.eval(at, (*b.var(dv->v).tubes)[i]) : x(at);
      out.push_back({component(v, i) + "(" + cell_text(g.t) + ")", constant_value(g.value[i].expr, at), proven, Interval(), {}});
    }
  }
  return out;
}

}  // namespace sillage::detail

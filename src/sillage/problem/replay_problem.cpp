#include "sillage/problem/replay_problem.h"

#include "sillage/interval/angle.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "sillage/error.h"

namespace sillage {

namespace {

// [output.truth] checked as time passes: the samples in the new slice
// (prev, now] against the online tubes at their time.
struct TruthWalk {
  const Problem& p;
  const CsvTable* table = nullptr;
  std::vector<std::size_t> order;  // rows by time
  std::size_t next = 0;
  explicit TruthWalk(const Problem& problem) : p(problem) {
    if (!p.output.truth) return;
    table = &p.table(p.output.truth->data)->table;
    const std::size_t tc = table->column(p.output.truth->time_column);
    for (std::size_t r = 0; r < table->nb_rows(); ++r) order.push_back(r);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return table->row(a)[tc] < table->row(b)[tc]; });
  }
  void check(const OnlineEstimator& est, ReplayResult& r) {
    if (!table) return;
    const std::size_t tc = table->column(p.output.truth->time_column);
    for (; next < order.size() && table->row(order[next])[tc] <= est.now(); ++next) {
      const std::span<const double> row = table->row(order[next]);
      const double time = row[tc];
      if (time < est.window_start()) continue;  // before the start
      ++r.truth_samples;
      bool inside = true, bounded = true;
      for (const auto& [var, cols] : p.output.truth->columns) {
        const auto tube = est.tube(var);
        for (std::size_t i = 0; i < cols.size(); ++i) {
          const double value = row[table->column(cols[i])];
          const Interval x = (*tube)[i](time);
          const bool angle = p.var(var)->angle;  // on its arc modulo 2π; the whole circle proves nothing
          bounded = bounded && (angle ? !angle_is_circle(x) : x.is_bounded());
          if (angle ? angle_contains(x, value) : x.contains(value)) continue;
          inside = false;
          if (r.truth_misses.size() < 10)
            r.truth_misses.push_back(var + "[" + std::to_string(i) + "] = " + number_text(value) + " at t = " +
                                     number_text(time) + " outside " + x.str());
        }
      }
      r.truth_inside += inside && bounded;  // unbounded proves nothing: no pass
      r.truth_unbounded += inside && !bounded;
    }
  }
};

}  // namespace

ReplayResult replay_problem(const Problem& p, const ReplayOptions& o) {
  if (!(o.speed >= 0) || std::isinf(o.speed)) throw Error("replay: speed must be finite and >= 0, got " + number_text(o.speed));
  ReplayResult r;
  OnlineProblem op(p, o.online);
  r.outputs = op.outputs();
  TruthWalk truth(p);
  using Clock = std::chrono::steady_clock;
  Clock::duration aside{};  // spent keeping and writing the estimates: not the estimator's latency
  op.on_update([&] {
    const auto called = Clock::now();
    const OnlineEstimator& est = op.estimator();
    r.t.push_back(est.now());
    std::vector<IntervalVector> boxes;
    for (const std::string& name : r.outputs) boxes.push_back(est.now(name));
    r.online.push_back(std::move(boxes));
    truth.check(est, r);
    if (o.on_update) o.on_update(op);
    aside += Clock::now() - called;
  });
  const std::vector<StreamRow> rows = op.recorded_rows();
  const auto start = std::chrono::steady_clock::now();
  const auto check_cancel = [&] {
    if (o.budget.cancel.cancelled()) {
      throw Cancelled("replay_problem: at row " + std::to_string(r.rows + 1) + " of " + std::to_string(rows.size()) +
                      " (t = " + number_text(op.estimator().now()) + ")");
    }
  };
  for (const StreamRow& row : rows) {
    check_cancel();
    if (o.speed > 0 && row.t) {  // wait for the row's time, N times faster than it was recorded
      const auto due = start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                   std::chrono::duration<double>((*row.t - p.time.t0) / o.speed));
      // In steps of at most 50 ms, so that a cancellation is seen while waiting.
      while (Clock::now() < due) {
        std::this_thread::sleep_until(std::min(due, Clock::now() + std::chrono::milliseconds(50)));
        check_cancel();
      }
    }
    const auto fed = Clock::now();
    aside = {};
    try {
      op.feed(row);
    } catch (const Error& e) {
      r.refused.push_back(row.table + (row.t ? " at t = " + number_text(*row.t) : "") + ": " + e.what());
    }
    r.latency.push_back(std::chrono::duration<double>(Clock::now() - fed - aside).count());
    ++r.rows;
    if (op.estimator().last_update().summary.status == Status::NoSolution) break;  // empty: stays so
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.summary = op.estimator().last_update().summary;
  if (o.batch) {
    SolveOptions so;
    so.budget = o.budget;
    r.batch_solve = solve_problem(p, so);
    const BuiltProblem& b = r.batch_solve->built;
    for (const double t : r.t) {
      std::vector<IntervalVector> boxes;
      for (const std::string& name : r.outputs) {
        const VarDomain& v = b.var(name);
        boxes.push_back(t >= b.td->t0() && t <= b.td->tf() ? (*v.tubes)(t) : IntervalVector(v.tubes->size()));
      }
      r.batch.push_back(std::move(boxes));
    }
  }
  return r;
}

}  // namespace sillage

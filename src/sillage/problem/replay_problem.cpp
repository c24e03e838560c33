#include "sillage/problem/replay_problem.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include <nlohmann/json.hpp>

#include "sillage/error.h"
#include "sillage/figures/figure.h"

namespace sillage {

namespace {

double side(const IntervalVector& x) {
  double s = 0;
  for (std::size_t i = 0; i < x.size(); ++i) s = std::max(s, x[i].is_empty() ? 0.0 : x[i].diam());
  return s;
}

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
          bounded = bounded && x.is_bounded();
          if (x.contains(value)) continue;
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
  for (const StreamRow& row : rows) {
    if (o.speed > 0 && row.t) {  // wait for the row's time, N times faster than it was recorded
      const auto due = start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                   std::chrono::duration<double>((*row.t - p.time.t0) / o.speed));
      std::this_thread::sleep_until(due);
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
    r.batch_solve = solve_problem(p);
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

double ReplayResult::latency_quantile(double q) const {
  if (latency.empty()) return 0;
  std::vector<double> x = latency;
  const auto i = static_cast<std::size_t>(std::min(q * static_cast<double>(x.size()), static_cast<double>(x.size() - 1)));
  std::nth_element(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(i), x.end());
  return x[i];
}

std::size_t ReplayResult::online_holds_batch() const {
  std::size_t n = 0;
  for (std::size_t k = 0; k < batch.size(); ++k) {
    bool holds = true;
    for (std::size_t j = 0; j < outputs.size(); ++j) {
      for (std::size_t i = 0; i < online[k][j].size(); ++i) {
        const Interval& on = online[k][j][i];
        const double slack = 1e-9 * std::max(1.0, on.mag());
        holds = holds && batch[k][j][i].is_subset(on + Interval(-slack, slack));
      }
    }
    n += holds;
  }
  return n;
}

double ReplayResult::mean_side_ratio(double after) const {
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < batch.size(); ++k) {
    if (t[k] < t.front() + after) continue;
    double on = 0, ba = 0;
    for (std::size_t j = 0; j < outputs.size(); ++j) on = std::max(on, side(online[k][j])), ba = std::max(ba, side(batch[k][j]));
    if (std::isfinite(on) && std::isfinite(ba) && ba > 0) sum += on / ba, ++n;
  }
  return n ? sum / static_cast<double>(n) : NAN;
}

std::string replay_svg(const Problem& p, const ReplayResult& r) {
  double lo = INFINITY, hi = 0;
  const auto each_side = [&](const std::vector<std::vector<IntervalVector>>& boxes, std::size_t j, auto&& f) {
    for (std::size_t k = 0; k < boxes.size(); ++k) {
      const double s = side(boxes[k][j]);
      if (s > 0 && std::isfinite(s)) f(k, s);
    }
  };
  for (std::size_t j = 0; j < r.outputs.size(); ++j)
    for (const auto* b : {&r.online, &r.batch}) each_side(*b, j, [&](std::size_t, double s) { lo = std::min(lo, s), hi = std::max(hi, s); });
  if (!(lo <= hi)) lo = 1, hi = 10;
  const double y0 = std::floor(std::log10(lo)), y1 = std::ceil(std::log10(hi));
  const double t0 = r.t.empty() ? p.time.t0 : r.t.front(), t1 = r.t.empty() ? t0 + 1 : r.t.back();
  Figure fig(IntervalVector{{0, std::max(t1 - t0, 1e-9)}, {y0, y1 + (y1 == y0 ? 1 : 0)}}, 760, 340);
  fig.set_title("sillage replay " + p.file + ": box side now (online) against the batch solve");
  fig.set_labels("t - t0", "log10 box side");
  static const char* colours[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  for (std::size_t j = 0; j < r.outputs.size(); ++j) {
    const std::string c = colours[j % 6];
    const auto curve = [&](const std::vector<std::vector<IntervalVector>>& boxes) {
      std::vector<Vector> pts;
      each_side(boxes, j, [&](std::size_t k, double s) { pts.push_back(Vector{r.t[k] - t0, std::log10(s)}); });
      return pts;
    };
    const Style online{"none", c, 1.4, 1, ""}, batch{"none", c, 0.7, 0.6, ""};
    fig.draw_polyline(curve(r.online), online);
    fig.add_legend(r.outputs[j] + " online (filtering)", online, LegendMark::Line);
    if (!r.batch.empty()) {
      fig.draw_polyline(curve(r.batch), batch);
      fig.add_legend(r.outputs[j] + " batch (smoothing), thin", batch, LegendMark::Line);
    }
  }
  return fig.svg();
}

std::string replay_json(const Problem& p, const ReplayResult& r) {
  nlohmann::ordered_json j;
  j["problem"] = p.file;
  j["status"] = status_name(r.summary.status);
  if (!r.summary.reason.empty()) j["reason"] = r.summary.reason;
  j["rows"] = r.rows;
  j["updates"] = r.t.size();
  j["seconds"] = r.seconds;
  const double span = r.t.empty() ? 0 : r.t.back() - p.time.t0;
  j["real_time_factor"] = r.seconds > 0 ? span / r.seconds : 0;
  j["latency_us"] = {{"median", 1e6 * r.latency_quantile(0.5)},
                     {"p90", 1e6 * r.latency_quantile(0.9)},
                     {"p99", 1e6 * r.latency_quantile(0.99)},
                     {"max", 1e6 * r.latency_quantile(1.0)}};
  j["refused"] = r.refused;
  if (p.output.truth)
    j["truth"] = {{"samples", r.truth_samples}, {"inside", r.truth_inside}, {"unbounded", r.truth_unbounded},
                  {"misses", r.truth_misses}};
  if (r.batch_solve) {
    j["batch"] = {{"status", status_name(r.batch_solve->summary.status)},
                  {"online_holds_batch", r.online_holds_batch()},
                  {"times", r.batch.size()},
                  {"mean_side_ratio", r.mean_side_ratio(0)}};
  }
  return j.dump(2) + "\n";
}

}  // namespace sillage

#pragma once
// replay_problem: a problem's own tables fed in stamp order through its
// OnlineProblem (what `sillage replay` runs, docs/online.md), the online
// estimate kept after every advance of time and set against the batch
// solve of the same file (which knows the future) and the truth.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sillage/budget.h"
#include "sillage/problem/online_problem.h"
#include "sillage/problem/solve_problem.h"

namespace sillage {

// How replay_problem feeds the rows.
struct ReplayOptions {
  // N × real time: the rows are fed when the wall clock reaches their time
  // over N; 0: as fast as possible.
  double speed = 0;
  // The estimator's window and forgetting (default: the file's [online]).
  std::optional<OnlineOptions> online;
  // Called after each update of the estimate (OnlineProblem::on_update), e.g. to write it.
  std::function<void(const OnlineProblem&)> on_update;
  // Solve the file in batch too, for the comparison (false: online only).
  bool batch = true;
  // The batch solve's budget (SolveOptions::budget); its cancel token is
  // also checked before each row and during the waits of a given speed:
  // cancelled, Cancelled out of replay_problem (Python: Ctrl-C).
  Budget budget;
};

// What a replay measured and kept.
struct ReplayResult {
  // The variables kept ([online] outputs).
  std::vector<std::string> outputs;
  // The time of each update (an advance of time, or observations at the same time).
  std::vector<double> t;
  // Per update, per output: the online box at that time (filtering).
  std::vector<std::vector<IntervalVector>> online;
  // Per update, per output: the batch box at the same time (smoothing; empty without the batch).
  std::vector<std::vector<IntervalVector>> batch;
  // Seconds per row fed (the estimator's work: the time on_update and the
  // replay's own bookkeeping took is left out).
  std::vector<double> latency;
  // Rows fed.
  std::size_t rows = 0;
  // The rows refused and why (the replay goes on).
  std::vector<std::string> refused;
  // The last update's: NoSolution with its reason when the data proved inconsistent.
  Summary summary;
  // [output.truth] samples checked against the online tubes as time passed.
  std::size_t truth_samples = 0;
  // Samples inside a bounded online box.
  std::size_t truth_inside = 0;
  // Samples in a box still unbounded (a state unknown until a measurement bounds it: no proof, no failure).
  std::size_t truth_unbounded = 0;
  // The first samples outside (up to 10).
  std::vector<std::string> truth_misses;
  // The batch solve of the same file (with ReplayOptions::batch).
  std::optional<SolveResult> batch_solve;
  // Wall clock of the replay (without the batch solve).
  double seconds = 0;
  // The q-th quantile of the latencies (0 <= q <= 1), seconds.
  double latency_quantile(double q) const;
  // Times at which the online box of every output holds the batch box, up to
  // rounding (1e-9 relative: the two propagations round differently).
  std::size_t online_holds_batch() const;
  // The mean over the times after the first `after` seconds of the online /
  // batch box side (the largest width over the outputs' components), where both are finite.
  double mean_side_ratio(double after) const;
};

// Feeds the problem's recorded rows (OnlineProblem::recorded_rows) through
// its OnlineProblem, keeps the estimate after every update, checks the
// truth as time passes and solves the file in batch for the comparison. A
// refused row is kept in `refused` and the replay goes on; an inconsistency
// stops it (summary NoSolution); a cancellation of o.budget.cancel raises
// Cancelled (Python: the GIL released, Ctrl-C stops it between two rows).
ReplayResult replay_problem(const Problem& p, const ReplayOptions& o = {});

// The figure of a replay: per output, the side of the online box over time
// against the batch one (log scale), as SVG.
std::string replay_svg(const Problem& p, const ReplayResult& r);

// The replay's report as JSON: rows, updates, latency quantiles, real-time
// factor, truth, online against batch, the rows refused.
std::string replay_json(const Problem& p, const ReplayResult& r);

// The replay's report as one offline HTML page: what was fed, the latency
// percentiles, the truth, the online estimate against the batch and the
// figure (replay_svg), the rows refused.
std::string replay_html(const Problem& p, const ReplayResult& r);

}  // namespace sillage

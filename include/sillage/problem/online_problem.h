#pragma once
// OnlineProblem: a problem file run online (docs/online.md, "From a problem
// file"): its tube variables and constraints declared on an OnlineEstimator,
// its tables' rows fed one by one as a robot receives them. What `sillage
// stream` (rows from stdin) and `sillage replay` (the file's own tables)
// run.
//
// How the rows drive it:
//  - the clock: a row of the table that gives tubes their slices (`slices =
//    {data = ...}`) is the period that ends at its time t: time advances to t
//    with that period's inputs. Without such a table, a row of the [time]
//    points table advances time to its point; with a slice width δ, time
//    advances on the grid t0 + kδ up to the first point at or after a row's
//    arrival time (or a tick: a row of no table).
//  - an observation: a row of a table an eval constraint reads is, per eval
//    constraint that keeps it, an observation of its tubes at the row's time
//    (stamp ± time_error, or [lb, ub] ± time_error; without a time column,
//    a time in [window start, arrival]: causal only in that sense). One
//    whose time begins after now is held until time reaches it (refused
//    beyond now + lead), one that reaches past now is held by the estimator.
//  - a value stated with `at` is the state's value at t0, or an observation
//    held until its time.
// Not online (an Error at construction naming the file's place): interval
// and box variables (a constant of the whole run), gates from a table,
// p_implies_z (the temporal SLAM's loops), an observation that reads a
// variable other than its evaluated tubes.
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sillage/online/online_estimator.h"
#include "sillage/problem/problem.h"

namespace sillage {

namespace detail {
struct OnlineProblemImpl;
}  // namespace detail

// One row as it arrives (a line of `sillage stream`): its table (empty: a
// tick, time advancing without data), when it arrived (none: now; the end
// of its period for a row of the clock table), and its columns by name.
struct StreamRow {
  std::string table;              // its table ("": a tick)
  std::optional<double> t;        // when it arrived (none: now); a clock row: the end of its period
  std::map<std::string, double> columns;  // every column of the table, by name
};

class OnlineProblem {
 public:
  // options: the window and forgetting (default: the file's [online], the
  // ratio of [network]). p is copied (its tables are read with each row).
  explicit OnlineProblem(const Problem& p, std::optional<OnlineOptions> options = std::nullopt);
  ~OnlineProblem();
  OnlineProblem(const OnlineProblem&) = delete;
  OnlineProblem& operator=(const OnlineProblem&) = delete;

  // A row arrives. Error, with nothing changed, for a table no constraint
  // reads online, a missing or unknown column, a NaN, a clock row without
  // t or not after now, an observation older than the window or stamped
  // beyond now + lead. A row may advance time several times (on_update).
  void feed(const StreamRow& row);
  // Called after each update of the estimate (one to write): each advance
  // of time, and at the end of a row whose observations changed it since.
  void on_update(std::function<void()> f);

  // The rows of the problem's own tables in the order a robot receives them
  // (what `sillage replay` feeds): clock rows at their time; an observation
  // once time has reached its stamp (the later of its time columns), after
  // the clock row of that time; with δ, a tick per slice; rows without a
  // time column last.
  std::vector<StreamRow> recorded_rows() const;

  // The tube variables written per update ([online] outputs, or all of them).
  const std::vector<std::string>& outputs() const;
  // Observations held until time reaches their start (the estimator holds
  // those that began).
  std::size_t waiting() const;
  // The estimator the rows feed (its tubes, now(), stats()).
  OnlineEstimator& estimator();
  const OnlineEstimator& estimator() const;

 private:
  std::unique_ptr<detail::OnlineProblemImpl> impl_;
};

// The estimator's options from the file: [online] window and forget_every,
// [network] ratio.
OnlineOptions online_options(const Problem& p);

}  // namespace sillage

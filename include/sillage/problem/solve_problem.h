#pragma once
// Solves a Problem: builds its network (build_network.h) and contracts it to
// the fixed point, for the δ of the file, a given δ, or δ chosen
// automatically: start coarse ((tf - t0)/64 slices), refine while the result
// still changes by more than `tolerance` (relative change of the mean
// thickness of the bounded tubes) and the time budget allows the next step
// (estimated from the last one, in proportion to the slices). Refining
// either halves every slice, or splits only the slices of the time regions
// where the tubes are thick (docs/benchmarks.md, "Automatic δ", compares both).
// Every step is a guaranteed enclosure; the finest one is the result, and the
// schedule (δ, slices, thickness, time) is kept.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sillage/budget.h"
#include "sillage/outcome.h"
#include "sillage/problem/build_network.h"

namespace sillage {

// How the automatic δ refines the slices from one step to the next.
enum class DeltaRefinement {
  Halving,  // every slice split in two (a uniform δ halved)
  Regions,  // only the slices whose thickness over their gates is above a quantile
};

struct SolveOptions {
  std::optional<double> delta;  // a given δ; none: the file's, or auto if the file says "auto"
  bool auto_delta = false;      // force the automatic δ
  double tolerance = 0.01;      // relative change that stops the refinement
  double budget_seconds = 60;   // of the automatic δ
  std::size_t max_slices = 1u << 20;
  DeltaRefinement refinement = DeltaRefinement::Halving;  // the faster to a thinner result (docs/cli.md)
  // The order within a round of the propagation; none: the file's ([network] scheduling, default Fifo).
  std::optional<Scheduling> scheduling;
  // The budget of each contraction (ContractorNetwork::set_budget: 10^7 contractor runs by
  // default; max_seconds; a cancel token, which Python sets on Ctrl-C). Exceeded: the result so
  // far, SolveResult::stopped saying why; cancelled: Cancelled out of solve_problem.
  Budget budget;
  // Regions: a slice is split when its excess thickness over its gates (summed
  // over the bounded tube components) is above this quantile of all the
  // slices' (0.5: the thicker half).
  double split_quantile = 0.5;
  // No solution: also keep the domains just before the contractor that emptied one of them ran
  // (SolveResult::before_empty), at the cost of the failing step contracted again.
  bool keep_before_empty = true;
  // Called after each step (progress line).
  std::function<void(const struct ScheduleStep&)> on_step;
};

struct ScheduleStep {
  double delta = 0;  // the slice width (regions: the narrowest slice)
  std::size_t slices = 0;
  double mean_thickness = 0;  // over the bounded tube components
  double build_seconds = 0, contract_seconds = 0;
  ContractStats stats;
};

// A solved problem: the domains, whether they are empty (no solution) and why, the schedule.
struct SolveResult {
  BuiltProblem built;  // the last step's domains
  std::vector<ScheduleStep> schedule;
  // True if the problem has no solution (an empty domain).
  bool empty = false;
  std::string why_empty;  // ContractStats::emptiness + the constraint and its place in the file
  // No solution: the domains just before the contractor that emptied one ran (the failing step
  // contracted again, cut one contractor run short: the propagation is deterministic). Every value
  // they exclude is in no solution; they show where the constraints met before the contradiction.
  // None when solved, when empty on input, or with SolveOptions::keep_before_empty false.
  std::optional<BuiltProblem> before_empty;
  // Why the contraction stopped before its fixed point ("": it did not): a budget of
  // SolveOptions::budget spent (BudgetExceeded's message). The domains are still enclosures of
  // every solution, only not as tight as the fixed point's; no further δ is tried.
  std::string stopped;
  // What the file may state without meaning to (problem_warnings): printed by sillage solve,
  // in results.json and the report.
  std::vector<std::string> warnings;
  Scheduling scheduling = Scheduling::Fifo;  // the order the propagation ran
  // How the solve ended (outcome.h), as the network reports it: Converged, NoSolution (reason:
  // why_empty) or Stopped (reason: stopped); rounds and work are the propagation rounds and
  // contractor calls of every step, seconds the whole solve. A cancellation raises Cancelled.
  Summary summary;
  // Time spent building the networks (all steps).
  double build_seconds() const;
  // Time spent contracting (all steps).
  double contract_seconds() const;
};

// Builds the network of the problem and contracts it to the fixed point (GIL released); delta: a
// slice width (default: the file's), auto_delta: refine δ from coarse until the result changes by
// less than tolerance or the budget is spent; scheduling: the order within a round (default: the file's
// [network] scheduling). In Python also delta="auto", refine="halving" | "regions",
// scheduling="fifo" | "priority" (the names of the `sillage solve` options) and keep_before_empty. The options are
// checked by check_solve_options.
SolveResult solve_problem(const Problem& p, const SolveOptions& options = {});

// Error if delta is not in (0, tf - t0] or gives more than kMaxSlices slices (the file's rule for
// its own delta), the message led by `name` (the option that gave it: "--delta", "delta").
// A problem whose time points are a table's stamps takes no delta: an Error
// naming the table and the file's [time] too.
void check_delta(const Problem& p, double delta, const std::string& name);

// The options of a solve against the problem, named with `prefix` ("--" on
// the command line, "" in Python): check_delta for o.delta, no automatic δ on
// a table's time points, refinement by regions only with an automatic δ.
// Error saying what and why; solve_problem calls it with "".
void check_solve_options(const Problem& p, const SolveOptions& o, const std::string& prefix);

// The mean thickness (volume / duration) summed over the tube components with
// a finite volume.
double mean_thickness(const BuiltProblem& b);

}  // namespace sillage

#pragma once
// One outcome for every long computation (after Ceres' Solver::Summary): how
// it ended, why, and what it did. The computations that keep their result so
// far return it with a Summary (sivia_run, kernel_sivia_run, ...): their
// result is then still an enclosure, only not as tight as a full run's.
// Their throwing forms (sivia, ...) raise BudgetExceeded for Stopped and
// Cancelled for Cancelled instead (budget.h).
//
// Progress: Budget::progress (budget.h) is called every
// Budget::progress_every units of work (boxes, contractor calls) with the
// counters so far, for tracing and progress bars (GTSAM's iterationHook).
#include <cstddef>
#include <functional>
#include <string>

namespace sillage {

// How a long computation ended.
enum class Status {
  Converged,   // ran to its end: the result is the full one
  Stopped,     // a budget was spent: the result so far (still an enclosure), Summary::reason says which
  Cancelled,   // its CancelToken was set: the result so far (still an enclosure)
  NoSolution,  // ran to its end and proved the solution set empty; Summary::reason says how
};

// The name of a status: "converged", "stopped", "cancelled", "no solution".
const char* status_name(Status s);

// What a long computation did: its status, why it ended that way, and its counters.
struct Summary {
  // How the run ended.
  Status status = Status::Converged;
  // Stopped: the budget spent, the value reached and the option that raises it
  // (BudgetExceeded's message); Cancelled: where ("sivia: cancelled");
  // NoSolution: the provenance of the emptiness; Converged: "".
  std::string reason;
  // Rounds of the run: the calls of the progress hook (Budget::progress), and
  // for a run stopped within a round (a network's contract_run()) that round too.
  std::size_t rounds = 0;
  // Units of work counted against the budget (boxes, paving nodes, contractor calls).
  std::size_t work = 0;
  // Wall-clock time of the run.
  double seconds = 0;
  // True if the computation ran to its end (Converged or NoSolution).
  bool finished() const { return status == Status::Converged || status == Status::NoSolution; }
  // One line: the status, the counters and the reason.
  std::string str() const;
};

// What the progress hook receives: the counters of the run so far.
struct Progress {
  // The computation ("sivia", "kernel_sivia", ...).
  const char* where = "";
  // 1 at the first call of the run, then 2, 3, ...
  std::size_t round = 0;
  // Units of work so far (boxes, paving nodes, contractor calls); never decreases.
  std::size_t work = 0;
  // Wall-clock time since the start of the run.
  double seconds = 0;
};

// Called every Budget::progress_every units of work, one call at a time (from
// any thread of the run). An exception it throws ends the computation.
using ProgressHook = std::function<void(const Progress&)>;

}  // namespace sillage

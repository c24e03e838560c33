#pragma once
// Budgets and cancellation of the long algorithms (SIVIA and its variants,
// the t-plane detections and proofs, the degree and count refinements, the
// contractor network, where max_boxes counts contractor calls). CtcIvp and
// CtcPImpliesZ, whose work is bounded by their tubes, take a CancelToken
// alone; a network passes its own to them.
// Their cost grows without bound as eps shrinks or the dimension grows, so
// each one checks a Budget as it goes:
//  - max_boxes: boxes stored or refined (for a paving: its nodes), 10^7 by
//    default;
//  - max_bytes: the memory of a paving's nodes (16 n + 8 bytes each in
//    dimension n), 1 GiB by default: 10^7 boxes in 2-D, 6.4 million in 10-D;
//  - max_seconds: wall-clock time, none by default (0);
//  - cancel: a CancelToken that another thread may set (Python sets it on
//    Ctrl-C); checked at every box, across the oneTBB tasks too.
// Exceeding a budget throws BudgetExceeded; a cancelled token throws Cancelled.
// The computations that return a Summary (outcome.h: sivia_run, ...) keep
// their result so far instead, with Status::Stopped or Status::Cancelled.
// Budget::progress, if set, is called every progress_every units of work.
#include <atomic>
#include <chrono>
#include <cstddef>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include "sillage/error.h"
#include "sillage/outcome.h"

namespace sillage {

// A flag shared by copies: cancel() on one copy is seen by all of them.
class CancelToken {
 public:
  // A token not cancelled.
  CancelToken() : flag_(std::make_shared<std::atomic<bool>>(false)) {}
  // Ask the computations holding this token to stop (any thread).
  void cancel() const { flag_->store(true, std::memory_order_relaxed); }
  // True once cancel() was called on this token or a copy of it (until reset()).
  bool cancelled() const { return flag_->load(std::memory_order_relaxed); }
  // Clears the flag, so that the token can be used again.
  void reset() const { flag_->store(false, std::memory_order_relaxed); }

 private:
  std::shared_ptr<std::atomic<bool>> flag_;
};

struct Budget {
  // Boxes stored or refined (for a paving: its nodes); 10^7 by default, 0: no limit.
  std::size_t max_boxes = 10'000'000;
  // Memory of a paving's nodes (16 n + 8 bytes each in dimension n); 1 GiB by default, 0: no limit.
  std::size_t max_bytes = 1u << 30;
  // Wall-clock time in seconds; 0 (the default): no limit.
  double max_seconds = 0;
  CancelToken cancel;
  // Called every progress_every units of work with the counters so far (outcome.h); a
  // ContractorNetwork calls it once per round instead. None by default.
  ProgressHook progress;
  // Units of work (boxes, contractor calls) between two calls of progress; 0: never called.
  std::size_t progress_every = 65536;
};

// A budget exceeded: the message names the algorithm, the budget, the value
// reached and the option that raises it.
class BudgetExceeded : public Error {
 public:
  using Error::Error;
};

// The computation was cancelled through its CancelToken. Not an Error: the
// input was fine.
class Cancelled : public std::runtime_error {
 public:
  explicit Cancelled(const std::string& where) : std::runtime_error(where + ": cancelled") {}
};

// Throws what the throwing form of a computation throws for a Summary that
// did not finish: BudgetExceeded(reason) for Stopped, Cancelled for Cancelled
// (same message); does nothing otherwise.
void throw_unfinished(const Summary& summary);

// Throws Cancelled(where) once `token` is cancelled: for the loops that
// check a token alone, without a BudgetMeter (CtcIvp, CtcOmega).
inline void check_cancel(const CancelToken& token, const char* where) {
  if (token.cancelled()) throw Cancelled(where);
}

// Counts the boxes of one run against a Budget; thread-safe (one meter is
// shared by the oneTBB tasks of the run). `option` names the setting that
// holds the budget in error messages (e.g. "options.budget"), `hint` another
// way out (" or use a larger eps"); with bytes_per_box > 0, max_bytes holds
// too (the boxes of a paving).
class BudgetMeter {
 public:
  BudgetMeter(const Budget& budget, const char* where, const char* option = "options.budget",
              const char* hint = "", std::size_t bytes_per_box = 0, const char* unit = "boxes");
  // Counts one more box; throws BudgetExceeded or Cancelled.
  void add();
  // Counts one more box; false once the budget is spent or the token
  // cancelled (then for good: status() and reason() say why), for the
  // computations that keep their result so far. Calls Budget::progress.
  bool try_add();
  // True once try_add or add found the budget spent or the token cancelled.
  bool stopped() const { return stopped_.load(std::memory_order_acquire); }
  // The counters and, once stopped, the status and reason of the run so far
  // (status Converged while it runs on).
  Summary summary() const;
  std::size_t boxes() const { return boxes_.load(std::memory_order_relaxed); }
  // The budget's token, for the work between two boxes that checks it alone.
  const CancelToken& cancel() const { return budget_.cancel; }

 private:
  Budget budget_;
  const char* where_;
  const char* option_;
  const char* hint_;
  std::size_t bytes_per_box_;
  const char* unit_;  // what is counted, in messages ("boxes", "contractor calls")
  std::size_t max_boxes_in_memory_;  // max_bytes / bytes_per_box; 0: no limit
  std::chrono::steady_clock::time_point start_;
  std::atomic<std::size_t> boxes_{0};
  std::atomic<bool> stopped_{false};
  mutable std::mutex mutex_;  // guards status_, reason_, rounds_ and the progress calls
  Status status_ = Status::Converged;
  std::string reason_;
  std::size_t rounds_ = 0;

  double seconds() const;
  // Records the first reason to stop; returns false.
  bool stop(Status status, std::string reason);
  void report_progress();
};

// Throws Error for a negative or NaN max_seconds.
void check_budget(const Budget& budget, const char* where);

}  // namespace sillage

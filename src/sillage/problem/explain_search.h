#pragma once
// The state of one explain_empty search (internal): the problem, the
// options, the answer being built, the clock, and the trial: a contraction
// of the problem with some items relaxed at the failing solve's δ.
#include <atomic>
#include <chrono>
#include <mutex>
#include <vector>

#include "sillage/problem/explain_empty.h"

namespace sillage::detail {

class ExplainSearch {
 public:
  // From the problem's own solve: the answer is empty (nothing to explain) unless failed is.
  ExplainSearch(const Problem& p, const ExplainOptions& o, const SolveResult& failed);

  // Contracts p with the items `relaxed` (indices into e.items) relaxed, records the trial, and
  // when its contraction is not empty and found is given, fills it (the items, their proven
  // values). Not run (Stopped) once the search's time is spent. Thread-safe.
  TrialOutcome trial(const std::vector<std::size_t>& relaxed, Relaxation* found);
  // The same on q, a problem derived from p with items[relaxed] relaxed or changed; `probe`
  // names a probe (ExplainTrial::probe).
  TrialOutcome run(const Problem& q, const std::vector<std::size_t>& relaxed, Relaxation* found,
                   const std::string& probe = "");
  // True once the search's time is spent.
  bool out_of_time() const;
  // Sets complete, stopped and seconds.
  void finish();

  const Problem& p;
  const ExplainOptions& o;
  Explanation e;

 private:
  std::chrono::steady_clock::time_point start_;
  SolveOptions trial_options_;  // the δ of the failing step, fixed
  std::mutex mutex_;            // guards e.trials
  std::atomic<std::size_t> not_run_{0};
  double seconds_left() const;
};

// A single relaxed gate whose value the relaxed contraction leaves unbounded: searched over a
// window (ProvenValue::window), 16 cells contracted in parallel, halved while not proven empty
// down to the stated value's width; its values there: the hull of theirs.
void probe_gate(ExplainSearch& s, Relaxation& r);

// What the contraction b of q (p with items[relaxed] relaxed) proves of those bounds and gates.
std::vector<ProvenValue> proven_values(const Problem& p, const Problem& q, const std::vector<ExplainItem>& items,
                                       const std::vector<std::size_t>& relaxed, const BuiltProblem& b);

}  // namespace sillage::detail

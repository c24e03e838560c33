#pragma once
// RunResult<T>: the outcome (outcome.h) of a long computation whose result
// so far is no answer: a degree or a count of zeros computed over part of a
// boundary or of a region says nothing of the whole. So the value is there
// when the run finished (Converged), and absent when the budget was spent
// (Stopped) or the run cancelled (Cancelled): no partial value is returned.
// (The computations whose result so far is still an enclosure keep it
// instead: SiviaResult, TPlane::compute_detections_run.)
#include <optional>
#include <string>
#include <utility>

#include "sillage/budget.h"
#include "sillage/outcome.h"

namespace sillage {

template <class T>
struct RunResult {
  // The result of a finished run; nullopt for Stopped and Cancelled.
  std::optional<T> value;
  // Converged, Stopped (the budget in reason) or Cancelled.
  Summary summary;
  // The value of a finished run; throws BudgetExceeded (Stopped) or
  // Cancelled (Cancelled), as the throwing form does.
  T take() && {
    throw_unfinished(summary);
    return std::move(*value);
  }
};

namespace detail {
// Runs compute() (which counts against `meter` and throws BudgetExceeded or
// Cancelled on the way) and turns those two exceptions into the Summary.
template <class T, class Compute>
RunResult<T> run_metered(BudgetMeter& meter, Compute&& compute) {
  RunResult<T> r;
  Status stop = Status::Converged;
  std::string reason;
  try {
    r.value = compute();
  } catch (const BudgetExceeded& e) {
    stop = Status::Stopped;
    reason = e.what();
  } catch (const Cancelled& e) {  // from the meter, or from a check of its token alone
    stop = Status::Cancelled;
    reason = e.what();
  }
  r.summary = meter.summary();
  if (stop != Status::Converged && r.summary.finished()) {  // thrown past the meter: say so
    r.summary.status = stop;
    r.summary.reason = reason;
  }
  return r;
}
}  // namespace detail

}  // namespace sillage

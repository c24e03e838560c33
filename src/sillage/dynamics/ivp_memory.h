#pragma once
// IvpMemory: what CtcIvp's network node remembers between runs
// (ctc_ivp_node.cpp), so that a run re-integrates only from the first gate
// or slice of x or u that changed since the last run (forward) and down from
// the last one (backward), instead of the whole tube.
//
// Sound whatever happened in between: the set a sweep carried into gate j
// encloses every solution consistent with the tubes that sweep saw before
// gate j; it is reused only when the tubes before gate j (in the sweep's
// direction) are exactly those left by the last run, which are subsets of
// what that sweep saw. A tube widened or reset by the user, a refined
// TDomain or other sizes: the sweep starts from the beginning.
#include <cstddef>
#include <optional>
#include <vector>

#include "sillage/dynamics/ivp_step.h"
#include "sillage/tube/tube_vector.h"

namespace sillage::detail {

struct IvpMemory {
  // The gates and slices of x then u after the last run (empty: no run yet).
  std::vector<std::vector<Interval>> gates, slices;
  std::vector<double> times;  // the TDomain's gate times
  // Per sweep (0: forward, 1: backward), indexed by the step j of the sweep
  // (gate j forward, gate N - j backward): the set arriving at that gate,
  // none where the integration was not running.
  std::vector<std::optional<LohnerSet>> arriving[2];

  void forget();
  // Records x and u as they are after a run.
  void remember(const TubeVector& x, const TubeVector* u);
  // The first step j of the sweep (sign > 0 forward) whose gate, or slice
  // after it, differs from the remembered tubes (N + 1 if none); 0 when
  // nothing usable is remembered.
  std::size_t first_change(const TubeVector& x, const TubeVector* u, double sign) const;
};

}  // namespace sillage::detail

#pragma once
// TubeObservation: one fix x(t) ∈ z at an uncertain time t on a tube x, the
// measurement list of CtcEvalList (all true) and CtcQEval (at most q wrong).
#include <cstddef>
#include <string>
#include <vector>

#include "sillage/ctc/ctc_algebra.h"
#include "sillage/interval/interval_vector.h"

namespace sillage {

// One fix: x(t) ∈ z for some t ∈ [t], and z satisfies the constraint of
// `ctc` (null: none). A range r to a beacon b is z = IntervalVector(n) with
// ctc = CtcFunction(|z - b|, [r]); a position fix is a bounded z alone.
struct TubeObservation {
  // The time interval of the fix.
  Interval t;
  // The box of the fix (contracted by ctc).
  IntervalVector z;
  CtcPtr ctc = nullptr;  // on z.size() variables
  // What the fix is, for the reports (e.g. "ranges line 12"); "" if unnamed.
  std::string name = "";
};

namespace detail {

// Error unless obs is a non-empty list of fixes of n components (z and ctc)
// whose times meet `domain`; `where` leads the message.
void check_observation_list(std::size_t n, const Interval& domain, const std::vector<TubeObservation>& obs,
                            const std::string& where);

}  // namespace detail

}  // namespace sillage

#include "sillage/dynamics/gomne_tube.h"

#include <algorithm>
#include <string>

namespace sillage {

TubeGomneResult gomne_tube(const TubeVector& x, const TubeVector& v, const std::vector<TubeObservation>& obs,
                           const TubeGomneOptions& options) {
  if (obs.empty()) throw Error("gomne_tube: needs at least one observation");
  if (options.q_max < 0) throw Error("gomne_tube: q_max must be >= 0, got " + std::to_string(options.q_max));
  if (options.max_passes < 1) {
    throw Error("gomne_tube: max_passes must be >= 1, got " + std::to_string(options.max_passes));
  }
  const int q_max = std::min<long long>(options.q_max, static_cast<long long>(obs.size()));
  TubeGomneResult r{0, x, {}};
  for (r.q = 0; r.q <= q_max; ++r.q) {
    const CtcQEval ctc(r.q);
    r.x = x;
    for (int pass = 0; pass < options.max_passes && !r.x.is_empty(); ++pass) {
      const TubeVector before = r.x;
      // Violated on `before`, a superset of the final tube: violated on it too.
      r.outliers = ctc.contract(r.x, v, obs);
      if (r.x == before) break;
    }
    if (!r.x.is_empty()) return r;
  }
  r.outliers.clear();
  return r;
}

}  // namespace sillage

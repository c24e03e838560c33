#pragma once
// CtcBiasedIncrement: increments measured by a sensor with an unknown constant
// bias b0 (a gyro's turn-on bias) plus a small in-run variation d(t):
//   x(t_j) − x(t_i) ∈ Σ_{i<=k<j} [i](k) − b0 (t_j − t_i) + [−d_max, d_max] (t_j − t_i)
// for every pair of gates i < j, with [i](k) (the slice k of a tube i) the
// measured increment over slice k and b0 ONE interval shared by the whole run.
// Both ways, in O(N log N), not over the N² pairs:
//   b0:  for a pair i < j the constraint gives b0 (t_j − t_i) ∈ S_ij − ([x](t_j) − [x](t_i));
//        the tightest pair for each j is the tangent from j to the convex hull
//        of the earlier gates (lifted by the prefix sums of the increments),
//        and every bound is computed on that pair with outward-rounded
//        Interval operations (any pair is sound; the hull only picks the best);
//   x:   a forward then a backward sweep over the gates with the increments
//        [i](k) − [b0] δ_k + [−d_max, d_max] δ_k (CtcIncrement's rule);
// repeated while [b0] shrinks. What one span learns of b0 (two gates known
// hundreds of seconds apart) narrows x everywhere else.
// The slices of x are left to CtcDeriv, as with CtcIncrement.
// With a fourth tube j (cn.add(ctc, {x, b0, i, j})), the slices of j are narrowed
// to the increments of x the model allows, [i](k) − [b0] δ_k + [−d_max, d_max] δ_k,
// for the contractors that read the true increments (CtcIncrement, CtcHeadingWindow):
// they tighten as b0 is learnt.
//
// Empty: an empty input, or no b0 left: x and b0 are set empty, contract
// returns false.
// In a ContractorNetwork: cn.add(ctc, {x, b0, i}) with x and i tubes on one
// TDomain and b0 an Interval; or {x, b0, i, j}.
#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/tube_contractor.h"
#include "sillage/interval/interval.h"
#include "sillage/tube/tube.h"

namespace sillage {

// Increments measured with one unknown constant bias b0 (an interval shared by the
// whole run) and an in-run drift |d(t)| <= d_max: x(t_j) - x(t_i) in the sum of the
// increments [i](k) over i..j - b0 (t_j - t_i) + [-d_max, d_max] (t_j - t_i) for every
// pair of gates, contracted both ways (b0 from the spans, the gates from b0) in
// O(N log N). ContractorNetwork.add(CtcBiasedIncrement(d_max), [x, b0, i]).
class CtcBiasedIncrement
    : public TubeContractor<CtcBiasedIncrement, bool(Tube&, Interval&, const Tube&),
                            bool(Tube&, Interval&, const Tube&, Tube&)> {
 public:
  // The bias contractor; drift = d_max >= 0 (units of x per unit of time), finite; Error otherwise.
  explicit CtcBiasedIncrement(double drift = 0.0);
  // The bound d_max on the in-run variation of the bias.
  double drift() const { return drift_; }
  std::string name() const override { return "CtcBiasedIncrement"; }

  // Contracts the gates of x and the bias b0; i is read only.
  // DimensionError if x and i are not on one TDomain.
  bool contract(Tube& x, Interval& b0, const Tube& i) const;
  // The same, and the slices of j (the true increments) narrowed to [i](k) − [b0] δ_k + [−d_max, d_max] δ_k;
  // j is set empty too when there is no solution.
  bool contract(Tube& x, Interval& b0, const Tube& i, Tube& j) const;

 private:
  double drift_;
};

}  // namespace sillage

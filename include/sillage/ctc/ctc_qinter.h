#pragma once
// CtcQInter: the q-relaxed intersection of m contractors on the same
// variables, for data with outliers ("at most q of the m constraints are
// wrong"). contract(x) keeps every point of [x] that satisfies at least m - q
// of the m constraints:
//     C([x]) = [x] ∩ q_inter(C_1([x]), ..., C_m([x]), q)   (see q_inter.h)
// A point satisfying constraint i is in C_i([x]) (consistency of C_i), so a
// point satisfying m - q of them is in m - q of the boxes and in their
// component-wise q-relaxed intersection: no such point is lost.
// q = 0 gives the same box as CtcInter; q >= m leaves [x] unchanged.
// Not idempotent in general: wrap it in CtcFixPoint to iterate.
#include <vector>

#include "sillage/ctc/ctc_algebra.h"
#include "sillage/ctc/q_inter.h"

namespace sillage {

class CtcQInter : public CtcCombination {
 public:
  // A non-empty list of non-null contractors on the same number of variables
  // and q >= 0 (else Error / DimensionError).
  CtcQInter(std::vector<CtcPtr> list, int q);
  void contract(IntervalVector& x) const override;
  std::string name() const override { return "CtcQInter"; }
  // The number of constraints allowed to be wrong.
  int q() const { return q_; }

 private:
  int q_;
};

}  // namespace sillage

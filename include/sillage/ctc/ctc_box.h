#pragma once
// CtcBox: x ∩= B, the contractor of the constraint x ∈ [B].
#include "sillage/ctc/ctc.h"

namespace sillage {

class CtcBox : public Ctc {
 public:
  // The contractor of x in box.
  explicit CtcBox(const IntervalVector& box) : Ctc(box.size()), box_(box) {}
  void contract(IntervalVector& x) const override;
  std::string name() const override { return "CtcBox"; }
  // The box B.
  const IntervalVector& box() const { return box_; }

 private:
  IntervalVector box_;
};

}  // namespace sillage

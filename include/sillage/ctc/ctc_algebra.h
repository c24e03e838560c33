#pragma once
// Contractor programming (thesis 2.34): contractors combined as sets.
//   CtcInter  (C1 ∩ ... ∩ Cn)(x) = C1(x) ∩ ... ∩ Cn(x)
//   CtcUnion  (C1 ∪ ... ∪ Cn)(x) = hull(C1(x), ..., Cn(x))
//   CtcCompo  applies C1 first, then C2, ..., Cn: the result is Cn ∘ ... ∘ C1(x)
//   CtcFixPoint  C∞: C applied again while one component shrinks by more than
//                ratio (see shrink.h)
// Operands are held by shared ownership, so an expression of contractors can
// outlive the variables that built it. All operands act on the same n variables.
// c1 & c2 builds a CtcInter, c1 | c2 a CtcUnion.
#include <memory>
#include <vector>

#include "sillage/ctc/ctc.h"

namespace sillage {

using CtcPtr = std::shared_ptr<const Ctc>;

// Base of the n-ary combinations: checks the operand list (non-empty, no null,
// equal nb_vars; else Error / DimensionError naming `kind`).
class CtcCombination : public Ctc {
 public:
  CtcCombination(std::vector<CtcPtr> list, const char* kind);
  const std::vector<CtcPtr>& list() const { return list_; }

 protected:
  std::vector<CtcPtr> list_;
};

// (C1 & ... & Cn)(x) = C1(x) & ... & Cn(x) (contractor programming, thesis 2.34); c1 & c2 builds
// one.
class CtcInter : public CtcCombination {
 public:
  explicit CtcInter(std::vector<CtcPtr> list) : CtcCombination(std::move(list), "CtcInter") {}
  void contract(IntervalVector& x) const override;
  std::string name() const override { return "CtcInter"; }
};

// (C1 | ... | Cn)(x) = hull(C1(x), ..., Cn(x)) (thesis 2.34); c1 | c2 builds one.
class CtcUnion : public CtcCombination {
 public:
  explicit CtcUnion(std::vector<CtcPtr> list) : CtcCombination(std::move(list), "CtcUnion") {}
  void contract(IntervalVector& x) const override;
  std::string name() const override { return "CtcUnion"; }
};

class CtcCompo : public CtcCombination {
 public:
  explicit CtcCompo(std::vector<CtcPtr> list) : CtcCombination(std::move(list), "CtcCompo") {}
  void contract(IntervalVector& x) const override;
  std::string name() const override { return "CtcCompo"; }
};

// C applied again while one component shrinks by more than ratio (the fixed point C-infinity).
class CtcFixPoint : public Ctc {
 public:
  // 0 <= ratio < 1 (else Error); ratio = 0 iterates until nothing changes at all.
  explicit CtcFixPoint(CtcPtr ctc, double ratio = 0.01);
  void contract(IntervalVector& x) const override;
  std::string name() const override { return "CtcFixPoint"; }
  // The shrink ratio that stops the iteration.
  double ratio() const { return ratio_; }

 private:
  CtcPtr ctc_;
  double ratio_;
};

std::shared_ptr<CtcInter> operator&(const CtcPtr& c1, const CtcPtr& c2);
std::shared_ptr<CtcUnion> operator|(const CtcPtr& c1, const CtcPtr& c2);

}  // namespace sillage

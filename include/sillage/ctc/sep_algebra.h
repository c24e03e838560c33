#pragma once
// Set operations on separators. With S_i separating X_i:
//   SepInter  separates X1 ∩ ... ∩ Xn: outer boxes intersected, inner boxes hulled
//   SepUnion  separates X1 ∪ ... ∪ Xn: outer boxes hulled, inner boxes intersected
//   SepNot    separates the complement of X: inner and outer swapped
// (a point removed from the hull of the inner boxes was removed by every S_i,
// so it lies in every X_i; dually for the union). s1 & s2, s1 | s2 and ~s build them.
#include <memory>
#include <vector>

#include "sillage/ctc/sep.h"

namespace sillage {

using SepPtr = std::shared_ptr<const Sep>;

class SepCombination : public Sep {
 public:
  SepCombination(std::vector<SepPtr> list, const char* kind);
  const std::vector<SepPtr>& list() const { return list_; }

 protected:
  std::vector<SepPtr> list_;
};

// Separates X1 & ... & Xn: outer boxes intersected, inner boxes hulled; s1 & s2 builds one.
class SepInter : public SepCombination {
 public:
  explicit SepInter(std::vector<SepPtr> list) : SepCombination(std::move(list), "SepInter") {}
  void separate(IntervalVector& x_in, IntervalVector& x_out) const override;
  std::string name() const override { return "SepInter"; }
};

// Separates X1 | ... | Xn: outer boxes hulled, inner boxes intersected; s1 | s2 builds one.
class SepUnion : public SepCombination {
 public:
  explicit SepUnion(std::vector<SepPtr> list) : SepCombination(std::move(list), "SepUnion") {}
  void separate(IntervalVector& x_in, IntervalVector& x_out) const override;
  std::string name() const override { return "SepUnion"; }
};

// Separates the complement of X: inner and outer swapped; ~s builds one.
class SepNot : public Sep {
 public:
  explicit SepNot(SepPtr sep);
  void separate(IntervalVector& x_in, IntervalVector& x_out) const override;
  std::string name() const override { return "SepNot"; }

 private:
  SepPtr sep_;
};

std::shared_ptr<SepInter> operator&(const SepPtr& s1, const SepPtr& s2);
std::shared_ptr<SepUnion> operator|(const SepPtr& s1, const SepPtr& s2);
std::shared_ptr<SepNot> operator~(const SepPtr& s);

}  // namespace sillage

#include "sillage/ctc/ctc_qinter.h"

namespace sillage {

CtcQInter::CtcQInter(std::vector<CtcPtr> list, int q) : CtcCombination(std::move(list), "CtcQInter"), q_(q) {
  check_q(q, "CtcQInter");
}

void CtcQInter::contract(IntervalVector& x) const {
  check_dim(x);
  if (x.is_empty()) return x.set_empty();
  if (static_cast<std::size_t>(q_) >= list_.size()) return;  // every point of [x] qualifies
  std::vector<IntervalVector> boxes(list_.size(), x);
  int violated = 0;
  for (std::size_t i = 0; i < list_.size(); ++i) {
    list_[i]->contract(boxes[i]);
    boxes[i] &= x;  // a contractor never enlarges; guard against one that would
    if (boxes[i].is_empty() && ++violated > q_) return x.set_empty();  // more than q violated everywhere
  }
  x &= q_inter(boxes, q_);
  if (x.is_empty()) x.set_empty();
}

}  // namespace sillage

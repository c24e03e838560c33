#include "sillage/ctc/ctc_algebra.h"

#include <string>

#include "sillage/ctc/shrink.h"

namespace sillage {

namespace {

std::size_t first_nb_vars(const std::vector<CtcPtr>& list, const char* kind) {
  if (list.empty()) throw Error(std::string(kind) + ": needs at least one contractor");
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (!list[i]) throw Error(std::string(kind) + ": contractor " + std::to_string(i) + " is null");
  }
  return list[0]->nb_vars();
}

CtcPtr checked(CtcPtr c, const char* kind) {
  if (!c) throw Error(std::string(kind) + ": contractor is null");
  return c;
}

}  // namespace

CtcCombination::CtcCombination(std::vector<CtcPtr> list, const char* kind)
    : Ctc(first_nb_vars(list, kind)), list_(std::move(list)) {
  for (std::size_t i = 0; i < list_.size(); ++i) {
    if (list_[i]->nb_vars() != nb_vars()) {
      throw DimensionError(std::string(kind) + ": contractor " + std::to_string(i) + " (" + list_[i]->name() +
                           ") acts on " + std::to_string(list_[i]->nb_vars()) + " variables, contractor 0 on " +
                           std::to_string(nb_vars()));
    }
  }
}

void CtcInter::contract(IntervalVector& x) const {
  check_dim(x);
  if (x.is_empty()) return x.set_empty();
  IntervalVector result(x);
  for (const auto& c : list_) {
    IntervalVector y(x);
    c->contract(y);
    result &= y;
    if (result.is_empty()) break;
  }
  x = std::move(result);
}

void CtcUnion::contract(IntervalVector& x) const {
  check_dim(x);
  if (x.is_empty()) return x.set_empty();
  IntervalVector result = IntervalVector::empty(x.size());
  for (const auto& c : list_) {
    IntervalVector y(x);
    c->contract(y);
    y &= x;  // a contractor never enlarges; guard against one that would
    result |= y;
  }
  x = std::move(result);
}

void CtcCompo::contract(IntervalVector& x) const {
  check_dim(x);
  for (const auto& c : list_) {
    if (x.is_empty()) break;
    c->contract(x);
  }
  if (x.is_empty()) x.set_empty();
}

CtcFixPoint::CtcFixPoint(CtcPtr ctc, double ratio)
    : Ctc(checked(ctc, "CtcFixPoint")->nb_vars()), ctc_(std::move(ctc)), ratio_(ratio) {
  check_ratio(ratio, "CtcFixPoint");
}

void CtcFixPoint::contract(IntervalVector& x) const {
  check_dim(x);
  while (!x.is_empty()) {
    const IntervalVector before(x);
    ctc_->contract(x);
    x &= before;
    if (!shrank(before, x, ratio_)) break;
  }
  if (x.is_empty()) x.set_empty();
}

std::shared_ptr<CtcInter> operator&(const CtcPtr& c1, const CtcPtr& c2) {
  return std::make_shared<CtcInter>(std::vector<CtcPtr>{c1, c2});
}

std::shared_ptr<CtcUnion> operator|(const CtcPtr& c1, const CtcPtr& c2) {
  return std::make_shared<CtcUnion>(std::vector<CtcPtr>{c1, c2});
}

}  // namespace sillage

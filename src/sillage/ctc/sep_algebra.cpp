#include "sillage/ctc/sep_algebra.h"

#include <string>

namespace sillage {

namespace {

std::size_t first_nb_vars(const std::vector<SepPtr>& list, const char* kind) {
  if (list.empty()) throw Error(std::string(kind) + ": needs at least one separator");
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (!list[i]) throw Error(std::string(kind) + ": separator " + std::to_string(i) + " is null");
  }
  return list[0]->nb_vars();
}

// Runs every separator on copies of (x_in, x_out); `meet_in` says whether the
// inner results are intersected (union of sets) or hulled (intersection of sets).
void combine(const std::vector<SepPtr>& list, IntervalVector& x_in, IntervalVector& x_out, bool meet_in) {
  const std::size_t n = x_in.size();
  IntervalVector in = meet_in ? x_in : IntervalVector::empty(n);
  IntervalVector out = meet_in ? IntervalVector::empty(n) : x_out;
  for (const auto& s : list) {
    IntervalVector a(x_in), b(x_out);
    s->separate(a, b);
    a &= x_in;  // a separator never enlarges; guard against one that would
    b &= x_out;
    if (meet_in) {
      in &= a;
      out |= b;
    } else {
      in |= a;
      out &= b;
    }
  }
  x_in = std::move(in);
  x_out = std::move(out);
}

}  // namespace

SepCombination::SepCombination(std::vector<SepPtr> list, const char* kind)
    : Sep(first_nb_vars(list, kind)), list_(std::move(list)) {
  for (std::size_t i = 0; i < list_.size(); ++i) {
    if (list_[i]->nb_vars() != nb_vars()) {
      throw DimensionError(std::string(kind) + ": separator " + std::to_string(i) + " (" + list_[i]->name() +
                           ") acts on " + std::to_string(list_[i]->nb_vars()) + " variables, separator 0 on " +
                           std::to_string(nb_vars()));
    }
  }
}

void SepInter::separate(IntervalVector& x_in, IntervalVector& x_out) const {
  check_dim(x_in, x_out);
  combine(list_, x_in, x_out, false);
}

void SepUnion::separate(IntervalVector& x_in, IntervalVector& x_out) const {
  check_dim(x_in, x_out);
  combine(list_, x_in, x_out, true);
}

SepNot::SepNot(SepPtr sep) : Sep(sep ? sep->nb_vars() : 0), sep_(std::move(sep)) {
  if (!sep_) throw Error("SepNot: separator is null");
}

void SepNot::separate(IntervalVector& x_in, IntervalVector& x_out) const {
  check_dim(x_in, x_out);
  sep_->separate(x_out, x_in);
}

std::shared_ptr<SepInter> operator&(const SepPtr& s1, const SepPtr& s2) {
  return std::make_shared<SepInter>(std::vector<SepPtr>{s1, s2});
}

std::shared_ptr<SepUnion> operator|(const SepPtr& s1, const SepPtr& s2) {
  return std::make_shared<SepUnion>(std::vector<SepPtr>{s1, s2});
}

std::shared_ptr<SepNot> operator~(const SepPtr& s) { return std::make_shared<SepNot>(s); }

}  // namespace sillage

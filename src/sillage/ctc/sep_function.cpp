#include "sillage/ctc/sep_function.h"

#include <limits>

namespace sillage {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Closed boxes covering before \ after (after ⊆ before): for each component,
// the two slabs of `before` beyond the bounds of `after`.
std::vector<IntervalVector> removed_cover(const IntervalVector& before, const IntervalVector& after) {
  if (after.is_empty()) return {before};
  std::vector<IntervalVector> cover;
  for (std::size_t i = 0; i < before.size(); ++i) {
    if (before[i].lb() < after[i].lb()) {
      IntervalVector b(before);
      b[i] = Interval(before[i].lb(), after[i].lb());
      cover.push_back(std::move(b));
    }
    if (after[i].ub() < before[i].ub()) {
      IntervalVector b(before);
      b[i] = Interval(after[i].ub(), before[i].ub());
      cover.push_back(std::move(b));
    }
  }
  return cover;
}

}  // namespace

SepFunction::SepFunction(const Function& f, const IntervalVector& y)
    : Sep(f.nb_vars()), outer_(f, y), check_(f) {}

SepFunction::SepFunction(const Function& f, const Interval& y) : SepFunction(f, IntervalVector{y}) {}

void SepFunction::contract_in(IntervalVector& x) const {
  const Function& f = outer_.function();
  const IntervalVector& y = outer_.image();
  if (x.is_empty() || y.is_empty()) return;  // X empty: nothing is proven inside
  IntervalVector result = IntervalVector::empty(x.size());
  IntervalVector piece(y.size());
  for (std::size_t i = 0; i < y.size(); ++i) {
    const Interval all = piece[i];
    if (y[i].lb() > -kInf) {
      piece[i] = Interval(-kInf, y[i].lb());
      IntervalVector z(x);
      if (f.hc4_revise(z, piece) && !z.is_empty()) result |= z;
    }
    if (y[i].ub() < kInf) {
      piece[i] = Interval(y[i].ub(), kInf);
      IntervalVector z(x);
      if (f.hc4_revise(z, piece) && !z.is_empty()) result |= z;
    }
    piece[i] = all;
    if (result == x) return;  // nothing left to remove
  }
  result &= x;
  if (!check_.is_total()) {
    for (const auto& b : removed_cover(x, result)) {
      if (!check_.defined_on(b)) return;  // not proven defined: keep x whole
    }
  }
  x = std::move(result);
}

void SepFunction::separate(IntervalVector& x_in, IntervalVector& x_out) const {
  check_dim(x_in, x_out);
  contract_in(x_in);
  outer_.contract(x_out);
}

}  // namespace sillage

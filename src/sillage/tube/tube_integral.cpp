#include "sillage/tube/tube_integral.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "sillage/error.h"
#include "sillage/interval/rounding.h"

namespace sillage {

namespace {

using rounding::kInf;
using rounding::kMax;

// [lo, hi] where an all-infinite range becomes the unbounded interval on its side.
Interval make_range(double lo, double hi) {
  if (lo == kInf) return Interval::from_bounds_unchecked(kMax, kInf);
  if (hi == -kInf) return Interval::from_bounds_unchecked(-kInf, -kMax);
  return Interval::from_bounds_unchecked(lo, hi);
}

// Range of F(s2) - F(s1) over s1 ∈ [t1], s2 ∈ [t2], F = L (the infinite
// parts are -inf) or U (+inf). The ranks decide first: if some pair has
// rank(s2) > rank(s1), an unbounded slice lies inside (s1, s2) and the value
// is infinite; if some pair has equal ranks (then necessarily s2 of the
// extreme rank of [t2] and s1 of the opposite one of [t1]), fin decides; if
// every pair has rank(s2) < rank(s1), every value is infinite the other way.
Interval difference(bool upper, const PrimitiveRange& r1, const PrimitiveRange& r2) {
  const auto d_max = r2.rank_last <=> r1.rank_first;   // the largest rank difference
  const auto d_min = r2.rank_first <=> r1.rank_last;   // the smallest
  double lo, hi;
  if (!upper) {
    lo = d_max > 0 ? -kInf : d_max < 0 ? kInf : rounding::sub_down(r2.min_last, r1.max_first);
    hi = d_min < 0 ? kInf : d_min > 0 ? -kInf : rounding::sub_up(r2.max_first, r1.min_last);
  } else {
    hi = d_max > 0 ? kInf : d_max < 0 ? -kInf : rounding::sub_up(r2.max_last, r1.min_first);
    lo = d_min < 0 ? -kInf : d_min > 0 ? kInf : rounding::sub_down(r2.min_first, r1.max_last);
  }
  return make_range(lo, hi);
}

void check_inside(const SynthesisTree& x, const Interval& t, const char* what, const char* where) {
  if (!t.is_subset(Interval(x.t0(), x.tf()))) {
    throw Error(std::string(where) + ": " + what + " = " + t.str() + " is not inside the domain [" + number_text(x.t0()) +
                ", " + number_text(x.tf()) + "]");
  }
}

Interval checked_point(const SynthesisTree& x, double t, const char* what, const char* where) {
  if (!(t >= x.t0() && t <= x.tf())) {
    throw Error(std::string(where) + ": " + what + " = " + number_text(t) + " is outside the domain [" + number_text(x.t0()) +
                ", " + number_text(x.tf()) + "]");
  }
  return Interval(t);
}


}  // namespace

// ---- over a synthesis tree ----

std::pair<Interval, Interval> partial_integral(const SynthesisTree& x, const Interval& t1, const Interval& t2) {
  check_inside(x, t1, "[t1]", "partial_integral(x, [t1], [t2])");
  check_inside(x, t2, "[t2]", "partial_integral(x, [t1], [t2])");
  if (t1.is_empty() || t2.is_empty()) return {Interval::empty(), Interval::empty()};
  PrimitiveRange l1, u1, l2, u2;
  x.ranges(t1, l1, u1);  // also checks that a tube's tree is current
  x.ranges(t2, l2, u2);
  if (x.has_empty_slice()) return {Interval::empty(), Interval::empty()};
  return {difference(false, l1, l2), difference(true, u1, u2)};
}

Interval integral(const SynthesisTree& x, const Interval& t1, const Interval& t2) {
  const auto [lower, upper] = partial_integral(x, t1, t2);
  if (lower.is_empty()) return Interval::empty();
  // t1 <= t2 for sure: (3.9). Otherwise the hull of both ranges (see header).
  if (t1.ub() <= t2.lb()) return Interval::from_bounds_unchecked(lower.lb(), upper.ub());
  return lower | upper;
}

Interval integral(const SynthesisTree& x, double t1, double t2) {
  return integral(x, checked_point(x, t1, "t1", "integral(x, t1, t2)"),
                  checked_point(x, t2, "t2", "integral(x, t1, t2)"));
}

Interval integral(const SynthesisTree& x, double t) {
  return integral(x, Interval(x.t0()), checked_point(x, t, "t", "integral(x, t)"));
}

Interval integral(const SynthesisTree& x, const Interval& t) {
  check_inside(x, t, "[t]", "integral(x, [t])");
  return integral(x, Interval(x.t0()), t);
}

// ---- over a tube ----

Interval integral(const Tube& x, double t) { return integral(*x.synthesis_tree(), t); }
Interval integral(const Tube& x, const Interval& t) { return integral(*x.synthesis_tree(), t); }
Interval integral(const Tube& x, double t1, double t2) { return integral(*x.synthesis_tree(), t1, t2); }
Interval integral(const Tube& x, const Interval& t1, const Interval& t2) {
  return integral(*x.synthesis_tree(), t1, t2);
}
std::pair<Interval, Interval> partial_integral(const Tube& x, const Interval& t1, const Interval& t2) {
  return partial_integral(*x.synthesis_tree(), t1, t2);
}

Tube primitive(const Tube& x, const Interval& x0) {
  const auto& td = x.tdomain();
  const std::size_t n = x.nb_slices();
  const auto times = td->times();
  const auto in = x.slices();
  bool empty = x0.is_empty();
  for (std::size_t k = 0; k < n && !empty; ++k) empty = in[k].is_empty();
  if (empty) return Tube(td, Interval::empty());
  std::vector<Interval> slices(n), gates(n + 1);
  gates[0] = x0;
  for (std::size_t k = 0; k < n; ++k) {
    const Interval width = Interval(times[k + 1]) - Interval(times[k]);
    gates[k + 1] = gates[k] + width * in[k];
    // t - t_k ranges over [0, exact width] ⊂ [0, ub(width)].
    slices[k] = gates[k] + Interval(0.0, width.ub()) * in[k];
  }
  return Tube(td, slices, gates);
}

// ---- TubeAnalysis ----

std::shared_ptr<const SynthesisTree> TubeAnalysis::tree() const { return x_->synthesis_tree(); }

}  // namespace sillage

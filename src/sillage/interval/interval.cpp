#include "sillage/error.h"
#include "sillage/interval/interval.h"

#include <ostream>
#include <sstream>

namespace sillage {

using rounding::kInf;
using rounding::kMax;

void detail::throw_bad_point(double x) {
  throw Error("Interval(x): x must be a finite number, got " + number_text(x));
}

void detail::throw_bad_bounds(double lb, double ub) {
  if (lb != lb || ub != ub) {
    throw Error("Interval(lb, ub): NaN bound in [" + number_text(lb) + ", " + number_text(ub) + "]");
  }
  if (lb > ub) {
    throw Error("Interval(lb, ub): inverted bounds, lb = " + number_text(lb) + " > ub = " + number_text(ub) +
                " (use Interval::empty() for the empty set)");
  }
  throw Error("Interval(lb, ub): [" + number_text(lb) + ", " + number_text(ub) +
              "] contains no real number; infinite bounds are limits, not members");
}

// pi = 3.14159265358979323846..., between two consecutive doubles.
Interval Interval::pi() { return {0x1.921fb54442d18p+1, 0x1.921fb54442d19p+1, Unchecked{}}; }
Interval Interval::half_pi() { return {0x1.921fb54442d18p+0, 0x1.921fb54442d19p+0, Unchecked{}}; }
Interval Interval::two_pi() { return {0x1.921fb54442d18p+2, 0x1.921fb54442d19p+2, Unchecked{}}; }

bool Interval::is_interior_subset(const Interval& y) const {
  if (is_empty()) return true;
  if (y.is_empty()) return false;
  const bool left = y.lo_ < lo_ || (y.lo_ == -kInf && lo_ == -kInf);
  const bool right = hi_ < y.hi_ || (y.hi_ == kInf && hi_ == kInf);
  return left && right;
}

double Interval::mid() const {
  if (is_empty()) return std::numeric_limits<double>::quiet_NaN();
  if (lo_ == -kInf) return hi_ == kInf ? 0.0 : -kMax;
  if (hi_ == kInf) return kMax;
  // (lo + hi) / 2 rounds once: the sum is exact whenever halving could round.
  const double m = (std::fabs(lo_) <= 0x1p1022 && std::fabs(hi_) <= 0x1p1022) ? (lo_ + hi_) * 0.5
                                                                               : lo_ * 0.5 + hi_ * 0.5;
  return std::clamp(m, lo_, hi_) + 0.0;  // + 0.0 turns -0 into +0
}

double Interval::diam() const {
  if (is_empty()) return std::numeric_limits<double>::quiet_NaN();
  return rounding::sub_up(hi_, lo_);
}

double Interval::rad() const {
  if (is_empty()) return std::numeric_limits<double>::quiet_NaN();
  if (is_unbounded()) return kInf;
  const double m = mid();
  return std::max(rounding::sub_up(m, lo_), rounding::sub_up(hi_, m));
}

double Interval::mag() const {
  if (is_empty()) return std::numeric_limits<double>::quiet_NaN();
  return std::max(std::fabs(lo_), std::fabs(hi_));
}

double Interval::mig() const {
  if (is_empty()) return std::numeric_limits<double>::quiet_NaN();
  if (lo_ <= 0 && hi_ >= 0) return 0.0;
  return std::min(std::fabs(lo_), std::fabs(hi_));
}

std::pair<Interval, Interval> Interval::bisect(double ratio) const {
  if (!(ratio > 0 && ratio < 1)) {
    throw Error("Interval::bisect: ratio must lie in (0, 1), got " + number_text(ratio));
  }
  if (is_empty()) throw Error("Interval::bisect: cannot bisect the empty interval");
  if (is_degenerate()) throw Error("Interval::bisect: cannot bisect the degenerate interval " + str());
  double p;
  if (lo_ == -kInf && hi_ == kInf) {
    p = 0.0;
  } else if (hi_ == kInf) {
    p = lo_ < 0 ? 0.0 : (lo_ < 1 ? 1.0 : std::min(kMax, lo_ * 2));
  } else if (lo_ == -kInf) {
    p = hi_ > 0 ? 0.0 : (hi_ > -1 ? -1.0 : std::max(-kMax, hi_ * 2));
  } else {
    p = lo_ * (1 - ratio) + hi_ * ratio;  // no overflow even for [-max, max]
    if (!(p > lo_ && p < hi_)) p = mid();
  }
  p = std::clamp(p, lo_, hi_);
  return {Interval(lo_, p, Unchecked{}), Interval(p, hi_, Unchecked{})};
}

Interval Interval::inflate(double r) const {
  if (!(r >= 0)) throw Error("Interval::inflate: radius must be >= 0, got " + number_text(r));
  if (is_empty()) return empty();
  return {rounding::sub_down(lo_, r), rounding::add_up(hi_, r), Unchecked{}};
}

std::pair<Interval, Interval> div2(const Interval& c, const Interval& b) {
  using rounding::div_down, rounding::div_up;
  const Interval e = Interval::empty();
  // + 0.0 turns a -0 bound (c / inf) into +0.
  auto make = [](double lo, double hi) { return Interval::from_bounds_unchecked(lo + 0.0, hi + 0.0); };
  if (c.is_empty() || b.is_empty()) return {e, e};
  const double b1 = b.lb(), b2 = b.ub(), c1 = c.lb(), c2 = c.ub();
  if (b1 > 0 || b2 < 0) return {c / b, e};
  if (c1 <= 0 && c2 >= 0) return {Interval::all_reals(), e};
  if (b1 == 0 && b2 == 0) return {e, e};
  if (c1 > 0) {  // z * b' = c' > 0: z has the sign of b'
    if (b1 == 0) return {make(div_down(c1, b2), kInf), e};
    if (b2 == 0) return {make(-kInf, div_up(c1, b1)), e};
    return {make(-kInf, div_up(c1, b1)), make(div_down(c1, b2), kInf)};
  }
  // c2 < 0: z has the sign opposite to b'
  if (b1 == 0) return {make(-kInf, div_up(c2, b2)), e};
  if (b2 == 0) return {make(div_down(c2, b1), kInf), e};
  return {make(-kInf, div_up(c2, b2)), make(div_down(c2, b1), kInf)};
}

Interval abs(const Interval& x) {
  if (x.is_empty()) return Interval::empty();
  if (x.lb() >= 0) return x;
  if (x.ub() <= 0) return -x;
  return Interval::from_bounds_unchecked(0.0, std::max(-x.lb(), x.ub()));
}

Interval min(const Interval& x, const Interval& y) {
  if (x.is_empty() || y.is_empty()) return Interval::empty();
  return Interval::from_bounds_unchecked(std::min(x.lb(), y.lb()), std::min(x.ub(), y.ub()));
}

Interval max(const Interval& x, const Interval& y) {
  if (x.is_empty() || y.is_empty()) return Interval::empty();
  return Interval::from_bounds_unchecked(std::max(x.lb(), y.lb()), std::max(x.ub(), y.ub()));
}

Interval sign(const Interval& x) {
  if (x.is_empty()) return Interval::empty();
  auto s = [](double v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); };
  return Interval::from_bounds_unchecked(s(x.lb()), s(x.ub()));
}

std::string Interval::str() const {
  if (is_empty()) return "[ empty ]";
  std::ostringstream os;
  os.precision(17);
  os << "[" << lo_ << ", " << hi_ << "]";
  return os.str();
}

std::ostream& operator<<(std::ostream& os, const Interval& x) { return os << x.str(); }

}  // namespace sillage

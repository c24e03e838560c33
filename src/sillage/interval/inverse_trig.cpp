// asin, acos, atan (monotone) and atan2 (extremes at two box corners).
#include "sillage/interval/elementary.h"
#include "sillage/interval/elementary_detail.h"

namespace sillage {

using namespace detail;

Interval asin(const Interval& x) {
  const Interval d = x & make(-1.0, 1.0);
  if (d.is_empty()) return Interval::empty();
  const double a = d.lb(), b = d.ub();
  double lo = a == -1 ? -kHalfPiHi : a == 1 ? kHalfPiLo : a == 0 ? 0.0 : widen_down(std::asin(a), kUlpsBasic);
  double hi = b == 1 ? kHalfPiHi : b == -1 ? -kHalfPiLo : b == 0 ? 0.0 : widen_up(std::asin(b), kUlpsBasic);
  // asin x >= x on [0, 1] and <= x on [-1, 0].
  if (a >= 0) lo = std::max(lo, a);
  if (b <= 0) hi = std::min(hi, b);
  return make(std::max(lo, -kHalfPiHi), std::min(hi, kHalfPiHi));
}

Interval acos(const Interval& x) {
  const Interval d = x & make(-1.0, 1.0);
  if (d.is_empty()) return Interval::empty();
  const double a = d.lb(), b = d.ub();  // decreasing
  double lo = b == 1 ? 0.0 : b == -1 ? kPiLo : b == 0 ? kHalfPiLo : widen_down(std::acos(b), kUlpsBasic);
  double hi = a == -1 ? kPiHi : a == 1 ? 0.0 : a == 0 ? kHalfPiHi : widen_up(std::acos(a), kUlpsBasic);
  // acos x <= pi/2 for x >= 0, >= pi/2 for x <= 0: the values given at 0.
  if (a >= 0) hi = std::min(hi, kHalfPiHi);
  if (b <= 0) lo = std::max(lo, kHalfPiLo);
  return make(std::max(lo, 0.0), std::min(hi, kPiHi));
}

Interval atan(const Interval& x) {
  if (x.is_empty()) return Interval::empty();
  const double a = x.lb(), b = x.ub();
  double lo = a == 0 ? 0.0 : widen_down(std::atan(a), kUlpsBasic);  // atan(-inf) = -pi/2
  double hi = b == 0 ? 0.0 : widen_up(std::atan(b), kUlpsBasic);
  // |atan x| <= |x|, with the sign of x.
  if (b >= 0) hi = std::min(hi, b);
  if (a <= 0) lo = std::max(lo, a);
  if (a >= 0) lo = std::max(lo, 0.0);
  if (b <= 0) hi = std::min(hi, 0.0);
  return make(std::max(lo, -kHalfPiHi), std::min(hi, kHalfPiHi));
}

namespace {

// Bounds of the angle of the point (x, y) != (0, 0), y = +0 on the negative x axis
// (angle pi); infinite coordinates give the limit angles. Inside a quadrant
// the widened libm value is clipped to the quadrant's bounds, which are the
// values given on the axes: a box reaching an axis then never gets a smaller
// enclosure than one of its sub-boxes (inclusion monotonicity).
double angle_down(double y, double x) {
  if (y == 0) return x > 0 ? 0.0 : kPiLo;
  if (x == 0) return y > 0 ? kHalfPiLo : -kHalfPiHi;
  const double quadrant_lb = y > 0 ? (x > 0 ? 0.0 : kHalfPiLo) : (x > 0 ? -kHalfPiHi : -kPiHi);
  return std::max(widen_down(std::atan2(y, x), kUlpsBasic), quadrant_lb);
}

double angle_up(double y, double x) {
  if (y == 0) return x > 0 ? 0.0 : kPiHi;
  if (x == 0) return y > 0 ? kHalfPiHi : -kHalfPiLo;
  const double quadrant_ub = y > 0 ? (x > 0 ? kHalfPiHi : kPiHi) : (x > 0 ? 0.0 : -kHalfPiLo);
  return std::min(widen_up(std::atan2(y, x), kUlpsBasic), quadrant_ub);
}

}  // namespace

Interval atan2(const Interval& y, const Interval& x) {
  if (y.is_empty() || x.is_empty()) return Interval::empty();
  const double c = y.lb() + 0.0, d = y.ub() + 0.0, a = x.lb() + 0.0, b = x.ub() + 0.0;
  if (c == 0 && d == 0) {  // on the x axis: 0 to the right, pi to the left
    if (a == 0 && b == 0) return Interval::empty();
    return make(b > 0 ? 0.0 : kPiLo, a < 0 ? kPiHi : 0.0);
  }
  // The box meets the negative x axis from below: angles near -pi and pi.
  if (a < 0 && c < 0 && d >= 0) return make(-kPiHi, kPiHi);
  if (a == 0 && b == 0) return make(c < 0 ? -kHalfPiHi : kHalfPiLo, d > 0 ? kHalfPiHi : -kHalfPiLo);
  // Elsewhere the angle is continuous on the convex box minus the origin, so
  // its extremes are at corners; which two depends on where the box lies.
  double lo, hi;
  if (a >= 0) {  // right half plane
    lo = angle_down(c, c >= 0 ? b : a);
    hi = d == 0 ? 0.0 : angle_up(d, d > 0 ? a : b);  // d = 0: the point (b, 0), b > 0
  } else if (c >= 0) {  // upper half plane, touching x < 0
    lo = b <= 0 ? angle_down(d, b) : angle_down(c, b);
    hi = angle_up(c, a);
  } else {  // d < 0: lower half plane, x < 0 somewhere
    lo = angle_down(d, a);
    hi = b <= 0 ? angle_up(c, b) : angle_up(d, b);
  }
  if (c >= 0) lo = std::max(lo, 0.0);
  if (d <= 0) hi = std::min(hi, 0.0);
  return make(std::max(lo, -kPiHi), std::min(hi, kPiHi));
}

}  // namespace sillage

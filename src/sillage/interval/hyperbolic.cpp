// sinh, tanh (increasing) and cosh (even, minimum 1 at 0).
#include "sillage/interval/elementary.h"
#include "sillage/interval/elementary_detail.h"

namespace sillage {

using namespace detail;

namespace {

// Smallest double above asinh(MAX) = acosh(MAX) = 710.4758600739439...:
// |sinh x| and cosh x exceed MAX exactly when |x| >= kHypOverflow.
constexpr double kHypOverflow = 0x1.633ce8fb9f87ep+9;

double sinh_down(double v) {
  if (v == 0) return 0.0;
  if (v >= kHypOverflow) return kMax;
  return widen_down(std::sinh(v), kUlpsHyp);
}

double sinh_up(double v) { return -sinh_down(-v); }  // sinh is odd

}  // namespace

Interval sinh(const Interval& x) {
  if (x.is_empty()) return Interval::empty();
  const double a = x.lb(), b = x.ub();
  double lo = sinh_down(a), hi = sinh_up(b);
  // |sinh x| >= |x|.
  if (a >= 0) lo = std::max(lo, a);
  if (b <= 0) hi = std::min(hi, b);
  return make(lo, hi);
}

Interval cosh(const Interval& x) {
  if (x.is_empty()) return Interval::empty();
  const double m = x.mig(), M = x.mag();
  double lo = 1.0, hi = 1.0;
  if (m != 0) lo = m >= kHypOverflow ? kMax : std::max(widen_down(std::cosh(m), kUlpsHyp), 1.0);
  if (M != 0) hi = M >= kHypOverflow ? kInf : widen_up(std::cosh(M), kUlpsHyp);
  return make(lo, hi);
}

Interval tanh(const Interval& x) {
  if (x.is_empty()) return Interval::empty();
  const double a = x.lb(), b = x.ub();
  double lo = a == 0 ? 0.0 : widen_down(std::tanh(a), kUlpsHyp);
  double hi = b == 0 ? 0.0 : widen_up(std::tanh(b), kUlpsHyp);
  // |tanh x| <= min(|x|, 1), with the sign of x.
  if (b >= 0) hi = std::min(hi, b);
  if (a <= 0) lo = std::max(lo, a);
  if (a >= 0) lo = std::max(lo, 0.0);
  if (b <= 0) hi = std::min(hi, 0.0);
  return make(std::max(lo, -1.0), std::min(hi, 1.0));
}

}  // namespace sillage

// exp and log: increasing, one libm call per bound, widened by a proven margin.
#include "sillage/interval/elementary.h"
#include "sillage/interval/elementary_detail.h"

namespace sillage {

using namespace detail;

namespace {

// Doubles on each side of log(MAX) = 709.78271289338399678...: exp(x) > MAX
// exactly when x >= kExpOverflow.
constexpr double kExpOverflow = 0x1.62e42fefa39fp+9;

double exp_down(double a) {
  if (a == 0) return 1.0;
  if (a >= kExpOverflow) return kMax;  // exact value above MAX
  return std::max(widen_down(std::exp(a), kUlpsBasic), 0.0);
}

double exp_up(double b) {
  if (b == 0) return 1.0;
  if (b >= kExpOverflow) return kInf;
  return widen_up(std::exp(b), kUlpsBasic);
}

}  // namespace

Interval exp(const Interval& x) {
  if (x.is_empty()) return Interval::empty();
  const double a = x.lb(), b = x.ub();
  double lo = exp_down(a), hi = exp_up(b);
  // exp(x) >= 1 exactly for x >= 0 and <= 1 for x <= 0.
  if (a >= 0) lo = std::max(lo, 1.0);
  if (b <= 0) hi = std::min(hi, 1.0);
  return make(lo, hi);
}

Interval log(const Interval& x) {
  if (x.is_empty() || x.ub() <= 0) return Interval::empty();  // log(0) is no real
  const double a = std::max(x.lb(), 0.0), b = x.ub();
  double lo, hi;
  if (a == 0) lo = -kInf;
  else if (a == 1) lo = 0.0;
  else lo = widen_down(std::log(a), kUlpsBasic);
  if (b == kInf) hi = kInf;
  else if (b == 1) hi = 0.0;
  else hi = widen_up(std::log(b), kUlpsBasic);
  if (a >= 1) lo = std::max(lo, 0.0);
  if (b <= 1) hi = std::min(hi, 0.0);
  return make(lo, hi);
}

}  // namespace sillage

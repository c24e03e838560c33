// sin, cos, tan over intervals.
//
// The extrema (and the poles of tan) sit on the quadrant boundaries k pi/2.
// Each end point's quadrant k mod 4 comes from a fast reduction x * 2/pi when
// its error bound proves floor() right, else from the exact reduction of
// trig_reduce. The number of boundaries crossed is then (qb - qa) mod 4, unless
// [a, b] is long enough to hold four more, in which case every extremum is in.
//
// End point values come from libm widened by its error bound, except next to
// a zero or a pole (|value| < 2^-27 or, for tan, > 2^27): there the reduction
// cancels most bits and libm is no longer within its documented error, so the
// value comes from the exact reduction x = q pi/2 + r, r tiny.
#include "sillage/interval/elementary.h"
#include "sillage/interval/elementary_detail.h"
#include "sillage/interval/trig_reduce.h"

namespace sillage {

using namespace detail;

namespace {

constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;  // round-to-nearest of 2/pi
constexpr double kSmall = 0x1p-27;                   // below: the exact reduction

// k mod 4 for x in [k pi/2, (k+1) pi/2), x finite; -1 if undecidable.
inline int quadrant(double x) {
  const double ax = std::fabs(x);
  if (ax < 1) return x >= 0 ? 0 : 3;  // pi/2 > 1
  if (ax <= 0x1p28) {
    // |t - x 2/pi| <= |x| 2^-52 (error of the constant and of the product).
    const double t = x * kTwoOverPi;
    long long k = static_cast<long long>(t);  // truncation; floor below
    if (static_cast<double>(k) > t) --k;
    const double f = t - static_cast<double>(k);
    const double margin = ax * 0x1p-50 + 0x1p-50;
    if (f > margin && f < 1.0 - margin) return static_cast<int>(k & 3);
  }
  const Reduced r = reduce_half_pi(x);
  return r.ok ? r.quadrant : -1;
}

// Number of boundaries k pi/2 in [a, b] (a <= b finite), capped at 4; 4 also
// when a quadrant is undecidable (then every extremum is assumed inside).
int crossings(double a, double b, int qa, int qb) {
  if (qa < 0 || qb < 0) return 4;
  const int r = (qb - qa) & 3;
  // The count is r or r + 4 or more; r + 4 needs b - a > (r + 3) pi/2, while
  // r itself means b - a < (r + 1) pi/2: a crude test separates the two.
  return (b - a) * kTwoOverPi > r + 2.5 ? 4 : r;
}

// Is a boundary leaving quadrant q (mod 4) among the n boundaries crossed from qa?
inline bool crosses_out_of(int q, int qa, int n) { return ((q - qa) & 3) < n; }

struct Bounds {
  double lo, hi;
};

Bounds negate(Bounds b) { return {-b.hi, -b.lo}; }

// Outward bounds of v = vh + vl (|vl| <= ulp(vh)/2) known to a relative
// error of 2^-90: vh itself, or one double further out.
Bounds outward(double vh, double vl) {
  const double d = std::fabs(vh) * 0x1p-90;
  return {vl - d >= 0 ? vh : rounding::next_down(vh), vl + d <= 0 ? vh : rounding::next_up(vh)};
}

Bounds fast_two_sum(double a, double b) {  // |a| >= |b|: a + b = s + e exactly
  const double sum = a + b;
  return {sum, b - (sum - a)};
}

// sin r, cos r, tan r, -cot r for r = rh + rl, |r| < 2^-26 (so r^2 < 2^-52):
// the first two terms of each series, the rest is far below 2^-90 relative.
Bounds sin_tiny(double rh, double rl) {
  const Bounds v = fast_two_sum(rh, rl - rh * rh * rh / 6);  // r - r^3/6
  return outward(v.lo, v.hi);
}
Bounds tan_tiny(double rh, double rl) {
  const Bounds v = fast_two_sum(rh, rl + rh * rh * rh / 3);  // r + r^3/3
  return outward(v.lo, v.hi);
}
Bounds cos_tiny() { return {rounding::next_down(1.0), 1.0}; }  // 1 - r^2/2 in (1 - 2^-53, 1)
Bounds neg_cot_tiny(double rh, double rl) {
  // 1/r = y + (1 - y rh)/rh - rl/rh^2 for y = 1/rh rounded; cot r = 1/r - r/3.
  const double y = 1 / rh;
  const double res = std::fma(-y, rh, 1.0);  // exact
  const Bounds v = fast_two_sum(-y, -(res * y - rl * y * y - rh / 3));
  return outward(v.lo, v.hi);
}

enum class Fn { kSin, kCos, kTan };

// Rigorous value at x (|x| >= 1) from the exact reduction; false if r is not tiny.
bool value_by_reduction(double x, Fn fn, Bounds& out) {
  const Reduced red = reduce_half_pi(x);
  if (!red.ok || std::fabs(red.r_hi) >= 0x1p-26) return false;
  const double rh = red.r_hi, rl = red.r_lo;
  if (fn == Fn::kTan) {
    out = (red.q & 1) == 0 ? tan_tiny(rh, rl) : neg_cot_tiny(rh, rl);
    return true;
  }
  const int q = (red.q + (fn == Fn::kCos ? 1 : 0)) & 3;  // cos x = sin(x + pi/2)
  switch (q) {
    case 0: out = sin_tiny(rh, rl); break;
    case 1: out = cos_tiny(); break;
    case 2: out = negate(sin_tiny(rh, rl)); break;
    default: out = negate(cos_tiny()); break;
  }
  return true;
}

// Bounds of sin x or cos x from the libm value v = f(x).
inline Bounds wave_at(double x, double v, Fn fn) {
  if (x == 0) return fn == Fn::kSin ? Bounds{0.0, 0.0} : Bounds{1.0, 1.0};
  if (std::fabs(v) < kSmall && std::fabs(x) >= 1) {
    Bounds b;
    if (value_by_reduction(x, fn, b)) return b;
    return {-1.0, 1.0};  // libm and the reduction disagree: give up tightness
  }
  return {widen_down(v, kUlpsBasic), widen_up(v, kUlpsBasic)};
}

Bounds tan_at(double x, double v) {
  if (x == 0) return {0.0, 0.0};
  const double av = std::fabs(v);
  if ((av < kSmall || av > 1 / kSmall) && std::fabs(x) >= 1) {
    Bounds b;
    if (value_by_reduction(x, Fn::kTan, b)) return b;
    return {-kInf, kInf};
  }
  return {widen_down(v, kUlpsTanPow), widen_up(v, kUlpsTanPow)};
}

Interval unit() { return make(-1.0, 1.0); }

}  // namespace

Interval sin(const Interval& x) {
  if (x.is_empty()) return Interval::empty();
  const double a = x.lb(), b = x.ub();
  if (!std::isfinite(a) || !std::isfinite(b) || b - a >= 6.3) return unit();
  const Bounds fa = wave_at(a, std::sin(a), Fn::kSin);
  double lo, hi;
  if (a == b) {
    lo = fa.lo;
    hi = fa.hi;
  } else {
    const Bounds fb = wave_at(b, std::sin(b), Fn::kSin);
    const int qa = quadrant(a), n = crossings(a, b, qa, quadrant(b));
    lo = crosses_out_of(2, qa, n) ? -1.0 : std::min(fa.lo, fb.lo);
    hi = crosses_out_of(0, qa, n) ? 1.0 : std::max(fa.hi, fb.hi);
  }
  // |sin x| <= |x|, and |sin x| <= 1; sin x has the sign of x on [-3, 3]
  // (the value 0 given at 0: widened values around a tiny x must not cross it).
  if (a >= 0) hi = std::min(hi, b);
  if (b <= 0) lo = std::max(lo, a);
  if (a >= 0 && b <= 3) lo = std::max(lo, 0.0);
  if (b <= 0 && a >= -3) hi = std::min(hi, 0.0);
  return make(std::max(lo, -1.0), std::min(hi, 1.0));
}

Interval cos(const Interval& x) {
  if (x.is_empty()) return Interval::empty();
  const double a = x.lb(), b = x.ub();
  if (!std::isfinite(a) || !std::isfinite(b) || b - a >= 6.3) return unit();
  const Bounds fa = wave_at(a, std::cos(a), Fn::kCos);
  double lo, hi;
  if (a == b) {
    lo = fa.lo;
    hi = fa.hi;
  } else {
    const Bounds fb = wave_at(b, std::cos(b), Fn::kCos);
    const int qa = quadrant(a), n = crossings(a, b, qa, quadrant(b));
    lo = crosses_out_of(1, qa, n) ? -1.0 : std::min(fa.lo, fb.lo);
    hi = crosses_out_of(3, qa, n) ? 1.0 : std::max(fa.hi, fb.hi);
  }
  return make(std::max(lo, -1.0), std::min(hi, 1.0));
}

Interval tan(const Interval& x) {
  if (x.is_empty()) return Interval::empty();
  const double a = x.lb(), b = x.ub();
  if (!std::isfinite(a) || !std::isfinite(b) || b - a >= 3.2) return Interval::all_reals();
  if (a != b) {
    const int qa = quadrant(a), n = crossings(a, b, qa, quadrant(b));
    if (crosses_out_of(0, qa, n) || crosses_out_of(2, qa, n)) return Interval::all_reals();  // a pole
  }
  const Bounds ta = tan_at(a, std::tan(a)), tb = a == b ? ta : tan_at(b, std::tan(b));
  double lo = ta.lo, hi = tb.hi;
  // tan x >= x on [0, pi/2) and tan x <= x on (-pi/2, 0].
  if (a >= 0 && a <= 1.5) lo = std::max(lo, a);
  if (b <= 0 && b >= -1.5) hi = std::min(hi, b);
  return make(lo, hi);
}

}  // namespace sillage

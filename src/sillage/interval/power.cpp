// Powers and roots: x^n (integer n), x^y (real y, x >= 0), the real n-th root.
#include <limits>
#include <string>

#include "sillage/interval/elementary.h"
#include "sillage/interval/elementary_detail.h"

namespace sillage {

using namespace detail;

namespace {

// v^m (v > 0) by binary exponentiation if every product is exact (fma residual
// 0, no overflow, nothing below 2^-968 where residuals may underflow); false
// otherwise. Keeps exact cases such as 2^10 or 1.5^3 exact, where a widened
// libm value would blur them.
bool pow_exact(double v, unsigned m, double& out) {
  double r = 1.0, s = v;
  for (;;) {
    if (m & 1u) {
      const double p = r * s;
      if (!std::isfinite(p) || std::fabs(p) < 0x1p-968 || std::fma(r, s, -p) != 0) return false;
      r = p;
    }
    m >>= 1;
    if (m == 0) break;
    const double q = s * s;
    if (!std::isfinite(q) || q < 0x1p-968 || std::fma(s, s, -q) != 0) return false;
    s = q;
  }
  out = r;
  return true;
}

// Rigorous bounds of v^n (v >= 0, n >= 1) by directed multiplications.
double pow_mul_up(double v, int n) {
  double r = 1.0, s = v;
  bool first = true;  // r = 1 exactly: skip that product
  for (unsigned m = static_cast<unsigned>(n);;) {
    if (m & 1u) {
      r = first ? s : rounding::mul_up(r, s);
      first = false;
    }
    m >>= 1;
    if (m == 0) return r;
    s = rounding::mul_up(s, s);
  }
}

double pow_mul_down(double v, int n) {
  double r = 1.0, s = v;
  bool first = true;  // r = 1 exactly: skip that product
  for (unsigned m = static_cast<unsigned>(n);;) {
    if (m & 1u) {
      r = first ? s : rounding::mul_down(r, s);
      first = false;
    }
    m >>= 1;
    if (m == 0) return r;
    s = rounding::mul_down(s, s);
  }
}

// Directed product chains for v^n, n != 0, n > INT_MIN (1 / chain for n < 0):
// rigorous, and tight where the widened libm value is coarse.
double chain_down(double v, int n) { return n > 0 ? pow_mul_down(v, n) : rounding::div_down(1.0, pow_mul_up(v, -n)); }
double chain_up(double v, int n) {
  if (n > 0) return pow_mul_up(v, n);
  const double d = pow_mul_down(v, -n);
  return d > 0 ? rounding::div_up(1.0, d) : kInf;
}

// The chain also serves for small |n| (a few products), and on overflow and
// underflow: where the libm value is widened past a lower power's directed
// bound (pow([1+u], 3) above pow([1+u], 2)), inclusion monotonicity of pow
// over an exponent interval would fail.
bool use_chain(int n, double r) {
  return n != std::numeric_limits<int>::min() && (std::abs(n) <= 64 || r == kInf || r < 0x1p-1000);
}

// Bounds of v^n for v >= 0 (v may be +inf) and n != 0; 0^n = inf for n < 0.
double pown_down(double v, int n) {
  if (v == 0) return n > 0 ? 0.0 : kInf;
  if (v == kInf) return n > 0 ? kInf : 0.0;
  if (n == 1) return v;
  const unsigned m = n > 0 ? static_cast<unsigned>(n) : 0u - static_cast<unsigned>(n);
  double p;
  if (pow_exact(v, m, p)) return n > 0 ? p : rounding::div_down(1.0, p);
  if (n == 2) return rounding::mul_down(v, v);
  if (n == -1) return rounding::div_down(1.0, v);
  const double r = std::pow(v, n);
  // v^n >= v (v > 1, n >= 1) and >= 1 (v < 1, n < 0), as the exact v^1 and v^0.
  const double floor = v > 1 && n > 0 ? v : v < 1 && n < 0 ? 1.0 : 0.0;
  const double lo = std::max(widen_down(r, kUlpsTanPow), floor);
  return use_chain(n, r) ? std::max(lo, chain_down(v, n)) : lo;
}

double pown_up(double v, int n) {
  if (v == 0) return n > 0 ? 0.0 : kInf;
  if (v == kInf) return n > 0 ? kInf : 0.0;
  if (n == 1) return v;
  const unsigned m = n > 0 ? static_cast<unsigned>(n) : 0u - static_cast<unsigned>(n);
  double p;
  if (pow_exact(v, m, p)) return n > 0 ? p : rounding::div_up(1.0, p);
  if (n == 2) return rounding::mul_up(v, v);
  if (n == -1) return rounding::div_up(1.0, v);
  const double r = std::pow(v, n);
  // v^n <= v (v < 1, n >= 1) and <= 1 (v > 1, n < 0).
  const double ceil = v < 1 && n > 0 ? v : v > 1 && n < 0 ? 1.0 : kInf;
  const double hi = std::min(widen_up(r, kUlpsTanPow), ceil);
  return use_chain(n, r) ? std::min(hi, chain_up(v, n)) : hi;
}

// Signed bounds of v^n for odd n (v^n has the sign of v).
double podd_down(double v, int n) { return v >= 0 ? pown_down(v, n) : -pown_up(-v, n); }
double podd_up(double v, int n) { return v >= 0 ? pown_up(v, n) : -pown_down(-v, n); }

bool is_small_int(double y) { return std::fabs(y) <= 0x1p30 && y == std::trunc(y); }

// x^e for the exponents evaluated exactly (integers, 1/2).
double exact_pow_down(double x, double e) { return e == 0.5 ? rounding::sqrt_down(x) : pown_down(x, static_cast<int>(e)); }
double exact_pow_up(double x, double e) { return e == 0.5 ? rounding::sqrt_up(x) : pown_up(x, static_cast<int>(e)); }

// The exactly evaluated exponents around a non-integer y (NaN where there is
// none: beyond +-2^30 only the side towards 0): x^y lies between the powers
// there (x^y is monotone in y). Clipping the widened libm value to them keeps
// inclusion monotonicity when a box's corner exponent is one of them and a
// sub-box's is not (pow([b], [1e-300]) ⊆ pow([b], [1e-300, 1])), underflow
// and overflow included.
void exact_neighbours(double y, double& below, double& above) {
  constexpr double kBig = 0x1p30, kNaN = std::numeric_limits<double>::quiet_NaN();
  const double n = std::floor(y);
  below = n > kBig ? kBig : n < -kBig ? kNaN : (n == 0 && y > 0.5 ? 0.5 : n);
  above = n >= kBig ? kNaN : n < -kBig ? -kBig : (n == 0 && y < 0.5 ? 0.5 : n + 1);
}

// Bounds of x^y for x >= 0 at a corner, with the C conventions 0^y = 0 (y > 0),
// 0^y = inf (y < 0), x^0 = 1, which are the limits of x^y there.
double powr_down(double x, double y) {
  if (y == 0 || x == 1) return 1.0;
  if (y == 0.5 || is_small_int(y)) return exact_pow_down(x, y);
  const double r = std::pow(x, y);
  if (x == 0 || x == kInf || std::isinf(y)) return r;  // exact limits
  double lo = std::max(widen_down(r, kUlpsTanPow), 0.0), e_lo, e_hi;
  exact_neighbours(y, e_lo, e_hi);
  const double e = x > 1 ? e_lo : e_hi;  // x^y >= x^e
  return std::isnan(e) ? lo : std::max(lo, exact_pow_down(x, e));
}

double powr_up(double x, double y) {
  if (y == 0 || x == 1) return 1.0;
  if (y == 0.5 || is_small_int(y)) return exact_pow_up(x, y);
  const double r = std::pow(x, y);
  if (x == 0 || x == kInf || std::isinf(y)) return r;  // exact limits
  double hi = widen_up(r, kUlpsTanPow), e_lo, e_hi;
  exact_neighbours(y, e_lo, e_hi);
  const double e = x > 1 ? e_hi : e_lo;  // x^y <= x^e
  return std::isnan(e) ? hi : std::min(hi, exact_pow_up(x, e));
}

// A close approximation of the n-th root of w in [1, 2^n), n >= 3: there the
// rounding of the exponent 1/n costs below one ulp.
double root_approx(double w, int n) {
  if (n == 3) return std::cbrt(w);
  double p = std::pow(w, 1.0 / n);
  const double q = std::pow(p, n);  // one Newton step
  if (std::isfinite(q)) p -= p * ((q - w) / w) / n;
  return p;
}

// x 2^e by multiplications with powers of two (exact: used where the result
// is a normal number), cheaper than ldexp.
double scale2(double x, int e) {
  while (e > 1000 || e < -1000) {
    const int step = e > 0 ? 1000 : -1000;
    x *= std::bit_cast<double>(static_cast<std::uint64_t>(step + 1023) << 52);
    e -= step;
  }
  return x * std::bit_cast<double>(static_cast<std::uint64_t>(e + 1023) << 52);
}

// v = w 2^(n k) with w in [1, 2^n): the root is root(w) 2^k, exactly scaled.
int root_scale(double v, int n, double& w) {
  w = v;
  if (n > 1000) return 0;  // the root is within a few ulps of 1 and pow() exact enough
  const int e = std::ilogb(v);
  const int k = e >= 0 ? e / n : -((-e + n - 1) / n);  // floor(e / n)
  w = scale2(v, -n * k);
  return k;
}

// Bounds of the n-th root of v >= 0, n >= 2: a candidate is accepted only
// when a directed power proves it is on the right side. From the estimate,
// the search moves outward until proven, or inward while still proven (so
// that exact roots come out exact).
double root_down(double v, int n) {
  if (v == 0 || v == kInf) return v;
  if (n == 2) return rounding::sqrt_down(v);
  double w;
  const int k = root_scale(v, n, w);
  auto below = [&](double c) { return pow_mul_up(c, n) <= w; };  // proves c <= root(w)
  double c = root_approx(w, n);
  if (below(c)) {
    for (int i = 0; i < 4 && below(step_up_pos(c, 1)); ++i) c = step_up_pos(c, 1);
    return scale2(c, k);
  }
  for (int i = 0; i < 40; ++i) {
    c = step_down_pos(c, i < 4 ? 1u : 1u << std::min(i - 2, 24));
    if (below(c)) return scale2(c, k);
  }
  return 0.0;
}

double root_up(double v, int n) {
  if (v == 0 || v == kInf) return v;
  if (n == 2) return rounding::sqrt_up(v);
  double w;
  const int k = root_scale(v, n, w);
  auto above = [&](double c) { return pow_mul_down(c, n) >= w; };  // proves c >= root(w)
  double c = root_approx(w, n);
  if (above(c)) {
    for (int i = 0; i < 4 && above(step_down_pos(c, 1)); ++i) c = step_down_pos(c, 1);
    return scale2(c, k);
  }
  for (int i = 0; i < 40; ++i) {
    c = step_up_pos(c, i < 4 ? 1u : 1u << std::min(i - 2, 24));
    if (above(c)) return scale2(c, k);
  }
  return scale2(2.0, k);  // root(w) < 2
}

}  // namespace

Interval pow(const Interval& x, int n) {
  if (x.is_empty()) return Interval::empty();
  if (n == 0) return make(1.0, 1.0);
  if (n == 1) return x;
  if (n == 2) return sqr(x);
  const double a = x.lb(), b = x.ub();
  if (n % 2 != 0) {
    if (n > 0) return make(podd_down(a, n), podd_up(b, n));
    // Odd negative: decreasing on each side of the pole at 0.
    if (a == 0 && b == 0) return Interval::empty();
    if (a >= 0) return make(pown_down(b, n), pown_up(a, n));
    if (b <= 0) return make(b == 0 ? -kInf : -pown_up(-b, n), -pown_down(-a, n));
    return Interval::all_reals();
  }
  const double mig = x.mig(), mag = x.mag();
  if (n > 0) return make(pown_down(mig, n), pown_up(mag, n));
  if (mag == 0) return Interval::empty();  // 0^-n undefined
  return make(pown_down(mag, n), pown_up(mig, n));
}

Interval pow(const Interval& x, const Interval& y) {
  if (x.is_empty() || y.is_empty()) return Interval::empty();
  const Interval xp = x & Interval::pos_reals();  // IEEE 1788 pow: x >= 0
  if (xp.is_empty()) return Interval::empty();
  const double a = xp.lb(), b = xp.ub(), c = y.lb(), d = y.ub();
  if (b == 0) return d > 0 ? make(0.0, 0.0) : Interval::empty();  // 0^y = 0, y > 0 only
  // x^y is monotone in x for a fixed y and in y for a fixed x: extremes at corners.
  double lo, hi;
  if (c >= 0) {         // increasing in x
    lo = a < 1 ? powr_down(a, d) : powr_down(a, c);
    hi = b > 1 ? powr_up(b, d) : powr_up(b, c);
  } else if (d <= 0) {  // decreasing in x
    lo = b > 1 ? powr_down(b, c) : powr_down(b, d);
    hi = a > 1 ? powr_up(a, d) : powr_up(a, c);
  } else {              // y straddles 0: x^0 = 1 lies between
    lo = std::min(powr_down(a, d), powr_down(b, c));
    hi = std::max(powr_up(a, c), powr_up(b, d));
  }
  // Exact facts: x^y >= 1 when x >= 1, y >= 0 or x <= 1, y <= 0; <= 1 otherwise.
  if ((a >= 1 && c >= 0) || (b <= 1 && d <= 0)) lo = std::max(lo, 1.0);
  if ((a >= 1 && d <= 0) || (b <= 1 && c >= 0)) hi = std::min(hi, 1.0);
  return make(std::max(lo, 0.0), hi);
}

// |x|^n is monotone in n on each side of |x| = 1: the real pow over [n]
// encloses it, the parity gives the sign.
Interval pow_big_int(const Interval& x, const Interval& n, bool odd) {
  const Interval pos = x & Interval::pos_reals(), neg = -(x & Interval::neg_reals());
  if (!odd) return pow(pos | neg, n);
  return pow(pos, n) | -pow(neg, n);
}

// An integral exponent is the integer power (defined for x < 0), as x^2.0 in an expression.
Interval pow(const Interval& x, double y) {
  if (!std::isfinite(y)) throw Error("pow(x, y): the exponent y must be a finite number, got " + std::to_string(y));
  if (y != std::trunc(y)) return pow(x, Interval(y));
  if (std::fabs(y) <= std::numeric_limits<int>::max()) return pow(x, static_cast<int>(y));
  return pow_big_int(x, Interval(y), std::fmod(y, 2.0) != 0);
}

Interval root(const Interval& x, int n) {
  if (n == 0) throw Error("root(x, n): n must be nonzero, got 0");
  if (x.is_empty()) return Interval::empty();
  if (n < 0) {
    if (n == std::numeric_limits<int>::min()) throw Error("root(x, n): n out of range");
    return Interval(1.0) / root(x, -n);
  }
  if (n == 1) return x;
  if (n % 2 == 0) {
    const Interval xp = x & Interval::pos_reals();
    if (xp.is_empty()) return Interval::empty();
    return make(root_down(xp.lb(), n), root_up(xp.ub(), n));
  }
  const double a = x.lb(), b = x.ub();
  const double lo = a >= 0 ? root_down(a, n) : -root_up(-a, n);
  const double hi = b >= 0 ? root_up(b, n) : -root_down(-b, n);
  return make(lo, hi);
}

}  // namespace sillage

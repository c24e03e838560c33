// Backward projections of powers, roots, exp/log, the hyperbolic functions and
// the inverse trigonometric functions.
//
// Inverses that elementary.h does not provide (n-th root as the inverse of
// x^n, asinh, acosh, atanh) come from a libm guess that is then PROVEN by the
// rigorous forward function: for an increasing f, a candidate L is a valid
// lower bound of f^-1(v) once F([L]) <= v; it is moved outward until it is,
// then tightened by bisection. The bounds are thus as good as the forward
// enclosures, and never wrong even if libm's inverse is off.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "sillage/interval/backward.h"
#include "sillage/interval/backward_detail.h"
#include "sillage/interval/elementary.h"

namespace sillage {

namespace {

using namespace detail;
using rounding::kInf;
using rounding::kMax;

double ulp_of(double g) {
  const double a = std::fabs(g);
  const double u = rounding::next_up(a) - a;
  return u > 0 ? u : std::numeric_limits<double>::denorm_min();
}

// Finite doubles as ordered integers, for bisection over the doubles.
std::int64_t ordinal(double x) {
  const auto b = std::bit_cast<std::int64_t>(x);
  return b >= 0 ? b : -(b & 0x7fffffffffffffff);
}

double from_ordinal(std::int64_t k) {
  return k >= 0 ? std::bit_cast<double>(k) : -std::bit_cast<double>(-k);
}

// Bound of f^-1(v) for f increasing on [dlo, dhi] with rigorous extension F.
// dir = -1: a candidate L with F([L]) <= v, so f^-1(v) >= L (a lower bound of
// the preimage of [v, +inf)); dir = +1: a U with F([U]) >= v. Candidates:
// guess + 1 ulp, guess, then guess moved outward by 1, 2, 4, ... ulps; once one
// is proven, bisection against the last failed one finds the tightest provable
// bound. The domain end is returned when nothing better is proven.
template <class F>
double inverse_bound(F f, double v, double guess, double dlo, double dhi, int dir) {
  const double dend = dir < 0 ? dlo : dhi;
  if ((dir < 0 ? v == -kInf : v == kInf) || guess != guess) return dend;
  auto proven = [&](double c) {
    const Interval fc = f(Interval(c));
    return dir < 0 ? fc.ub() <= v : fc.lb() >= v;
  };
  const double g = std::clamp(guess, std::max(dlo, -kMax), std::min(dhi, kMax));
  const double u = ulp_of(g);
  double failed = std::numeric_limits<double>::quiet_NaN();
  for (int i = -1; i < 2100; ++i) {
    double c;
    if (i == -1) c = dir < 0 ? rounding::next_up(g) : rounding::next_down(g);
    else if (i == 0) c = g;
    else c = dir < 0 ? rounding::sub_down(g, std::ldexp(u, i - 1)) : rounding::add_up(g, std::ldexp(u, i - 1));
    if (dir < 0 ? c <= dlo : c >= dhi) return dend;  // walked out of the domain
    if (c < dlo || c > dhi || !std::isfinite(c)) continue;
    if (!proven(c)) {
      failed = c;
      continue;
    }
    if (failed != failed) return c;
    std::int64_t good = ordinal(c), bad = ordinal(failed);
    while (good - bad > 1 || bad - good > 1) {
      const std::int64_t mid = bad + (good - bad) / 2;
      (proven(from_ordinal(mid)) ? good : bad) = mid;
    }
    return from_ordinal(good);
  }
  return dend;
}

// Enclosure of t^m (m >= 1) by binary powering with directed rounding: all
// factors are >= 0, so rounding each product down (up) bounds it from below
// (above). Self-contained so that the inverse does not rest on another bound.
Interval pow_point(double t, int m) {
  const double a = std::fabs(t);
  double lo = 1, hi = 1, blo = a, bhi = a;
  for (unsigned k = static_cast<unsigned>(m); k; k >>= 1) {
    if (k & 1) {
      lo = rounding::mul_down(lo, blo);
      hi = rounding::mul_up(hi, bhi);
    }
    if (k > 1) {
      blo = rounding::mul_down(blo, blo);
      bhi = rounding::mul_up(bhi, bhi);
    }
  }
  if (t < 0 && m % 2 == 1) return Interval::from_bounds_unchecked(-hi, -lo);
  return Interval::from_bounds_unchecked(lo, hi);
}

// Preimage of y by t -> t^m (m >= 1) on the reals (odd m) or on [0, inf) (even m).
Interval pow_preimage_half(const Interval& y, int m) {
  const bool even = m % 2 == 0;
  const Interval v = even ? y & Interval::pos_reals() : y;
  if (v.is_empty()) return Interval::empty();
  if (m == 1) return v;
  if (m == 2) return sqrt(v);
  auto f = [m](const Interval& t) { return pow_point(t.lb(), m); };
  auto guess = [m](double w) { return w < 0 ? -std::pow(-w, 1.0 / m) : std::pow(w, 1.0 / m); };
  const double dlo = even ? 0.0 : -kInf;
  return Interval(inverse_bound(f, v.lb(), guess(v.lb()), dlo, kInf, -1),
                  inverse_bound(f, v.ub(), guess(v.ub()), dlo, kInf, +1));
}

// x contracted by u = x^m (m >= 1).
Interval contract_pos_pow(const Interval& u, const Interval& x, int m) {
  const Interval p = pow_preimage_half(u, m);
  return m % 2 == 0 ? meet_symmetric(x, p) : x & p;
}

// x contracted by y = root(x, m) (m >= 1): x = y^m, with y >= 0 for even m.
Interval contract_pos_root(const Interval& y, const Interval& x, int m) {
  const bool even = m % 2 == 0;
  const Interval v = even ? y & Interval::pos_reals() : y;
  if (v.is_empty()) return Interval::empty();
  Interval r = x & pow(v, m);
  if (even) r &= Interval::pos_reals();
  return r;
}

}  // namespace

bool bwd_pow(const Interval& y, Interval& x, int n) {
  if (y.is_empty() || x.is_empty()) {
    x.set_empty();
    return false;
  }
  if (n == 0) {  // x^0 = 1 for every x
    if (!y.contains(1)) x.set_empty();
    return settle(x);
  }
  if (n > 0) {
    x = contract_pos_pow(y, x, n);
    return settle(x);
  }
  // x^n = (1/x)^|n| = y: 1/x lies in the preimage p of y by t^|n| (or in -p for
  // even |n|), so x in 1/p, taken piecewise. Rooting before inverting keeps
  // 1/y from overflowing.
  if (n == std::numeric_limits<int>::min()) throw Error("bwd_pow: exponent n out of range");
  const int m = -n;
  const auto [q1, q2] = div2(Interval(1.0), pow_preimage_half(y, m));
  x = m % 2 == 0 ? meet_symmetric(x, q1) : (x & q1) | (x & q2);
  if (x.lb() == 0 && x.ub() == 0) x.set_empty();  // 0^n is undefined for n < 0
  return settle(x);
}

bool bwd_root(const Interval& y, Interval& x, int n) {
  if (n == 0) throw Error("bwd_root: the root order n must be nonzero");
  if (n == std::numeric_limits<int>::min()) throw Error("bwd_root: root order n out of range");
  if (n > 0) {
    x = contract_pos_root(y, x, n);
    return settle(x);
  }
  // root(x, n) = 1 / root(x, |n|), nonzero.
  const auto [r1, r2] = div2(Interval(1.0), y);
  x = contract_pos_root(r1, x, -n) | contract_pos_root(r2, x, -n);
  if (x.lb() == 0 && x.ub() == 0) x.set_empty();
  return settle(x);
}

bool bwd_pow(const Interval& y_in, Interval& x, Interval& p) {
  // y = x^p = exp(p log x) for x > 0, and 0^p = 0 for p > 0.
  const Interval y = y_in & Interval::pos_reals();
  const Interval xp = x & Interval::pos_reals();
  const bool zero_ok = xp.contains(0) && y.contains(0) && p.ub() > 0;
  Interval x_pos = Interval::empty(), p_pos = Interval::empty();
  Interval lx = log(xp), pp = p;
  const Interval ly = log(y);
  if (!lx.is_empty() && !ly.is_empty() && bwd_mul(ly, pp, lx)) {
    x_pos = xp & exp(lx);
    p_pos = pp;
  }
  x = zero_ok ? x_pos | Interval(0.0) : x_pos;
  p = zero_ok ? p_pos | (p & Interval::pos_reals()) : p_pos;
  return settle(x, p);
}

bool bwd_exp(const Interval& y, Interval& x) {
  x &= log(y);
  return settle(x);
}

bool bwd_log(const Interval& y, Interval& x) {
  x &= exp(y);
  if (x.ub() <= 0) x.set_empty();  // log needs x > 0
  return settle(x);
}

bool bwd_sinh(const Interval& y, Interval& x) {
  if (y.is_empty()) x.set_empty();
  if (x.is_empty()) return false;
  auto f = [](const Interval& t) { return sinh(t); };
  const double lo = inverse_bound(f, y.lb(), std::asinh(y.lb()), -kInf, kInf, -1);
  const double hi = inverse_bound(f, y.ub(), std::asinh(y.ub()), -kInf, kInf, +1);
  x &= Interval(lo, hi);
  return settle(x);
}

bool bwd_cosh(const Interval& y, Interval& x) {
  const Interval v = y & Interval(1.0, kInf);
  if (v.is_empty()) x.set_empty();
  if (x.is_empty()) return false;
  auto f = [](const Interval& t) { return cosh(t); };
  const double lo = inverse_bound(f, v.lb(), std::acosh(v.lb()), 0.0, kInf, -1);
  const double hi = inverse_bound(f, v.ub(), std::acosh(v.ub()), 0.0, kInf, +1);
  x = meet_symmetric(x, Interval(lo, hi));
  return settle(x);
}

bool bwd_tanh(const Interval& y, Interval& x) {
  // tanh ranges over the open (-1, 1).
  if (y.is_empty() || y.lb() >= 1 || y.ub() <= -1) x.set_empty();
  if (x.is_empty()) return false;
  auto f = [](const Interval& t) { return tanh(t); };
  const double lo = y.lb() <= -1 ? -kInf : inverse_bound(f, y.lb(), std::atanh(y.lb()), -kInf, kInf, -1);
  const double hi = y.ub() >= 1 ? kInf : inverse_bound(f, y.ub(), std::atanh(y.ub()), -kInf, kInf, +1);
  x &= Interval(lo, hi);
  return settle(x);
}

bool bwd_asin(const Interval& y, Interval& x) {
  const double h = Interval::half_pi().ub();
  const Interval v = y & Interval(-h, h);
  x &= Interval(-1.0, 1.0);
  if (v.is_empty()) x.set_empty();
  x &= sin(v);
  return settle(x);
}

bool bwd_acos(const Interval& y, Interval& x) {
  const Interval v = y & Interval(0.0, Interval::pi().ub());
  x &= Interval(-1.0, 1.0);
  if (v.is_empty()) x.set_empty();
  x &= cos(v);
  return settle(x);
}

bool bwd_atan(const Interval& y, Interval& x) {
  // atan ranges over (-pi/2, pi/2); tan is increasing there.
  const Interval hp = Interval::half_pi();
  const Interval v = y & Interval(-hp.ub(), hp.ub());
  if (v.is_empty()) x.set_empty();
  if (x.is_empty()) return false;
  const double lo = v.lb() <= -hp.lb() ? -kInf : tan(Interval(v.lb())).lb();
  const double hi = v.ub() >= hp.lb() ? kInf : tan(Interval(v.ub())).ub();
  x &= Interval(lo, hi);
  return settle(x);
}

}  // namespace sillage

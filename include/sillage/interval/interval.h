#pragma once
// Interval: a closed connected subset [lb, ub] of the reals, possibly empty or
// unbounded (thesis 2.2.2). Bounds are binary64; every operation returns an
// interval guaranteed to contain the exact set result (outward rounding by
// AVX-512F static rounding modes or by error-free transformations, see
// docs/intervals.md). + - * / sqr sqrt are optimal: their bounds are the
// correctly rounded exact bounds.
//
// Set-based semantics (IEEE 1788): an operation acts on the part of its
// argument inside its domain; sqrt([-4,4]) = [0,2], 1/[0,0] = empty,
// [0,0] * [-inf,inf] = [0,0]. Infinite bounds are limits, never members.
#include <algorithm>
#include <cmath>
#include <concepts>
#include <iosfwd>
#include <limits>
#include <string>
#include <utility>

#include "sillage/error.h"
#include "sillage/interval/rounding.h"

namespace sillage {

class Interval {
 public:
  // The whole real line, the usual starting domain of a variable.
  Interval() : lo_(-rounding::kInf), hi_(rounding::kInf) {}
  // The degenerate interval {x}; x must be a finite number.
  Interval(double x);  // NOLINT: implicit, so that 2.0 * [x] reads naturally
  // The tightest interval around the integer n: {n} if n is a double, else
  // the two doubles around it (not every integer beyond 2^53 is a double).
  template <std::integral T>
  Interval(T n);  // NOLINT: implicit, as Interval(double)
  // [lb, ub]; NaN bounds, lb > ub and [inf, inf] / [-inf, -inf] are errors.
  Interval(double lb, double ub);

  static Interval empty() { return Interval(rounding::kInf, -rounding::kInf, Unchecked{}); }
  static Interval all_reals() { return Interval(); }
  static Interval pos_reals() { return {0.0, rounding::kInf, Unchecked{}}; }
  static Interval neg_reals() { return {-rounding::kInf, 0.0, Unchecked{}}; }
  static Interval pi();
  static Interval half_pi();
  static Interval two_pi();
  // Trusted construction from bounds already known to be valid (no check).
  static Interval from_bounds_unchecked(double lb, double ub) { return {lb, ub, Unchecked{}}; }

  double lb() const { return lo_; }
  double ub() const { return hi_; }

  // ---- predicates ----
  bool is_empty() const { return !(lo_ <= hi_); }
  bool is_degenerate() const { return lo_ == hi_; }
  bool is_unbounded() const { return !is_empty() && (lo_ == -rounding::kInf || hi_ == rounding::kInf); }
  bool is_bounded() const { return !is_unbounded(); }
  bool is_all_reals() const { return lo_ == -rounding::kInf && hi_ == rounding::kInf; }
  bool contains(double x) const { return lo_ <= x && x <= hi_ && std::isfinite(x); }
  bool interior_contains(double x) const { return lo_ < x && x < hi_; }
  bool is_subset(const Interval& y) const { return is_empty() || (y.lo_ <= lo_ && hi_ <= y.hi_); }
  bool is_strict_subset(const Interval& y) const { return is_subset(y) && *this != y; }
  // Subset of the interior of y (IEEE 1788 "interior"; infinite bounds count as open).
  bool is_interior_subset(const Interval& y) const;
  bool is_superset(const Interval& y) const { return y.is_subset(*this); }
  bool intersects(const Interval& y) const { return std::max(lo_, y.lo_) <= std::min(hi_, y.hi_); }
  bool is_disjoint(const Interval& y) const { return !intersects(y); }
  bool operator==(const Interval& y) const {
    return (is_empty() && y.is_empty()) || (lo_ == y.lo_ && hi_ == y.hi_);
  }
  bool operator!=(const Interval& y) const { return !(*this == y); }

  // ---- numeric functions (IEEE 1788 conventions for empty and unbounded) ----
  double mid() const;    // midpoint rounded to nearest; 0 for the whole line; NaN if empty
  double diam() const;   // ub - lb rounded up; inf if unbounded; NaN if empty
  double width() const { return diam(); }  // the thesis' name (2.4)
  double rad() const;    // smallest r with [mid - r, mid + r] containing *this
  double mag() const;    // max |x|
  double mig() const;    // min |x|
  // Volume of the interval seen as a 1-D box: its diam, 0 if empty.
  double volume() const { return is_empty() ? 0.0 : diam(); }

  // ---- set operations ----
  // Intersection (2.6), (2.18) and hull of the union (2.8), (2.17); inline:
  // contractors call them on every slice.
  Interval operator&(const Interval& y) const {
    const double l = std::max(lo_, y.lo_), u = std::min(hi_, y.hi_);
    if (!(l <= u)) return empty();
    return {l, u, Unchecked{}};
  }
  Interval operator|(const Interval& y) const {
    if (is_empty()) return y;
    if (y.is_empty()) return *this;
    return {std::min(lo_, y.lo_), std::max(hi_, y.hi_), Unchecked{}};
  }
  Interval& operator&=(const Interval& y) { return *this = *this & y; }
  Interval& operator|=(const Interval& y) { return *this = *this | y; }
  // Split at lb + ratio * diam (at 0 or a finite point if unbounded).
  std::pair<Interval, Interval> bisect(double ratio = 0.5) const;
  // [lb - r, ub + r], outward rounded; r >= 0.
  Interval inflate(double r) const;
  void set_empty() { *this = empty(); }

  // ---- arithmetic ----
  Interval operator-() const { return {0.0 - hi_, 0.0 - lo_, Unchecked{}}; }  // 0 - x: no -0 bound
  Interval operator+() const { return *this; }
  Interval& operator+=(const Interval& y);
  Interval& operator-=(const Interval& y);
  Interval& operator*=(const Interval& y);
  Interval& operator/=(const Interval& y);

  std::string str() const;

 private:
  struct Unchecked {};
  Interval(double lb, double ub, Unchecked) : lo_(lb), hi_(ub) {}

  double lo_, hi_;
};

namespace detail {
// The errors of the constructors below (out of line: the checks inline, the messages cold).
[[noreturn]] void throw_bad_point(double x);
[[noreturn]] void throw_bad_bounds(double lb, double ub);
}  // namespace detail

inline Interval::Interval(double x) : lo_(x + 0.0), hi_(x + 0.0) {  // + 0.0: no -0 bound
  if (!std::isfinite(x)) [[unlikely]] detail::throw_bad_point(x);
}

inline Interval::Interval(double lb, double ub) : lo_(lb == 0 ? 0.0 : lb), hi_(ub == 0 ? 0.0 : ub) {
  // One zero ([-0, x] and [+0, x] are the same set); NaN, inverted and [±inf, ±inf] rejected.
  if (!(lb <= ub) || lb == rounding::kInf || ub == -rounding::kInf) [[unlikely]] detail::throw_bad_bounds(lb, ub);
}

template <std::integral T>
Interval::Interval(T n) : Interval(static_cast<double>(n)) {
  if constexpr (std::numeric_limits<T>::digits > 53) {
    const double d = lo_;  // n rounded to nearest
    if (d >= std::ldexp(1.0, std::numeric_limits<T>::digits)) {  // beyond T: n < d
      lo_ = rounding::next_down(d);
    } else if (static_cast<T>(d) < n) {
      hi_ = rounding::next_up(d);
    } else if (static_cast<T>(d) > n) {
      lo_ = rounding::next_down(d);
    }
  }
}

// ---- arithmetic (2.13)-(2.20) ----
// Defined out of line (interval_arith.cpp), without a branch on the data: the
// rounding path, AVX-512F or portable, is chosen once per process.

// {a + b : a in x, b in y}.
Interval operator+(const Interval& x, const Interval& y);
// {a - b : a in x, b in y}.
Interval operator-(const Interval& x, const Interval& y);
// {a * b : a in x, b in y}; [0, 0] times anything non-empty is [0, 0].
Interval operator*(const Interval& x, const Interval& y);
// Division: the hull of the real quotient set, (2.19)-(2.20).
Interval operator/(const Interval& x, const Interval& y);

inline Interval& Interval::operator+=(const Interval& y) { return *this = *this + y; }
inline Interval& Interval::operator-=(const Interval& y) { return *this = *this - y; }
inline Interval& Interval::operator*=(const Interval& y) { return *this = *this * y; }
inline Interval& Interval::operator/=(const Interval& y) { return *this = *this / y; }

// Relational (extended) division: the set {z : z * b in [c] for some b in [b]}
// as up to two disjoint intervals, lower piece first (the second is empty when
// one suffices; IEEE 1788 mulRevToPair). Unlike operator/ it keeps both pieces:
// div2([1,2], [-1,1]) = ([-inf,-1], [1,inf]); and 0 in [c] and in [b] gives
// the whole line (z * 0 = 0 for every z).
std::pair<Interval, Interval> div2(const Interval& c, const Interval& b);

// x^2, tighter than x * x (the two factors are the same variable).
Interval sqr(const Interval& x);
// Square root, on the part of x above 0 (empty if x < 0).
Interval sqrt(const Interval& x);
// Absolute value {|v| : v in x}.
Interval abs(const Interval& x);
// {min(a, b) : a in x, b in y}.
Interval min(const Interval& x, const Interval& y);
// {max(a, b) : a in x, b in y}.
Interval max(const Interval& x, const Interval& y);
// Image of the sign function: a subset of {-1, 0, 1} hulled.
Interval sign(const Interval& x);

// Free-function spellings of the set operations (same as & and |).
inline Interval intersection(const Interval& x, const Interval& y) { return x & y; }
// The smallest interval containing x and y.
inline Interval hull(const Interval& x, const Interval& y) { return x | y; }

std::ostream& operator<<(std::ostream& os, const Interval& x);

}  // namespace sillage

#pragma once
// The MPFR test oracle: correctly rounded reference values, deterministic
// adversarial point generators, and the checker that compares an interval
// result with the outward rounding of the exact image.
//
// A reference value is computed once at 53 bits in round-to-nearest, inside
// binary64's exponent range (subnormals emulated with mpfr_subnormalize); the
// ternary value then tells on which side of the exact value it lies, which
// gives both directed roundings from one evaluation.
#include <gtest/gtest.h>
#include <mpfr.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "kit/close_bounds.h"
#include "sillage/interval/interval.h"

namespace oracle {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kMax = std::numeric_limits<double>::max();
inline constexpr double kTiny = std::numeric_limits<double>::denorm_min();

// SILLAGE_QUICK=1 (sanitizer runs) shrinks every sweep tenfold.
inline bool quick() {
  const char* q = std::getenv("SILLAGE_QUICK");
  return q != nullptr && q[0] == '1';
}
inline std::size_t scaled(std::size_t n) { return quick() ? n / 10 : n; }

// Sets MPFR's exponent range to binary64's while alive.
class DoubleRange {
 public:
  DoubleRange() : emin_(mpfr_get_emin()), emax_(mpfr_get_emax()) {
    mpfr_set_emin(-1073);
    mpfr_set_emax(1024);
  }
  ~DoubleRange() {
    mpfr_set_emin(emin_);
    mpfr_set_emax(emax_);
  }
  DoubleRange(const DoubleRange&) = delete;
  DoubleRange& operator=(const DoubleRange&) = delete;

 private:
  mpfr_exp_t emin_, emax_;
};

// An MPFR number (RAII).
class Real {
 public:
  explicit Real(mpfr_prec_t prec = 53) { mpfr_init2(v_, prec); }
  Real(double x, mpfr_prec_t prec) {
    mpfr_init2(v_, prec);
    mpfr_set_d(v_, x, MPFR_RNDN);  // exact: prec >= 53
  }
  ~Real() { mpfr_clear(v_); }
  Real(const Real&) = delete;
  Real& operator=(const Real&) = delete;
  mpfr_ptr get() { return v_; }
  operator mpfr_ptr() { return v_; }  // NOLINT: reads like mpfr_t

 private:
  mpfr_t v_;
};

// The two directed roundings of an exact value (equal if it is a double).
// NaN marks a value outside the function's domain.
struct Bounds {
  double down = 0, up = 0;
  bool valid() const { return down == down; }
};

inline double next_up(double x) { return sillage::rounding::next_up(x); }
inline double next_down(double x) { return sillage::rounding::next_down(x); }

// Runs f(result, MPFR_RNDN) at 53 bits (needs a live DoubleRange) and returns
// RNDD and RNDU of the exact value.
template <class F>
Bounds rounded(F&& f) {
  Real r(53);
  int t = f(r.get(), MPFR_RNDN);
  t = mpfr_subnormalize(r.get(), t, MPFR_RNDN);
  const double v = mpfr_get_d(r.get(), MPFR_RNDN);  // exact
  if (v != v) return {v, v};
  if (t == 0) return {v, v};
  if (t > 0) return {next_down(v), v};
  return {v, next_up(v)};
}

// f(x) for a one-argument MPFR function.
inline Bounds eval1(int (*f)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t), double x) {
  Real xr(x, 53);
  return rounded([&](mpfr_ptr r, mpfr_rnd_t rnd) { return f(r, xr, rnd); });
}

inline Bounds eval2(int (*f)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t), double x, double y) {
  Real xr(x, 53), yr(y, 53);
  return rounded([&](mpfr_ptr r, mpfr_rnd_t rnd) { return f(r, xr, yr, rnd); });
}

using sillage::test::ulps_between;

inline std::string hex(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}
inline std::string hex(const sillage::Interval& x) {
  if (x.is_empty()) return "[empty]";
  return std::string("[") + hex(x.lb()) + ", " + hex(x.ub()) + "]";
}

// The outward rounded exact image of one case.
struct Expected {
  bool empty = false;
  double lo = 0, hi = 0;
  static Expected none() { return {true, 0, 0}; }
  static Expected of(double lo, double hi) { return {false, lo, hi}; }
};

// Collects the outcome of a sweep over one operation.
class Checker {
 public:
  Checker(std::string name, int max_ulps) : name_(std::move(name)), max_ulps_(max_ulps) {}

  // input: a description of the case, built only when it fails.
  template <class Describe>
  void check(const sillage::Interval& ours, const Expected& e, Describe&& input) {
    ++cases_;
    std::string why;
    if (e.empty) {
      if (!ours.is_empty()) why = "expected empty";
    } else if (ours.is_empty()) {
      why = "unexpected empty";
    } else if (!(ours.lb() <= e.lo && ours.ub() >= e.hi)) {
      why = "CONTAINMENT: exact image not inside";
    } else {
      const std::uint64_t dl = ulps_between(ours.lb(), e.lo), du = ulps_between(ours.ub(), e.hi);
      worst_ = std::max({worst_, dl, du});
      if (dl > static_cast<std::uint64_t>(max_ulps_) || du > static_cast<std::uint64_t>(max_ulps_)) {
        why = "bounds " + std::to_string(dl) + " / " + std::to_string(du) + " ulps from the optimal ones";
      }
    }
    if (!why.empty()) {
      if (++failures_ <= 8) {
        log_ += "  " + name_ + input() + " = " + hex(ours) + ", optimal [" + hex(e.lo) + ", " + hex(e.hi) + "]" +
                (e.empty ? " (empty)" : "") + ": " + why + "\n";
      }
    }
  }

  std::size_t cases() const { return cases_; }
  std::size_t failures() const { return failures_; }
  std::uint64_t worst_ulps() const { return worst_; }
  const std::string& log() const { return log_; }
  std::string summary() const {
    return name_ + ": " + std::to_string(cases_) + " cases, max distance to optimal " + std::to_string(worst_) +
           " ulp(s), " + std::to_string(failures_) + " failure(s)";
  }

 private:
  std::string name_;
  int max_ulps_;
  std::size_t cases_ = 0, failures_ = 0;
  std::uint64_t worst_ = 0;
  std::string log_;
};

// Deterministic random source (own mappings, so results do not depend on the
// standard library's distributions).
class Gen {
 public:
  explicit Gen(std::uint64_t seed) : rng_(seed) {}
  std::uint64_t bits() { return rng_(); }
  // Uniform in [0, 1).
  double unit() { return static_cast<double>(rng_() >> 11) * 0x1p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  std::int64_t integer(std::int64_t lo, std::int64_t hi) {  // inclusive
    return lo + static_cast<std::int64_t>(rng_() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  bool coin() { return rng_() & 1; }
  double sign() { return coin() ? 1.0 : -1.0; }
  // Any finite double, every exponent equally likely (subnormals included).
  double any_finite() {
    for (;;) {
      const double x = std::bit_cast<double>(rng_());
      if (std::isfinite(x)) return x;
    }
  }
  // Random sign, magnitude 2^e * [1, 2) with e uniform in [emin, emax].
  double log_uniform(int emin, int emax) {
    return sign() * std::ldexp(1.0 + unit(), static_cast<int>(integer(emin, emax)));
  }
  // x moved by up to k ulps either way.
  double near(double x, int k) {
    std::int64_t s = integer(-k, k);
    for (; s > 0; --s) x = next_up(x);
    for (; s < 0; ++s) x = next_down(x);
    return x;
  }

 private:
  std::mt19937_64 rng_;
};

// Sorted distinct points, -0 folded into +0, optionally with +-inf at the ends.
inline std::vector<double> finish_pool(std::vector<double> p, bool with_infinities) {
  for (double& x : p) x += 0.0;
  if (with_infinities) {
    p.push_back(-kInf);
    p.push_back(kInf);
  }
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  return p;
}

// Doubles every test pool contains.
inline void add_specials(std::vector<double>& p) {
  for (double v : {0.0, 1.0, 2.0, 0.5, 3.0, 10.0, 1e-300, 1e300, kMax, kTiny, 0x1p-1022, 0x1p-1023, 0x1p1023,
                   1.5, 0.1, 100.0, 1e10, 1e-10}) {
    p.push_back(v);
    p.push_back(-v);
    p.push_back(next_up(v));
    p.push_back(next_down(v));
    p.push_back(-next_up(v));
    p.push_back(-next_down(v));
  }
}

// Index pairs (i <= j) into a sorted pool: every point alone, then random
// pairs, near neighbours (ulp-near intervals) and medium spans.
template <class F>
void for_each_pair(const std::vector<double>& pool, std::size_t cases, Gen& g, F&& f) {
  const auto n = static_cast<std::int64_t>(pool.size());
  std::size_t done = 0;
  for (std::int64_t i = 0; i < n && done < cases; ++i) {
    if (std::isinf(pool[i])) continue;
    f(i, i);
    ++done;
  }
  while (done < cases) {
    std::int64_t i = g.integer(0, n - 1), j;
    switch (done % 6) {
      case 0: case 1: j = g.integer(0, n - 1); break;
      case 2: case 3: j = i + g.integer(0, 3); break;
      case 4: j = i + g.integer(0, std::max<std::int64_t>(n / 200, 1)); break;
      default: j = g.coin() ? n - 1 : 0; break;  // infinite or extreme end
    }
    j = std::clamp<std::int64_t>(j, 0, n - 1);
    if (i > j) std::swap(i, j);
    if (pool[i] == pool[j] && std::isinf(pool[i])) continue;
    f(i, j);
    ++done;
  }
}

// A pool of points with the rounded values of f at each.
struct Table {
  std::vector<double> x;
  std::vector<Bounds> f;
  std::size_t size() const { return x.size(); }
};

template <class F>
Table tabulate(std::vector<double> pool, F&& f) {
  Table t;
  t.x = std::move(pool);
  t.f.reserve(t.x.size());
  for (double v : t.x) t.f.push_back(f(v));
  return t;
}

// Prints the sweep's summary (the figures the report quotes) and fails the
// test on any failed case.
inline void expect_ok(const Checker& c) {
  std::printf("[mpfr] %s\n", c.summary().c_str());
  EXPECT_EQ(c.failures(), 0u) << c.summary() << "\n" << c.log();
}

}  // namespace oracle

// Property tests of every backward projection: on random intervals, the
// contracted arguments are subsets of the inputs, and every sampled tuple
// whose image is PROVEN (by MPFR at 256 bits, both roundings) to lie in [y]
// is kept. Images are often chosen around a sampled tuple, so that true
// solutions are plentiful.
#include <gtest/gtest.h>
#include <mpfr.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "sillage/interval/backward.h"

using namespace sillage;

namespace {

constexpr double kInf = INFINITY;

// Exact image f(args) enclosed by [lo, hi] at 256 bits; NaN when outside the domain.
using RealFn = std::function<void(const std::vector<double>&, mpfr_t, mpfr_rnd_t)>;
using BwdFn = std::function<bool(const Interval&, std::vector<Interval>&)>;

class Mp {
 public:
  Mp() { mpfr_init2(v_, 256); }
  ~Mp() { mpfr_clear(v_); }
  Mp(const Mp&) = delete;
  Mp& operator=(const Mp&) = delete;
  mpfr_ptr get() { return v_; }

 private:
  mpfr_t v_;
};

// True when f(args) is defined and certainly inside y.
bool certainly_in(const RealFn& f, const std::vector<double>& args, const Interval& y) {
  if (y.is_empty()) return false;
  Mp lo, hi;
  f(args, lo.get(), MPFR_RNDD);
  f(args, hi.get(), MPFR_RNDU);
  if (mpfr_nan_p(lo.get()) || mpfr_nan_p(hi.get())) return false;
  return mpfr_cmp_d(lo.get(), y.lb()) >= 0 && mpfr_cmp_d(hi.get(), y.ub()) <= 0 && mpfr_number_p(lo.get()) &&
         mpfr_number_p(hi.get());
}

double nearest(const RealFn& f, const std::vector<double>& args) {
  Mp v;
  f(args, v.get(), MPFR_RNDN);
  return mpfr_get_d(v.get(), MPFR_RNDN);
}

struct Gen {
  std::mt19937_64 rng{20170714};
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); }

  double value(double scale) {
    switch (pick(10)) {
      case 0: return std::round(uniform(-scale, scale));
      case 1: return 0.0;
      case 2: return (pick(2) ? 1 : -1) * std::pow(10.0, uniform(-320, 308));  // tiny or huge
      default: return uniform(-scale, scale);
    }
  }

  Interval interval(double scale) {
    const int kind = pick(20);
    if (kind == 0) return Interval::all_reals();
    if (kind == 1) return Interval(value(scale), kInf);
    if (kind == 2) return Interval(-kInf, value(scale));
    double a = value(scale), b = kind == 3 ? a : value(scale);
    if (a > b) std::swap(a, b);
    return Interval(a, b);
  }

  // A point of the (nonempty) interval x: an end point or a random inner point.
  double sample(const Interval& x, double scale) {
    if (x.is_bounded() && pick(3) == 0) return pick(2) ? x.lb() : x.ub();  // end points, even far ones
    const double lo = std::max(x.lb(), -4 * scale - 1), hi = std::min(x.ub(), 4 * scale + 1);
    if (lo > hi) return x.ub() < lo ? x.ub() : x.lb();  // x lies beyond the window: its nearer end
    switch (pick(4)) {
      case 0: return lo;
      case 1: return hi;
      default: return lo + (hi - lo) * uniform(0, 1);
    }
  }

  // An image: often a small or degenerate interval around f(sample), else random.
  Interval image(const RealFn& f, const std::vector<double>& pt, double yscale) {
    const double v = nearest(f, pt);
    if (!std::isfinite(v) || pick(4) == 0) return interval(yscale);
    const double w = std::fabs(v) + 1;
    switch (pick(4)) {
      case 0: return Interval(v);
      case 1: return Interval(v - w * 1e-12 * uniform(0, 1), v + w * 1e-12 * uniform(0, 1));
      default: return Interval(v - w * uniform(0, 1), v + w * uniform(0, 1));
    }
  }
};

struct Case {
  std::string name;
  int arity;
  double scale, yscale;
  RealFn f;
  BwdFn bwd;
};

void run_property(const Case& c, int trials = 3000) {
  Gen g;
  g.rng.seed(std::hash<std::string>{}(c.name));
  int kept_checks = 0;
  for (int t = 0; t < trials; ++t) {
    std::vector<Interval> xs;
    for (int i = 0; i < c.arity; ++i) xs.push_back(g.interval(c.scale));
    // Samples: a grid of points per argument (all combinations are tried).
    std::vector<std::vector<double>> pts(c.arity);
    for (int i = 0; i < c.arity; ++i)
      for (int k = 0; k < 4; ++k) pts[i].push_back(g.sample(xs[i], c.scale));
    std::vector<double> first(c.arity);
    for (int i = 0; i < c.arity; ++i) first[i] = pts[i][0];
    const Interval y = g.image(c.f, first, c.yscale);
    std::vector<Interval> out = xs;
    const bool ok = c.bwd(y, out);
    bool any_empty = false;
    for (int i = 0; i < c.arity; ++i) {
      ASSERT_TRUE(out[i].is_subset(xs[i])) << c.name << ": argument " << i << " grew from " << xs[i] << " to "
                                           << out[i] << " (y = " << y << ")";
      any_empty |= out[i].is_empty();
    }
    ASSERT_EQ(ok, !any_empty) << c.name << ": return value disagrees with emptiness";
    if (any_empty) {
      for (int i = 0; i < c.arity; ++i) ASSERT_TRUE(out[i].is_empty()) << c.name << ": not all arguments emptied";
    }
    std::vector<double> pt(c.arity);
    const int combos = c.arity == 1 ? 4 : 16;
    for (int k = 0; k < combos; ++k) {
      for (int i = 0; i < c.arity; ++i) pt[i] = pts[i][i == 0 ? k % 4 : (k / 4) % 4];
      if (!certainly_in(c.f, pt, y)) continue;
      ++kept_checks;
      for (int i = 0; i < c.arity; ++i) {
        ASSERT_TRUE(out[i].contains(pt[i]))
            << c.name << ": removed the solution " << pt[i] << " of argument " << i << "; y = " << y
            << ", inputs " << xs[0] << " " << (c.arity > 1 ? xs[1] : Interval()) << ", result " << out[i];
      }
    }
  }
  EXPECT_GT(kept_checks, trials / 4) << c.name << ": too few true solutions were sampled";
}

// Helpers to state the real functions with MPFR.
RealFn mp1(int (*fn)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t)) {
  return [fn](const std::vector<double>& a, mpfr_t r, mpfr_rnd_t rnd) {
    Mp x;
    mpfr_set_d(x.get(), a[0], MPFR_RNDN);
    fn(r, x.get(), rnd);
  };
}

RealFn mp2(int (*fn)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t)) {
  return [fn](const std::vector<double>& a, mpfr_t r, mpfr_rnd_t rnd) {
    Mp x, y;
    mpfr_set_d(x.get(), a[0], MPFR_RNDN);
    mpfr_set_d(y.get(), a[1], MPFR_RNDN);
    fn(r, x.get(), y.get(), rnd);
  };
}

// Functions exact in binary64 (no rounding at all).
RealFn exact1(double (*fn)(double)) {
  return [fn](const std::vector<double>& a, mpfr_t r, mpfr_rnd_t) { mpfr_set_d(r, fn(a[0]), MPFR_RNDN); };
}

BwdFn b1(bool (*fn)(const Interval&, Interval&)) {
  return [fn](const Interval& y, std::vector<Interval>& x) { return fn(y, x[0]); };
}

BwdFn b2(bool (*fn)(const Interval&, Interval&, Interval&)) {
  return [fn](const Interval& y, std::vector<Interval>& x) { return fn(y, x[0], x[1]); };
}

}  // namespace

TEST(BackwardProperty, Arithmetic) {
  run_property({"add", 2, 10, 10, mp2(mpfr_add), b2(bwd_add)});
  run_property({"sub", 2, 10, 10, mp2(mpfr_sub), b2(bwd_sub)});
  run_property({"mul", 2, 10, 20, mp2(mpfr_mul), b2(bwd_mul)});
  run_property({"div", 2, 10, 5, mp2(mpfr_div), b2(bwd_div)});
  run_property({"neg", 1, 10, 10, mp1(mpfr_neg), b1(bwd_neg)});
  run_property({"sqr", 1, 10, 30, mp1(mpfr_sqr), b1(bwd_sqr)});
  run_property({"sqrt", 1, 10, 3, mp1(mpfr_sqrt), b1(bwd_sqrt)});
}

TEST(BackwardProperty, PiecewiseFunctions) {
  run_property({"abs", 1, 10, 10, mp1(mpfr_abs), b1(bwd_abs)});
  run_property({"min", 2, 10, 10, mp2(mpfr_min), b2(bwd_min)});
  run_property({"max", 2, 10, 10, mp2(mpfr_max), b2(bwd_max)});
  run_property({"sign", 1, 3, 1,
                exact1([](double v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); }), b1(bwd_sign)});
}

TEST(BackwardProperty, ExpLogHyperbolic) {
  run_property({"exp", 1, 20, 100, mp1(mpfr_exp), b1(bwd_exp)});
  run_property({"log", 1, 20, 3, mp1(mpfr_log), b1(bwd_log)});
  run_property({"sinh", 1, 10, 100, mp1(mpfr_sinh), b1(bwd_sinh)});
  run_property({"cosh", 1, 10, 100, mp1(mpfr_cosh), b1(bwd_cosh)});
  run_property({"tanh", 1, 5, 1, mp1(mpfr_tanh), b1(bwd_tanh)});
}

TEST(BackwardProperty, Trigonometric) {
  run_property({"sin", 1, 20, 1, mp1(mpfr_sin), b1(bwd_sin)});
  run_property({"cos", 1, 20, 1, mp1(mpfr_cos), b1(bwd_cos)});
  run_property({"tan", 1, 20, 5, mp1(mpfr_tan), b1(bwd_tan)});
  run_property({"sin_far", 1, 1e7, 1, mp1(mpfr_sin), b1(bwd_sin)}, 500);
  run_property({"asin", 1, 1.2, 2, mp1(mpfr_asin), b1(bwd_asin)});
  run_property({"acos", 1, 1.2, 3, mp1(mpfr_acos), b1(bwd_acos)});
  run_property({"atan", 1, 20, 2, mp1(mpfr_atan), b1(bwd_atan)});
  // theta = atan2(y, x), the arguments in the order of bwd_atan2(theta, y, x);
  // undefined at the origin, and 0 is unsigned (atan2(0, x < 0) = pi).
  RealFn atan2_fn = [](const std::vector<double>& a, mpfr_t r, mpfr_rnd_t rnd) {
    if (a[0] == 0 && a[1] == 0) {
      mpfr_set_nan(r);
      return;
    }
    Mp y, x;
    mpfr_set_d(y.get(), a[0] + 0.0, MPFR_RNDN);
    mpfr_set_d(x.get(), a[1] + 0.0, MPFR_RNDN);
    mpfr_atan2(r, y.get(), x.get(), rnd);
  };
  run_property({"atan2", 2, 5, 3, atan2_fn, b2(bwd_atan2)});
}

TEST(BackwardProperty, Powers) {
  for (int n : {-4, -3, -2, -1, 0, 1, 2, 3, 4, 5}) {
    RealFn f = [n](const std::vector<double>& a, mpfr_t r, mpfr_rnd_t rnd) {
      Mp x;
      mpfr_set_d(x.get(), a[0], MPFR_RNDN);
      if (n < 0 && a[0] == 0) {
        mpfr_set_nan(r);  // 0^n undefined for n < 0
        return;
      }
      mpfr_pow_si(r, x.get(), n, rnd);
    };
    BwdFn b = [n](const Interval& y, std::vector<Interval>& x) { return bwd_pow(y, x[0], n); };
    run_property({"pow" + std::to_string(n), 1, 4, 50, f, b}, 1500);
  }
  for (int n : {-3, -2, 2, 3, 4}) {
    RealFn f = [n](const std::vector<double>& a, mpfr_t r, mpfr_rnd_t rnd) {
      Mp x;
      mpfr_set_d(x.get(), a[0], MPFR_RNDN);
      const unsigned long m = static_cast<unsigned long>(std::abs(n));
      if ((m % 2 == 0 && a[0] < 0) || (n < 0 && a[0] == 0)) {
        mpfr_set_nan(r);
        return;
      }
      if (n > 0) {
        mpfr_rootn_ui(r, x.get(), m, rnd);
      } else {  // 1 / root: round the root the other way
        Mp q;
        mpfr_rootn_ui(q.get(), x.get(), m, rnd == MPFR_RNDD ? MPFR_RNDU : (rnd == MPFR_RNDU ? MPFR_RNDD : rnd));
        mpfr_ui_div(r, 1, q.get(), rnd);
      }
    };
    BwdFn b = [n](const Interval& y, std::vector<Interval>& x) { return bwd_root(y, x[0], n); };
    run_property({"root" + std::to_string(n), 1, 20, 5, f, b}, 1500);
  }
  // Real exponent: y = x^p with x > 0, or x = 0 and p > 0.
  RealFn f = [](const std::vector<double>& a, mpfr_t r, mpfr_rnd_t rnd) {
    if (a[0] < 0 || (a[0] == 0 && a[1] <= 0)) {
      mpfr_set_nan(r);
      return;
    }
    Mp x, p;
    mpfr_set_d(x.get(), a[0], MPFR_RNDN);
    mpfr_set_d(p.get(), a[1], MPFR_RNDN);
    mpfr_pow(r, x.get(), p.get(), rnd);
  };
  run_property({"pow_real", 2, 4, 20, f, b2([](const Interval& y, Interval& x, Interval& p) {
                  return bwd_pow(y, x, p);
                })});
}

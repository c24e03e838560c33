// pow(x, n), root(x, n), pow(x, y) and atan2(y, x) against MPFR: containment
// of the exact image, each bound within 4 ulps of the optimal one.
//
// pow(x, n) and root(x, n) use one pool per n. pow(x, y) and atan2(y, x) use
// two pools and a full table of the function on the grid; the image of a box
// is then read at its corners (both functions are monotone in each argument
// on every part of the box where the sign of that monotony is fixed).
#include <gtest/gtest.h>

#include "mpfr_oracle.h"
#include "sillage/interval/elementary.h"

using namespace oracle;
using sillage::Interval;

namespace {

constexpr int kMaxUlps = 4;

// Points for x^n: every scale, the overflow and underflow thresholds of x^n,
// exact cases (small integers, dyadics), near 1 and near 0.
std::vector<double> power_pool(Gen& g, int n, std::size_t size) {
  std::vector<double> p;
  add_specials(p);
  const double an = std::fabs(static_cast<double>(n));
  const double over = std::pow(kMax, 1 / an), under = std::pow(0x1p-1074, 1 / an);
  for (std::size_t k = 0; k < size; ++k) {
    double v;
    switch (k % 9) {
      case 0: v = g.any_finite(); break;
      case 1: v = g.near(over, 50); break;
      case 2: v = g.near(under, 50); break;
      case 3: v = static_cast<double>(g.integer(-40, 40)); break;
      case 4: v = std::ldexp(static_cast<double>(g.integer(-64, 64)), static_cast<int>(g.integer(-8, 0))); break;
      case 5: v = g.near(1.0, 30); break;
      case 6: v = g.log_uniform(-60, 60); break;
      case 7: v = g.uniform(-3, 3); break;
      default: v = g.log_uniform(-1074, 1023); break;
    }
    p.push_back(g.coin() ? v : -v);
  }
  return finish_pool(std::move(p), true);
}

Bounds pown(double x, long n) {
  Real xr(x, 53);
  return rounded([&](mpfr_ptr r, mpfr_rnd_t rnd) { return mpfr_pow_si(r, xr, n, rnd); });
}

Bounds rootn(double x, long n) {
  Real xr(x, 53);
  return rounded([&](mpfr_ptr r, mpfr_rnd_t rnd) { return mpfr_rootn_si(r, xr, n, rnd); });
}

// Image of x^n (n != 0) over [x_i, x_j], from the values at the end points.
Expected exact_pown(const Table& t, std::int64_t i, std::int64_t j, int n) {
  const double a = t.x[i], b = t.x[j];
  const bool even = n % 2 == 0;
  if (n > 0) {
    if (!even || a >= 0) return Expected::of(even ? std::min(t.f[i].down, t.f[j].down) : t.f[i].down, t.f[j].up);
    if (b <= 0) return Expected::of(t.f[j].down, t.f[i].up);
    return Expected::of(0.0, std::max(t.f[i].up, t.f[j].up));  // 0 inside
  }
  if (a == 0 && b == 0) return Expected::none();
  if (a < 0 && b > 0) {  // the pole inside
    if (!even) return Expected::of(-kInf, kInf);
    return Expected::of(std::min(t.f[i].down, t.f[j].down), kInf);
  }
  if (a == 0) return Expected::of(t.f[j].down, kInf);                 // (0, b]
  if (b == 0) return Expected::of(even ? t.f[i].down : -kInf, even ? kInf : t.f[i].up);  // [a, 0)
  if (even && b < 0) return Expected::of(t.f[i].down, t.f[j].up);  // x^n increasing for x < 0
  return Expected::of(t.f[j].down, t.f[i].up);                       // decreasing
}

// Image of the real n-th root (n != 0; set-based for even n and negative n).
Expected exact_root(const Table& t, std::int64_t i, std::int64_t j, int n) {
  const double a = t.x[i], b = t.x[j];
  const bool even = n % 2 == 0;
  if (even && b < 0) return Expected::none();
  if (n > 0) {
    if (even && a < 0) return Expected::of(0.0, t.f[j].up);
    return Expected::of(t.f[i].down, t.f[j].up);
  }
  if (b <= 0 && (even || a == 0)) return Expected::none();  // even: x > 0 only; {0}: pole
  if (even) return Expected::of(t.f[j].down, a <= 0 ? kInf : t.f[i].up);
  if (a < 0 && b > 0) return Expected::of(-kInf, kInf);
  if (a == 0) return Expected::of(t.f[j].down, kInf);
  if (b == 0) return Expected::of(-kInf, t.f[i].up);
  return Expected::of(t.f[j].down, t.f[i].up);  // decreasing
}

}  // namespace

TEST(MpfrPower, PowInt) {
  DoubleRange range;
  Gen g(0x90e0001);
  const std::vector<int> exponents = {3, 4, 5, 7, 8, 10, 17, 60, -1, -2, -3, -4, -7};
  std::size_t cases = 0;
  Checker c("pow(x, n)", kMaxUlps);
  for (int n : exponents) {
    const Table t = tabulate(power_pool(g, n, scaled(20'000)), [&](double x) { return pown(x, n); });
    for_each_pair(t.x, scaled(80'000), g, [&](std::int64_t i, std::int64_t j) {
      const Interval x(t.x[i], t.x[j]);
      c.check(pow(x, n), exact_pown(t, i, j, n), [&] { return std::string("(") + hex(x) + ", " + std::to_string(n) + ")"; });
    });
    cases += scaled(80'000);
  }
  EXPECT_GE(cases, scaled(1'000'000));
  expect_ok(c);
}

TEST(MpfrPower, Root) {
  DoubleRange range;
  Gen g(0x90e0002);
  const std::vector<int> exponents = {3, 4, 5, 6, 7, 9, 12, 25, -2, -3, -4, -5};
  Checker c("root(x, n)", kMaxUlps);
  for (int n : exponents) {
    const int an = std::abs(n);
    const Table t = tabulate(power_pool(g, n, scaled(20'000)), [&](double x) { return rootn(x, n); });
    for_each_pair(t.x, scaled(90'000), g, [&](std::int64_t i, std::int64_t j) {
      const Interval x(t.x[i], t.x[j]);
      c.check(root(x, n), exact_root(t, i, j, n), [&] { return std::string("(") + hex(x) + ", " + std::to_string(n) + ")"; });
    });
    // Exact roots: k^n has the root k.
    for (int k = 1; k <= 20; ++k) {
      const double v = std::pow(static_cast<double>(k), an);
      if (n > 0 && v < 0x1p53) {
        EXPECT_EQ(root(Interval(v), n), Interval(k)) << k << "^" << n;
      }
    }
  }
  expect_ok(c);
}

namespace {

// A two-argument function tabulated on a grid: f[k * nx + i] = f(ys[k], xs[i]).
struct Grid {
  std::vector<double> ys, xs;
  std::vector<Bounds> f;
  const Bounds& at(std::int64_t k, std::int64_t i) const { return f[k * xs.size() + i]; }
};

template <class F>
Grid tabulate2(std::vector<double> ys, std::vector<double> xs, F&& f) {
  Grid g{std::move(ys), std::move(xs), {}};
  g.f.reserve(g.ys.size() * g.xs.size());
  for (double y : g.ys)
    for (double x : g.xs) g.f.push_back(f(y, x));
  return g;
}

std::pair<std::int64_t, std::int64_t> pick(Gen& g, std::int64_t n) {
  std::int64_t i = g.integer(0, n - 1), j;
  switch (g.integer(0, 3)) {
    case 0: j = i; break;
    case 1: j = i + g.integer(0, 2); break;
    default: j = g.integer(0, n - 1); break;
  }
  j = std::min(j, n - 1);
  return {std::min(i, j), std::max(i, j)};
}

std::vector<double> axis_pool(Gen& g, std::size_t size, bool positive_only) {
  std::vector<double> p = {0.0, 1.0, 2.0, 0.5, 3.0, 10.0, kMax, kTiny, 1e-300, 1e300, next_up(1.0), next_down(1.0)};
  for (std::size_t k = 0; k < size; ++k) {
    double v;
    switch (k % 7) {
      case 0: v = g.any_finite(); break;
      case 1: v = g.log_uniform(-8, 8); break;
      case 2: v = g.near(1.0, 20); break;
      case 3: v = static_cast<double>(g.integer(1, 12)); break;
      case 4: v = g.log_uniform(-1074, -900); break;
      case 5: v = g.log_uniform(100, 1023); break;
      default: v = g.uniform(0, 4); break;
    }
    p.push_back(std::fabs(v));
  }
  const std::size_t n = p.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (!positive_only || k % 8 == 0) p.push_back(-p[k]);
  }
  return finish_pool(std::move(p), true);
}

}  // namespace

TEST(MpfrPower, PowReal) {
  DoubleRange range;
  Gen g(0x90e0003);
  // x mostly >= 0 (a few negatives for the set-based domain), y of both signs
  // including integers, halves and huge exponents.
  std::vector<double> xs = axis_pool(g, scaled(600), true);
  std::vector<double> ys = axis_pool(g, scaled(600), false);
  for (double v : {0.5, 1.5, 2.5, 1.0 / 3, 1e5, 1e10, 2000.0}) ys.push_back(v), ys.push_back(-v);
  ys = finish_pool(std::move(ys), false);
  const Grid grid = tabulate2(ys, xs, [](double y, double x) { return eval2(mpfr_pow, x, y); });
  const auto zero = static_cast<std::int64_t>(std::lower_bound(xs.begin(), xs.end(), 0.0) - xs.begin());
  Checker c("pow(x, y)", kMaxUlps);
  while (c.cases() < scaled(1'000'000)) {
    auto [i, j] = pick(g, static_cast<std::int64_t>(xs.size()));
    auto [k, l] = pick(g, static_cast<std::int64_t>(ys.size()));
    if ((xs[i] == xs[j] && std::isinf(xs[i])) || (ys[k] == ys[l] && std::isinf(ys[k]))) continue;
    const Interval x(xs[i], xs[j]), y(ys[k], ys[l]);
    Expected e;
    if (xs[j] < 0) {
      e = Expected::none();
    } else if (xs[j] == 0) {
      e = ys[l] > 0 ? Expected::of(0, 0) : Expected::none();  // 0^y = 0 for y > 0 only
    } else {
      const std::int64_t i0 = xs[i] < 0 ? zero : i;  // the part x >= 0
      double lo = kInf, hi = -kInf;
      for (std::int64_t xi : {i0, j})
        for (std::int64_t yk : {k, l}) {
          lo = std::min(lo, grid.at(yk, xi).down);
          hi = std::max(hi, grid.at(yk, xi).up);
        }
      e = Expected::of(lo, hi);
    }
    c.check(pow(x, y), e, [&] { return std::string("(") + hex(x) + ", " + hex(y) + ")"; });
  }
  expect_ok(c);
}

TEST(MpfrPower, Atan2) {
  DoubleRange range;
  Gen g(0x90e0004);
  const std::vector<double> ys = axis_pool(g, scaled(600), false), xs = axis_pool(g, scaled(600), false);
  const Grid grid = tabulate2(ys, xs, [](double y, double x) { return eval2(mpfr_atan2, y, x); });
  const Bounds pi = rounded([&](mpfr_ptr r, mpfr_rnd_t rnd) { return mpfr_const_pi(r, rnd); });
  Checker c("atan2", kMaxUlps);
  while (c.cases() < scaled(1'000'000)) {
    auto [k, l] = pick(g, static_cast<std::int64_t>(ys.size()));
    auto [i, j] = pick(g, static_cast<std::int64_t>(xs.size()));
    if ((xs[i] == xs[j] && std::isinf(xs[i])) || (ys[k] == ys[l] && std::isinf(ys[k]))) continue;
    const Interval y(ys[k], ys[l]), x(xs[i], xs[j]);
    Expected e;
    if (ys[k] == 0 && ys[l] == 0 && xs[i] == 0 && xs[j] == 0) {
      e = Expected::none();  // only the origin
    } else if (xs[i] < 0 && ys[k] < 0 && ys[l] >= 0) {
      e = Expected::of(-pi.up, pi.up);  // touches the negative x axis from below: -pi and pi
    } else {
      // Elsewhere the angle is continuous on the box minus the origin: its
      // extremes are at corners (zero y read as +0, the origin skipped).
      double lo = kInf, hi = -kInf;
      for (std::int64_t yk : {k, l})
        for (std::int64_t xi : {i, j}) {
          if (ys[yk] == 0 && xs[xi] == 0) continue;
          lo = std::min(lo, grid.at(yk, xi).down);
          hi = std::max(hi, grid.at(yk, xi).up);
        }
      e = Expected::of(lo, hi);
    }
    c.check(atan2(y, x), e, [&] { return std::string("(") + hex(y) + ", " + hex(x) + ")"; });
  }
  expect_ok(c);
}

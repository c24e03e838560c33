// sin cos tan against MPFR, including huge arguments and points next to the
// multiples of pi/2 where the extrema and the poles are.
//
// The oracle knows, for each pool point x, K(x) mod 4 with K(x) = floor(x / (pi/2))
// (MPFR, pi to |x|'s exponent + 200 bits: no double is closer than 2^-62 to
// a multiple of pi/2, relative to pi/2). An interval [a, b] with b - a < 2 pi
// holds the n multiples (K(a)+1..K(b)) pi/2, n the only integer = K(b) - K(a)
// (mod 4) within 1 of (b - a) / (pi/2) (computed exactly). Multiple m is an
// extremum or a pole according to m mod 4.
#include <gtest/gtest.h>

#include "mpfr_oracle.h"
#include "sillage/interval/elementary.h"
#include "sillage/interval/trig_batch.h"

using namespace oracle;
using sillage::Interval;

namespace {

const std::size_t kCases = scaled(1'000'000);
const std::size_t kPool = scaled(100'000);
constexpr int kMaxUlps = 4;

// floor(x / (pi/2)) mod 4, x finite.
int quadrant(double x) {
  const long e = x == 0 ? 0 : std::max<long>(std::ilogb(x), 0);
  const mpfr_prec_t prec = static_cast<mpfr_prec_t>(e) + 200;
  Real half_pi(prec), q(prec), xr(x, prec);
  mpfr_const_pi(half_pi, MPFR_RNDN);
  mpfr_div_2ui(half_pi, half_pi, 1, MPFR_RNDN);
  mpfr_div(q, xr, half_pi, MPFR_RNDN);
  mpfr_floor(q, q);
  mpfr_div_2ui(q, q, 2, MPFR_RNDN);  // exact
  mpfr_frac(q, q, MPFR_RNDN);        // 0, +-1/4, +-1/2, +-3/4: exact
  const int m = static_cast<int>(mpfr_get_d(q, MPFR_RNDN) * 4);
  return (m + 4) & 3;
}

// (b - a) / (pi/2), b - a exact (2200 bits hold any difference of doubles).
double quarter_turns(double a, double b) {
  Real w(2200), ar(a, 53), br(b, 53), pi(300);
  mpfr_sub(w, br, ar, MPFR_RNDN);
  mpfr_const_pi(pi, MPFR_RNDN);
  mpfr_mul_2ui(w, w, 1, MPFR_RNDN);
  mpfr_div(w, w, pi, MPFR_RNDN);
  return mpfr_get_d(w, MPFR_RNDN);
}

// Multiples of pi/2, rounded to double at every scale, then moved a few ulps.
double near_multiple(Gen& g) {
  const double t = g.coin() ? g.log_uniform(-2, 60) : g.log_uniform(60, 1023);
  const double z = std::fabs(t);
  const mpfr_prec_t prec = std::max(std::ilogb(z), 0) + 200;
  Real half_pi(prec), m(prec), tr(t, prec);
  mpfr_const_pi(half_pi, MPFR_RNDN);
  mpfr_div_2ui(half_pi, half_pi, 1, MPFR_RNDN);
  mpfr_div(m, tr, half_pi, MPFR_RNDN);
  mpfr_round(m, m);
  mpfr_mul(m, m, half_pi, MPFR_RNDN);
  return g.near(mpfr_get_d(m, MPFR_RNDN), 3);
}

struct TrigTable {
  std::vector<double> x;
  std::vector<Bounds> s, c, t;
  std::vector<int> k;  // K(x) mod 4
};

TrigTable make_table() {
  Gen g(0x7419001);
  std::vector<double> p;
  add_specials(p);
  // The closest double to a multiple of pi/2 (6381956970095103 * 2^797) and
  // its neighbours, and a few famous large arguments.
  for (double v : {0x1.6ac5b262ca1ffp+849, 1e22, 1e300, 0x1p1023, 0x1p60, 0x1p52, 0x1p28}) {
    double u = v, d = v;
    for (int k = 0; k < 4; ++k) {
      for (double w : {u, d}) p.push_back(w), p.push_back(-w);
      u = next_up(u);
      d = next_down(d);
    }
  }
  for (std::size_t i = 0; i < kPool; ++i) {
    switch (i % 8) {
      case 0: p.push_back(g.any_finite()); break;
      case 1: case 2: p.push_back(near_multiple(g)); break;
      case 3: p.push_back(g.uniform(-10, 10)); break;
      case 4: p.push_back(g.uniform(-1e4, 1e4)); break;
      case 5: p.push_back(g.log_uniform(-1074, -20)); break;
      case 6: p.push_back(g.log_uniform(-10, 60)); break;
      default: p.push_back(static_cast<double>(g.integer(-100, 100))); break;
    }
  }
  TrigTable t;
  t.x = finish_pool(std::move(p), true);
  for (double v : t.x) {
    const bool fin = std::isfinite(v);
    t.s.push_back(fin ? eval1(mpfr_sin, v) : Bounds{});
    t.c.push_back(fin ? eval1(mpfr_cos, v) : Bounds{});
    t.t.push_back(fin ? eval1(mpfr_tan, v) : Bounds{});
    t.k.push_back(fin ? quadrant(v) : 0);
  }
  return t;
}

const TrigTable& table() {
  static const TrigTable t = [] {
    DoubleRange range;
    return make_table();
  }();
  return t;
}

// Residues mod 4 of the multiples of pi/2 inside [x_i, x_j], as a bit set;
// -1 if the interval is unbounded or at least 2 pi wide (every residue).
int residues_inside(const TrigTable& t, std::int64_t i, std::int64_t j) {
  const double a = t.x[i], b = t.x[j];
  if (!std::isfinite(a) || !std::isfinite(b)) return -1;
  if (a == b) return 0;
  const double z = quarter_turns(a, b);
  if (z >= 4) return -1;
  const int r = (t.k[j] - t.k[i]) & 3;
  const int n = r + 4 * static_cast<int>(std::lround((z - r) / 4));
  int set = 0;
  for (int m = 1; m <= n; ++m) set |= 1 << ((t.k[i] + m) & 3);
  return set;
}

template <class Ours, class Exact>
void sweep(const char* name, std::uint64_t seed, Ours&& ours, Exact&& expected, int max_ulps = kMaxUlps) {
  DoubleRange range;
  const TrigTable& t = table();
  Gen g(seed);
  Checker c(name, max_ulps);
  for_each_pair(t.x, kCases, g, [&](std::int64_t i, std::int64_t j) {
    const Interval x(t.x[i], t.x[j]);
    c.check(ours(x), expected(t, i, j, residues_inside(t, i, j)), [&] { return std::string("(") + hex(x) + ")"; });
  });
  expect_ok(c);
}

// Image of a function with a maximum 1 at residue `top` and a minimum -1 at `bottom`.
Expected wave(const std::vector<Bounds>& f, std::int64_t i, std::int64_t j, int set, int top, int bottom) {
  if (set < 0) return Expected::of(-1, 1);
  const double lo = (set >> bottom) & 1 ? -1.0 : std::min(f[i].down, f[j].down);
  const double hi = (set >> top) & 1 ? 1.0 : std::max(f[i].up, f[j].up);
  return Expected::of(lo, hi);
}

}  // namespace

TEST(MpfrTrig, Sin) {
  sweep("sin", 0x7419002, [](const Interval& x) { return sin(x); },
        [](const TrigTable& t, std::int64_t i, std::int64_t j, int set) { return wave(t.s, i, j, set, 1, 3); });
}

TEST(MpfrTrig, Cos) {
  sweep("cos", 0x7419003, [](const Interval& x) { return cos(x); },
        [](const TrigTable& t, std::int64_t i, std::int64_t j, int set) { return wave(t.c, i, j, set, 0, 2); });
}

TEST(MpfrTrig, Tan) {
  sweep("tan", 0x7419004, [](const Interval& x) { return tan(x); },
        [](const TrigTable& t, std::int64_t i, std::int64_t j, int set) {
          if (set < 0 || (set & 0b1010) != 0) return Expected::of(-kInf, kInf);  // a pole inside
          return Expected::of(t.t[i].down, t.t[j].up);
        });
}

// The rows of the batch evaluator (trig_batch.h): enclosures within 8 ulps
// of the optimal ones on the kernel's lanes (relative widening 2^-50), the
// scalar functions elsewhere.
namespace {

constexpr int kRowUlps = 8;

Interval sin_row(const Interval& x) {
  Interval r;
  sillage::detail::sin_rows(&x, &r, 1);
  return r;
}

Interval cos_row(const Interval& x) {
  Interval r;
  sillage::detail::cos_rows(&x, &r, 1);
  return r;
}

}  // namespace

TEST(MpfrTrig, SinRows) {
  sweep("sin rows", 0x7419005, sin_row,
        [](const TrigTable& t, std::int64_t i, std::int64_t j, int set) { return wave(t.s, i, j, set, 1, 3); }, kRowUlps);
}

TEST(MpfrTrig, CosRows) {
  sweep("cos rows", 0x7419006, cos_row,
        [](const TrigTable& t, std::int64_t i, std::int64_t j, int set) { return wave(t.c, i, j, set, 0, 2); }, kRowUlps);
}

// The value kernel on every pool point it covers: enclosing bounds, the
// quadrant of the exact reduction, and a share of covered points large
// enough that the sweeps above exercise it.
TEST(MpfrTrig, RowKernelValues) {
  DoubleRange range;
  const TrigTable& t = table();
  const std::size_t n = t.x.size();
  std::vector<double> lo(n), hi(n), quad(n), fast(n);
  std::size_t covered = 0, moderate = 0;
  std::uint64_t worst = 0;
  for (const bool cosine : {false, true}) {
    sillage::detail::trig_values(t.x.data(), n, cosine, lo.data(), hi.data(), quad.data(), fast.data());
    const std::vector<Bounds>& f = cosine ? t.c : t.s;
    for (std::size_t i = 0; i < n; ++i) {
      if (std::fabs(t.x[i]) >= 1e-6 && std::fabs(t.x[i]) <= 1e4) ++moderate;
      if (fast[i] == 0) continue;
      ++covered;
      ASSERT_TRUE(lo[i] <= f[i].down && hi[i] >= f[i].up)
          << (cosine ? "cos(" : "sin(") << hex(t.x[i]) << "): [" << hex(lo[i]) << ", " << hex(hi[i]) << "] misses ["
          << hex(f[i].down) << ", " << hex(f[i].up) << "]";
      ASSERT_EQ(static_cast<int>(quad[i]), t.k[i]) << hex(t.x[i]);
      worst = std::max({worst, ulps_between(lo[i], f[i].down), ulps_between(hi[i], f[i].up)});
    }
  }
  std::printf("[mpfr] row kernel: %zu of %zu values covered, max distance to optimal %llu ulp(s)\n", covered, 2 * n,
              static_cast<unsigned long long>(worst));
  EXPECT_GE(covered, moderate * 9 / 10);
  EXPECT_LE(worst, static_cast<std::uint64_t>(kRowUlps));
}

// A row of many intervals gives each one's result alone (the lanes are independent).
TEST(MpfrTrig, RowsOfManyIntervals) {
  Gen g(0x7419007);
  std::vector<Interval> x(1000), s(1000), c(1000);
  for (Interval& v : x) {
    const double a = g.uniform(-50, 50);
    v = g.coin() ? Interval(a) : g.integer(0, 20) == 0 ? Interval::empty() : Interval(a, a + g.uniform(0, 4));
  }
  sillage::detail::sin_rows(x.data(), s.data(), x.size());
  sillage::detail::cos_rows(x.data(), c.data(), x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    ASSERT_EQ(hex(s[i]), hex(sin_row(x[i]))) << hex(x[i]);
    ASSERT_EQ(hex(c[i]), hex(cos_row(x[i]))) << hex(x[i]);
  }
  sillage::detail::cos_rows(x.data(), x.data(), x.size());  // in place
  for (std::size_t i = 0; i < x.size(); ++i) ASSERT_EQ(hex(x[i]), hex(c[i]));
}

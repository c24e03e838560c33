// exp log atan asin acos sinh cosh tanh against MPFR: containment of the
// exact image, each bound within 4 ulps of the optimal outward rounding.
//
// Each sweep draws a pool of points (random and adversarial), tabulates the
// correctly rounded f at each with MPFR, then checks >= 1e6 intervals built
// from pairs of pool points: the exact image of an interval follows from the
// values at its end points (and at the domain's edges), by monotonicity.
#include <gtest/gtest.h>

#include <functional>

#include "mpfr_oracle.h"
#include "sillage/interval/elementary.h"

using namespace oracle;
using sillage::Interval;

namespace {

const std::size_t kCases = scaled(1'000'000);
const std::size_t kPool = scaled(60'000);
constexpr int kMaxUlps = 4;

using Recipe = std::function<double(Gen&)>;

// kPool points from the recipes in turn, plus the common specials and +-inf.
std::vector<double> make_pool(Gen& g, const std::vector<Recipe>& recipes) {
  std::vector<double> p;
  add_specials(p);
  for (std::size_t k = 0; k < kPool; ++k) p.push_back(recipes[k % recipes.size()](g));
  return finish_pool(std::move(p), true);
}

Table table1(const std::vector<double>& pool, int (*f)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t)) {
  return tabulate(pool, [&](double x) { return eval1(f, x); });
}

// Sweeps the interval cases of a pool; expected(i, j) gives the exact image of [x_i, x_j].
template <class Ours, class Exact>
void sweep(const char* name, const Table& t, Gen& g, Ours&& ours, Exact&& expected) {
  Checker c(name, kMaxUlps);
  for_each_pair(t.x, kCases, g, [&](std::int64_t i, std::int64_t j) {
    const Interval x(t.x[i], t.x[j]);
    c.check(ours(x), expected(i, j), [&] { return std::string("(") + hex(x) + ")"; });
  });
  expect_ok(c);
}

Recipe near(double v, int k) { return [=](Gen& g) { return g.near(v, k); }; }
Recipe uniform(double lo, double hi) { return [=](Gen& g) { return g.uniform(lo, hi); }; }
Recipe logu(int lo, int hi) { return [=](Gen& g) { return g.log_uniform(lo, hi); }; }
const Recipe kAny = [](Gen& g) { return g.any_finite(); };
const Recipe kInts = [](Gen& g) { return static_cast<double>(g.integer(-1000, 1000)); };

}  // namespace

TEST(MpfrElementary, Exp) {
  DoubleRange range;
  Gen g(0xe1e0001);
  // Around 0, the overflow threshold log(MAX), the subnormal range and its ends.
  const auto pool = make_pool(g, {kAny, logu(-1074, 0), uniform(-750, 750), near(709.782712893384, 40),
                                  near(-708.3964185322641, 40), near(-745.1332191019411, 40),
                                  uniform(-745.2, -708.3), kInts, near(0.6931471805599453, 8)});
  const Table t = table1(pool, mpfr_exp);
  sweep("exp", t, g, [](const Interval& x) { return exp(x); },
        [&](std::int64_t i, std::int64_t j) { return Expected::of(t.f[i].down, t.f[j].up); });
}

TEST(MpfrElementary, Log) {
  DoubleRange range;
  Gen g(0xe1e0002);
  const auto pool = make_pool(g, {kAny, logu(-1074, 1023), near(1.0, 60), uniform(0.5, 2.0),
                                  [](Gen& g) { return 1.0 + g.log_uniform(-52, -10); }, uniform(0, 10),
                                  [](Gen& g) { return std::ldexp(1.0, static_cast<int>(g.integer(-1074, 1023))); }});
  const Table t = table1(pool, mpfr_log);
  sweep("log", t, g, [](const Interval& x) { return log(x); }, [&](std::int64_t i, std::int64_t j) {
    if (t.x[j] <= 0) return Expected::none();
    return Expected::of(t.x[i] <= 0 ? -kInf : t.f[i].down, t.f[j].up);
  });
}

TEST(MpfrElementary, Atan) {
  DoubleRange range;
  Gen g(0xe1e0003);
  const auto pool = make_pool(g, {kAny, logu(-1074, -20), logu(-30, 60), uniform(-10, 10), near(0x1p53, 20),
                                  near(1.0, 20), kInts});
  const Table t = table1(pool, mpfr_atan);
  sweep("atan", t, g, [](const Interval& x) { return atan(x); },
        [&](std::int64_t i, std::int64_t j) { return Expected::of(t.f[i].down, t.f[j].up); });
}

namespace {

// Rounded value of a constant computed by f (pi/2 = asin(1), pi = acos(-1)).
Bounds at(int (*f)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t), double x) { return eval1(f, x); }

const std::vector<Recipe> kUnitRecipes = {
    uniform(-1, 1), near(1.0, 60), near(-1.0, 60), logu(-1074, -1), uniform(-3, 3),
    [](Gen& g) { return g.sign() * (1.0 - g.log_uniform(-53, -20)); }, near(0.5, 10), near(-0.5, 10), kAny};

}  // namespace

TEST(MpfrElementary, Asin) {
  DoubleRange range;
  Gen g(0xe1e0004);
  const Table t = table1(make_pool(g, kUnitRecipes), mpfr_asin);
  const Bounds lo_edge = at(mpfr_asin, -1.0), hi_edge = at(mpfr_asin, 1.0);
  sweep("asin", t, g, [](const Interval& x) { return asin(x); }, [&](std::int64_t i, std::int64_t j) {
    const double a = t.x[i], b = t.x[j];
    if (b < -1 || a > 1) return Expected::none();
    return Expected::of(a < -1 ? lo_edge.down : t.f[i].down, b > 1 ? hi_edge.up : t.f[j].up);
  });
}

TEST(MpfrElementary, Acos) {
  DoubleRange range;
  Gen g(0xe1e0005);
  const Table t = table1(make_pool(g, kUnitRecipes), mpfr_acos);
  const Bounds pi = at(mpfr_acos, -1.0);
  sweep("acos", t, g, [](const Interval& x) { return acos(x); }, [&](std::int64_t i, std::int64_t j) {
    const double a = t.x[i], b = t.x[j];
    if (b < -1 || a > 1) return Expected::none();
    return Expected::of(b > 1 ? 0.0 : t.f[j].down, a < -1 ? pi.up : t.f[i].up);  // decreasing
  });
}

namespace {

// Around 0, the overflow thresholds +-asinh(MAX), and where tanh rounds to 1.
const std::vector<Recipe> kHypRecipes = {kAny,
                                         logu(-1074, -1),
                                         uniform(-720, 720),
                                         near(710.4758600739439, 40),
                                         near(-710.4758600739439, 40),
                                         uniform(-25, 25),
                                         near(19.061547465398498, 30),
                                         logu(-30, 5),
                                         kInts};

}  // namespace

TEST(MpfrElementary, Sinh) {
  DoubleRange range;
  Gen g(0xe1e0006);
  const Table t = table1(make_pool(g, kHypRecipes), mpfr_sinh);
  sweep("sinh", t, g, [](const Interval& x) { return sinh(x); },
        [&](std::int64_t i, std::int64_t j) { return Expected::of(t.f[i].down, t.f[j].up); });
}

TEST(MpfrElementary, Cosh) {
  DoubleRange range;
  Gen g(0xe1e0007);
  const Table t = table1(make_pool(g, kHypRecipes), mpfr_cosh);
  sweep("cosh", t, g, [](const Interval& x) { return cosh(x); }, [&](std::int64_t i, std::int64_t j) {
    const double lo = t.x[i] <= 0 && t.x[j] >= 0 ? 1.0 : std::min(t.f[i].down, t.f[j].down);
    return Expected::of(lo, std::max(t.f[i].up, t.f[j].up));
  });
}

TEST(MpfrElementary, Tanh) {
  DoubleRange range;
  Gen g(0xe1e0008);
  const Table t = table1(make_pool(g, kHypRecipes), mpfr_tanh);
  sweep("tanh", t, g, [](const Interval& x) { return tanh(x); },
        [&](std::int64_t i, std::int64_t j) { return Expected::of(t.f[i].down, t.f[j].up); });
}

// Tube arithmetic (3.5)-(3.6): exact values on a small tube, and the
// guarantee on random trajectories inside random tubes: the pointwise result
// of the trajectories stays inside the result tube.
#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "sillage/error.h"
#include "sillage/tube/trajectory.h"
#include "sillage/tube/tube_arithmetic.h"

using namespace sillage;

namespace {

std::shared_ptr<TDomain> td012() { return TDomain::create(std::vector<double>{0.0, 1.0, 2.0}); }

// A random piecewise-linear trajectory over td's domain with samples at the
// time points and at random inner times.
Trajectory random_trajectory(const TDomain& td, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0), v(-3.0, 3.0);
  std::map<double, double> samples;
  for (std::size_t k = 0; k <= td.nb_slices(); ++k) samples[td.t(k)] = v(rng);
  for (std::size_t k = 0; k < td.nb_slices(); ++k) {
    const double t = td.t(k) + u(rng) * (td.t(k + 1) - td.t(k));
    samples[t] = v(rng);
  }
  return Trajectory(samples);
}

// A random tube that contains x: its enclosures inflated by random margins.
Tube tube_around(const std::shared_ptr<TDomain>& td, const Trajectory& x, std::mt19937_64& rng) {
  std::exponential_distribution<double> m(4.0);
  std::vector<Interval> slices, gates;
  for (std::size_t k = 0; k < td->nb_slices(); ++k) slices.push_back(x(td->slice_domain(k)).inflate(m(rng)));
  for (std::size_t k = 0; k <= td->nb_slices(); ++k) {
    gates.push_back(x(td->t(k)).inflate(m(rng)) & slices[k < td->nb_slices() ? k : k - 1]);
  }
  return Tube(td, slices, gates);
}

std::shared_ptr<TDomain> random_tdomain(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> d(0.01, 0.5);
  std::vector<double> ts{-1.0};
  const int n = std::uniform_int_distribution<int>(1, 30)(rng);
  for (int i = 0; i < n; ++i) ts.push_back(ts.back() + d(rng));
  return TDomain::create(ts);
}

using Binary = std::function<Interval(const Interval&, const Interval&)>;
using TubeBinary = std::function<Tube(const Tube&, const Tube&)>;

// The values of the trajectories at many times (time points included), run
// through op, stay inside the result tube.
void check_binary(const char* name, const TubeBinary& tube_op, const Binary& op) {
  std::mt19937_64 rng(2024);
  for (int trial = 0; trial < 60; ++trial) {
    auto td = random_tdomain(rng);
    const Trajectory a = random_trajectory(*td, rng), b = random_trajectory(*td, rng);
    const Tube x = tube_around(td, a, rng), y = tube_around(td, b, rng);
    ASSERT_TRUE(x.contains(a));
    ASSERT_TRUE(y.contains(b));
    const Tube z = tube_op(x, y);
    for (std::size_t k = 0; k <= td->nb_slices(); ++k) {
      const double t = td->t(k);
      ASSERT_TRUE(op(a(t), b(t)).is_subset(z(t))) << name << " at gate " << k;
    }
    std::uniform_real_distribution<double> ut(td->t0(), td->tf());
    for (int i = 0; i < 200; ++i) {
      const double t = ut(rng);
      ASSERT_TRUE(op(a(t), b(t)).is_subset(z(t))) << name << " at t = " << t;
      const Interval s(std::max(td->t0(), t - 0.05), t);
      ASSERT_TRUE(op(a(t), b(t)).is_subset(z(s))) << name << " over " << s;
    }
  }
}

}  // namespace

TEST(TubeArithmetic, ExactSmallValues) {
  auto td = td012();
  Tube x(td, {Interval(1, 2), Interval(-1, 3)}, {Interval(1, 1), Interval(2, 2), Interval(0, 3)});
  Tube y(td, Interval(2, 4));
  Tube s = x + y;
  EXPECT_EQ(s.slice(0), Interval(3, 6));
  EXPECT_EQ(s.slice(1), Interval(1, 7));
  EXPECT_EQ(s.gate(0), Interval(3, 5));
  EXPECT_EQ(s.gate(1), Interval(4, 6));
  EXPECT_EQ((x - y).slice(1), Interval(-5, 1));
  EXPECT_EQ((x * y).slice(1), Interval(-4, 12));
  EXPECT_EQ((x / y).gate(1), Interval(0.5, 1));
  EXPECT_EQ((-x).slice(1), Interval(-3, 1));
  EXPECT_EQ((x + 1.0).gate(2), Interval(1, 4));
  EXPECT_EQ((2.0 * x).slice(0), Interval(2, 4));
  EXPECT_EQ((1.0 - x).slice(0), Interval(-1, 0));
  EXPECT_EQ((x / Interval(2)).slice(0), Interval(0.5, 1));
  EXPECT_EQ((Interval(6) / y).slice(0), Interval(1.5, 3));
  EXPECT_EQ(sqr(x).slice(1), Interval(0, 9));
  EXPECT_EQ(abs(x).slice(1), Interval(0, 3));
  EXPECT_EQ(pow(x, 3).slice(0), Interval(1, 8));
  EXPECT_EQ(sqrt(y).gate(0), sqrt(Interval(2, 4)));
  EXPECT_EQ(exp(x).gate(0), exp(Interval(1)));
  EXPECT_EQ(min(x, y).slice(1), Interval(-1, 3));
  EXPECT_EQ(max(x, y).slice(1), Interval(2, 4));
  EXPECT_EQ(sign(x).slice(1), Interval(-1, 1));
  Tube c = x;
  c += y;
  EXPECT_EQ(c, s);
  c -= y;
  EXPECT_TRUE(x.is_subset(c));
  c *= Interval(0);
  EXPECT_EQ(c.slice(1), Interval(0, 0));
  c /= Interval(2);
  EXPECT_EQ(c.gate(0), Interval(0, 0));
  EXPECT_EQ((x & y).slice(1), Interval(2, 3));
  EXPECT_EQ((x | y).gate(0), Interval(1, 4));
}

TEST(TubeArithmetic, ElementaryFunctionsSliceWise) {
  auto td = td012();
  Tube x(td, Interval(0.5, 1));
  const Interval v(0.5, 1);
  // sin and cos of tubes go by rows (trig_batch.h): enclosures of sin(v)
  // and cos(v) within a few ulps, not the scalar functions' bits.
  const auto near = [](const Interval& row, const Interval& scalar) {
    EXPECT_TRUE(scalar.is_subset(row)) << row << " " << scalar;
    EXPECT_LE(row.diam() - scalar.diam(), 0x1p-48 * scalar.mag()) << row << " " << scalar;
  };
  near(sin(x).slice(0), sin(v));
  near(cos(x).gate(2), cos(v));
  near(sin(Tube(td, Interval(-40.0, -39.0))).slice(1), sin(Interval(-40.0, -39.0)));
  EXPECT_TRUE(cos(Tube(td, Interval::empty())).slice(0).is_empty());
  EXPECT_EQ(cos(Tube(td, Interval(-1e30, 1e30))).gate(1), Interval(-1, 1));  // huge: the scalar path
  EXPECT_EQ(tan(x).slice(1), tan(v));
  EXPECT_EQ(log(x).slice(1), log(v));
  EXPECT_EQ(asin(x).slice(1), asin(v));
  EXPECT_EQ(acos(x).slice(1), acos(v));
  EXPECT_EQ(atan(x).slice(1), atan(v));
  EXPECT_EQ(sinh(x).slice(1), sinh(v));
  EXPECT_EQ(cosh(x).slice(1), cosh(v));
  EXPECT_EQ(tanh(x).slice(1), tanh(v));
  EXPECT_EQ(root(x, 3).slice(1), root(v, 3));
  EXPECT_EQ(pow(x, 0.5).slice(1), pow(v, 0.5));
  EXPECT_EQ(pow(x, Interval(1, 2)).slice(1), pow(v, Interval(1, 2)));
  EXPECT_EQ(pow(x, x).slice(1), pow(v, v));
  EXPECT_EQ(atan2(x, x).slice(1), atan2(v, v));
  EXPECT_EQ(atan2(x, Interval(1)).slice(1), atan2(v, Interval(1)));
  EXPECT_EQ(atan2(Interval(1), x).slice(1), atan2(Interval(1), v));
  // outside the domain: empty (a result, not an error)
  EXPECT_TRUE(log(Tube(td, Interval(-2, -1))).is_empty());
}

TEST(TubeArithmetic, MismatchedDomainsThrow) {
  Tube x(td012(), Interval(0, 1));
  Tube y(td012(), Interval(0, 1));
  EXPECT_THROW(x + y, DimensionError);
  EXPECT_THROW(x - y, DimensionError);
  EXPECT_THROW(x * y, DimensionError);
  EXPECT_THROW(x / y, DimensionError);
  EXPECT_THROW(x += y, DimensionError);
  EXPECT_THROW(atan2(x, y), DimensionError);
  EXPECT_THROW(x & y, DimensionError);
}

TEST(TubeArithmetic, PropertyAdd) {
  check_binary("+", [](const Tube& x, const Tube& y) { return x + y; },
               [](const Interval& a, const Interval& b) { return a + b; });
}
TEST(TubeArithmetic, PropertySub) {
  check_binary("-", [](const Tube& x, const Tube& y) { return x - y; },
               [](const Interval& a, const Interval& b) { return a - b; });
}
TEST(TubeArithmetic, PropertyMul) {
  check_binary("*", [](const Tube& x, const Tube& y) { return x * y; },
               [](const Interval& a, const Interval& b) { return a * b; });
}
TEST(TubeArithmetic, PropertyDiv) {
  check_binary("/", [](const Tube& x, const Tube& y) { return x / y; },
               [](const Interval& a, const Interval& b) { return a / b; });
}
TEST(TubeArithmetic, PropertyAtan2) {
  check_binary("atan2", [](const Tube& x, const Tube& y) { return atan2(x, y); },
               [](const Interval& a, const Interval& b) { return atan2(a, b); });
}
TEST(TubeArithmetic, PropertyUnaryCompositions) {
  check_binary("sin(x)+exp(y)", [](const Tube& x, const Tube& y) { return sin(x) + exp(y); },
               [](const Interval& a, const Interval& b) { return sin(a) + exp(b); });
  check_binary("sqrt(sqr(x))*cos(y)", [](const Tube& x, const Tube& y) { return sqrt(sqr(x)) * cos(y); },
               [](const Interval& a, const Interval& b) { return sqrt(sqr(a)) * cos(b); });
  check_binary("-x^3 + tanh(y)", [](const Tube& x, const Tube& y) { return -pow(x, 3) + tanh(y); },
               [](const Interval& a, const Interval& b) { return -pow(a, 3) + tanh(b); });
}

// Tube: construction, evaluation at times and over intervals (3.3),
// set/set_gate, inversion (3.4), set operations, value semantics, errors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "sillage/error.h"
#include "sillage/expr/function.h"
#include "sillage/tube/trajectory.h"
#include "sillage/tube/tube.h"

using namespace sillage;

namespace {

std::shared_ptr<TDomain> td0123() { return TDomain::create(std::vector<double>{0.0, 1.0, 2.0, 3.0}); }

// slices [0,2] [1,3] [2,5]; gates [0,2] [1,2] [2,3] [2,5]
Tube small_tube(const std::shared_ptr<TDomain>& td) {
  return Tube(td, std::vector<Interval>{Interval(0, 2), Interval(1, 3), Interval(2, 5)});
}

}  // namespace

TEST(Tube, GatesFromSlices) {
  auto td = td0123();
  Tube x = small_tube(td);
  ASSERT_EQ(x.nb_slices(), 3u);
  EXPECT_EQ(x.gate(0), Interval(0, 2));
  EXPECT_EQ(x.gate(1), Interval(1, 2));
  EXPECT_EQ(x.gate(2), Interval(2, 3));
  EXPECT_EQ(x.gate(3), Interval(2, 5));
  EXPECT_EQ(x.slices().size(), 3u);
  EXPECT_EQ(x.gates().size(), 4u);
  EXPECT_EQ(x.tdomain(), td);
}

TEST(Tube, ConstantConstructor) {
  auto td = td0123();
  Tube x(td, Interval(-1, 1));
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(x.slice(k), Interval(-1, 1));
  for (std::size_t k = 0; k <= 3; ++k) EXPECT_EQ(x.gate(k), Interval(-1, 1));
  Tube all(td);
  EXPECT_TRUE(all.codomain().is_all_reals());
}

TEST(Tube, EvalAtTimes) {
  auto td = td0123();
  Tube x = small_tube(td);
  EXPECT_EQ(x(0.0), Interval(0, 2));
  EXPECT_EQ(x(0.5), Interval(0, 2));
  EXPECT_EQ(x(1.0), Interval(1, 2));  // the gate, tighter than both slices
  EXPECT_EQ(x(1.5), Interval(1, 3));
  EXPECT_EQ(x(3.0), Interval(2, 5));
  EXPECT_THROW(x(3.5), Error);
  EXPECT_THROW(x(-0.1), Error);
  EXPECT_THROW(x(std::numeric_limits<double>::quiet_NaN()), Error);
}

TEST(Tube, EvalOverIntervals) {
  auto td = td0123();
  Tube x = small_tube(td);
  EXPECT_EQ(x(Interval(0.5, 1.5)), Interval(0, 3));
  EXPECT_EQ(x(Interval(1, 2)), Interval(1, 3));  // slice 1 and gates 1, 2 only
  EXPECT_EQ(x(Interval(0, 1)), Interval(0, 2));
  EXPECT_EQ(x(Interval(1.2, 1.8)), Interval(1, 3));
  EXPECT_EQ(x(Interval(1.5, 3)), Interval(1, 5));
  EXPECT_EQ(x(Interval(0, 3)), Interval(0, 5));
  EXPECT_EQ(x(Interval(1, 1)), Interval(1, 2));  // degenerate: the gate
  EXPECT_EQ(x(Interval(2.5, 2.5)), Interval(2, 5));
  EXPECT_TRUE(x(Interval::empty()).is_empty());
  EXPECT_THROW(x(Interval(-1, 1)), Error);
  EXPECT_THROW(x(Interval(2, 4)), Error);
}

TEST(Tube, EvalOverIntervalWithTightGates) {
  auto td = td0123();
  // gates narrower than slices: x([1,2]) must use slice 1 and gates 1, 2 but
  // not the neighbouring slices
  Tube x(td, {Interval(0, 10), Interval(4, 5), Interval(-10, 0)});
  x.set_gate(1, Interval(4));  // set_gate takes any value: gate 2 is even off slice 2
  x.set_gate(2, Interval(5));
  EXPECT_EQ(x(Interval(1, 2)), Interval(4, 5));
  EXPECT_EQ(x(Interval(0.9, 2)), Interval(0, 10));
}

TEST(Tube, SetSliceAndGate) {
  auto td = td0123();
  Tube x(td, Interval(0, 10));
  x.set(Interval(1, 2), 1);
  EXPECT_EQ(x.slice(1), Interval(1, 2));
  EXPECT_EQ(x.gate(1), Interval(1, 2));  // [1,2] & [0,10]
  EXPECT_EQ(x.gate(2), Interval(1, 2));
  EXPECT_EQ(x.slice(0), Interval(0, 10));
  x.set(Interval(5, 6), 2);
  EXPECT_EQ(x.slice(2), Interval(5, 6));
  EXPECT_TRUE(x.gate(2).is_empty());  // [5,6] & slice 1 = [1,2]
  EXPECT_EQ(x.gate(3), Interval(5, 6));  // end gate: y
  EXPECT_TRUE(x.is_empty());
  x.set(Interval(-1, 1), 0);
  EXPECT_EQ(x.gate(0), Interval(-1, 1));
  EXPECT_EQ(x.gate(1), Interval(1, 1));
  x.set_gate(2, Interval(2, 5));
  EXPECT_EQ(x.gate(2), Interval(2, 5));
  EXPECT_EQ(x.slice(1), Interval(1, 2));  // set_gate leaves the slices alone
  EXPECT_FALSE(x.is_empty());
  x.set(Interval(3, 4));
  EXPECT_EQ(x, Tube(td, Interval(3, 4)));
  EXPECT_THROW(x.set(Interval(0, 1), 3), OutOfRangeError);
  EXPECT_THROW(x.set_gate(4, Interval(0, 1)), OutOfRangeError);
  EXPECT_THROW(x.slice(3), OutOfRangeError);
  EXPECT_THROW(x.gate(4), OutOfRangeError);
}

TEST(Tube, CodomainVolumeThickness) {
  auto td = td0123();
  Tube x = small_tube(td);
  EXPECT_EQ(x.codomain(), Interval(0, 5));
  EXPECT_EQ(x.volume(), 7.0);  // 1*2 + 1*2 + 1*3
  EXPECT_EQ(x.thickness(1), 2.0);
  EXPECT_EQ(x.max_thickness(), 3.0);
  // a non-representable width: the volume is an upper bound
  auto td2 = TDomain::create(std::vector<double>{0.1, 0.3});
  Tube y(td2, Interval(0, 1));
  EXPECT_GE(static_cast<long double>(y.volume()), static_cast<long double>(0.3) - static_cast<long double>(0.1));
  Tube e(td, Interval::empty());
  EXPECT_TRUE(e.is_empty());
  EXPECT_TRUE(e.codomain().is_empty());
  EXPECT_EQ(e.volume(), 0.0);
  Tube u(td);
  EXPECT_EQ(u.volume(), std::numeric_limits<double>::infinity());
}

TEST(Tube, InversionHandComputed) {
  auto td = td0123();
  Tube x = small_tube(td);
  std::vector<Interval> c;
  EXPECT_EQ(x.inverse(Interval(4, 6), c), Interval(2, 3));
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0], Interval(2, 3));
  EXPECT_EQ(x.inverse(Interval(0, 0.5)), Interval(0, 1));
  EXPECT_EQ(x.inverse(Interval(1.5, 1.6)), Interval(0, 2));
  EXPECT_TRUE(x.inverse(Interval(7, 8), c).is_empty());
  EXPECT_TRUE(c.empty());
  EXPECT_TRUE(x.inverse(Interval::empty()).is_empty());
}

TEST(Tube, InversionComponents) {
  auto td = td0123();
  // a tube that dips: slices [0,1] [2,3] [0,1], gates [0,1] [1,2] [1,2] [0,1]
  Tube x(td, {Interval(0, 1), Interval(2, 3), Interval(0, 1)},
         {Interval(0, 1), Interval(1, 2), Interval(1, 2), Interval(0, 1)});
  std::vector<Interval> c;
  EXPECT_EQ(x.inverse(Interval(0, 0.5), c), Interval(0, 3));
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0], Interval(0, 1));
  EXPECT_EQ(c[1], Interval(2, 3));
  EXPECT_EQ(x.inverse(Interval(2, 2), c), Interval(1, 2));
  ASSERT_EQ(c.size(), 1u);
  // y = [1,1]: gates 0..3 and slices 0, 2 meet it, slice 1 does not
  EXPECT_EQ(x.inverse(Interval(1, 1), c), Interval(0, 3));
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0], Interval(0, 1));
  EXPECT_EQ(c[1], Interval(2, 3));
  // a gate alone: a degenerate component
  Tube z(td, {Interval(0, 1), Interval(0, 4), Interval(0, 1)});
  z.set_gate(2, Interval(5));  // off its slices: only set_gate takes that
  EXPECT_EQ(z.inverse(Interval(5, 5), c), Interval(2, 2));
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0], Interval(2, 2));
}

TEST(Tube, SetOperationsAndComparisons) {
  auto td = td0123();
  Tube x = small_tube(td);
  Tube y(td, Interval(1, 4));
  Tube i = x;
  i &= y;
  EXPECT_EQ(i.slice(0), Interval(1, 2));
  EXPECT_EQ(i.slice(2), Interval(2, 4));
  EXPECT_EQ(i.gate(3), Interval(2, 4));
  EXPECT_TRUE(i.is_subset(x));
  EXPECT_TRUE(i.is_subset(y));
  EXPECT_FALSE(x.is_subset(y));
  Tube h = x;
  h |= y;
  EXPECT_EQ(h.slice(0), Interval(0, 4));
  EXPECT_EQ(h.gate(3), Interval(1, 5));
  EXPECT_TRUE(x.is_subset(h));
  EXPECT_NE(h, x);
  auto other = td0123();  // same times, different domain object
  Tube z(other, Interval(1, 4));
  EXPECT_THROW(x &= z, DimensionError);
  EXPECT_THROW(x |= z, DimensionError);
  EXPECT_THROW((void)x.is_subset(z), DimensionError);
  EXPECT_FALSE(z == y);
}

TEST(Tube, ValueSemantics) {
  auto td = td0123();
  Tube x = small_tube(td);
  Tube y = x;
  y.set(Interval(7, 8), 0);
  EXPECT_EQ(x.slice(0), Interval(0, 2));
  td->sample(0.5);
  EXPECT_EQ(x.nb_slices(), 4u);
  EXPECT_EQ(y.nb_slices(), 4u);
  EXPECT_EQ(y.slice(1), Interval(7, 8));
  auto td2 = TDomain::create(0.0, 1.0, 0.5);
  Tube z(td2, Interval(0, 1));
  z = x;  // becomes a copy on x's domain
  EXPECT_EQ(z.tdomain(), td);
  EXPECT_EQ(z, x);
  td->sample(2.5);
  EXPECT_EQ(z.nb_slices(), 5u);
}

TEST(Tube, FromExpressionExactValues) {
  auto td = TDomain::create(std::vector<double>{0.0, 1.0, 2.0});
  Tube x(td, "2*t+1");
  EXPECT_EQ(x.slice(0), Interval(1, 3));
  EXPECT_EQ(x.slice(1), Interval(3, 5));
  EXPECT_EQ(x.gate(0), Interval(1, 1));
  EXPECT_EQ(x.gate(1), Interval(3, 3));
  EXPECT_EQ(x.gate(2), Interval(5, 5));
  Tube c(td, "[-1,1] + 0*t");
  EXPECT_EQ(c.slice(1), Interval(-1, 1));
  EXPECT_THROW(Tube(td, "2*t+"), ParseError);
  EXPECT_THROW(Tube(td, Function({"t", "u"}, "t+u")), DimensionError);
  EXPECT_THROW(Tube(td, Function({"t"}, "(t, t)")), DimensionError);
}

TEST(Tube, FromExpressionContainsAnalyticTrajectory) {
  auto td = TDomain::create(0.0, 20.0, 0.1);
  Tube x(td, "-9/20*cos(t/5) + [-0.001,0.001]");
  EXPECT_GE(x.max_thickness(), 0.002);
  for (std::size_t k = 0; k <= td->nb_slices(); ++k) EXPECT_GE(x.gate(k).diam(), 0.002);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> ut(0.0, 20.0);
  for (int i = 0; i < 2000; ++i) {
    const double t = ut(rng);
    const double v = -9.0 / 20.0 * std::cos(t / 5.0);
    // the thickness 0.002 absorbs any libm error
    ASSERT_TRUE(x(t).contains(v - 0.0009) && x(t).contains(v + 0.0009)) << "t = " << t;
  }
  Tube s(td, "sin(t)");
  EXPECT_TRUE(s.contains(Trajectory("sin(t)", Interval(0, 20))));
  EXPECT_TRUE(s.contains(Trajectory("sin(t)", Interval(-1, 21))));
  EXPECT_FALSE(s.contains(Trajectory("sin(t) + 0.01", Interval(0, 20))));
  for (int i = 0; i < 2000; ++i) {
    const double t = ut(rng);
    if (td->is_time_point(t)) continue;
    ASSERT_TRUE(s(t).contains(std::sin(t))) << "t = " << t;
  }
  EXPECT_THROW((void)s.contains(Trajectory("sin(t)", Interval(0, 10))), Error);
}

TEST(Tube, ContainsSampledTrajectory) {
  auto td = td0123();
  Tube x = small_tube(td);
  // through (0,1) (1,1.5) (2,2.5) (3,4): inside
  Trajectory a(std::vector<double>{0, 1, 2, 3}, std::vector<double>{1, 1.5, 2.5, 4});
  EXPECT_TRUE(x.contains(a));
  // crosses slice 0's top between samples: (0.5, 2.5) leaves [0,2]
  Trajectory b(std::vector<double>{0, 0.5, 1, 2, 3}, std::vector<double>{1, 2.5, 1.5, 2.5, 4});
  EXPECT_FALSE(x.contains(b));
  // misses gate 1 = [1,2] only at t = 1
  Trajectory c(std::vector<double>{0, 1, 2, 3}, std::vector<double>{1, 0.5, 2.5, 4});
  EXPECT_FALSE(x.contains(c));
}

TEST(Tube, NullDomainAndSizeErrors) {
  EXPECT_THROW(Tube(nullptr, Interval(0, 1)), Error);
  auto td = td0123();
  EXPECT_THROW(Tube(td, std::vector<Interval>{Interval(0, 1)}), DimensionError);
  EXPECT_THROW(Tube(td, std::vector<Interval>(3, Interval(0, 1)), std::vector<Interval>(3, Interval(0, 1))),
               DimensionError);
}

// Trajectory: sampled (piecewise-linear) and analytic evaluations, errors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "sillage/error.h"
#include "sillage/tube/trajectory.h"

using namespace sillage;

TEST(TubeTrajectory, SampledExactValues) {
  Trajectory x(std::vector<double>{0, 1, 3}, std::vector<double>{0, 2, -2});
  EXPECT_TRUE(x.is_sampled());
  EXPECT_EQ(x.domain(), Interval(0, 3));
  EXPECT_EQ(x(0.0), Interval(0));
  EXPECT_EQ(x(1.0), Interval(2));
  EXPECT_EQ(x(0.5), Interval(1));
  EXPECT_EQ(x(2.0), Interval(0));
  EXPECT_EQ(x(Interval(0.5, 2.5)), Interval(-1, 2));  // the sample at t = 1 is inside
  EXPECT_EQ(x(Interval(1.5, 2.0)), Interval(0, 1));
  EXPECT_EQ(x(Interval(0, 3)), Interval(-2, 2));
  EXPECT_TRUE(x(Interval::empty()).is_empty());
  EXPECT_THROW(x(3.5), Error);
  EXPECT_THROW(x(Interval(-1, 1)), Error);
  EXPECT_THROW(x(std::numeric_limits<double>::quiet_NaN()), Error);
}

TEST(TubeTrajectory, SampledInterpolationIsRigorous) {
  // x goes from 0 at t = 0 to 1 at t = 3: x(1) = 1/3 is not a double
  Trajectory x(std::map<double, double>{{0.0, 0.0}, {3.0, 1.0}});
  const Interval v = x(1.0);
  EXPECT_LE(static_cast<long double>(v.lb()), 1.0L / 3.0L);
  EXPECT_GE(static_cast<long double>(v.ub()), 1.0L / 3.0L);
  EXPECT_LT(v.diam(), 1e-15);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 3.0);
  for (int i = 0; i < 1000; ++i) {
    const double t = u(rng);
    const long double exact = static_cast<long double>(t) / 3.0L;
    ASSERT_LE(static_cast<long double>(x(t).lb()), exact);
    ASSERT_GE(static_cast<long double>(x(t).ub()), exact);
  }
}

TEST(TubeTrajectory, SetAddsSamples) {
  Trajectory x(std::map<double, double>{{0.0, 0.0}, {2.0, 2.0}});
  x.set(1.0, 5.0);
  EXPECT_EQ(x(1.0), Interval(5));
  EXPECT_EQ(x(0.5), Interval(2.5));
  x.set(4.0, 0.0);
  EXPECT_EQ(x.domain(), Interval(0, 4));
  x.set(1.0, 1.0);  // replaces
  EXPECT_EQ(x(1.0), Interval(1));
  EXPECT_EQ(x.sample_times().size(), 4u);
}

TEST(TubeTrajectory, Analytic) {
  Trajectory x("sin(t)", Interval(0, 10));
  EXPECT_FALSE(x.is_sampled());
  EXPECT_TRUE(x(1.0).contains(std::sin(1.0)) || x(1.0).diam() > 0);
  EXPECT_EQ(x(Interval(0, 4)), sin(Interval(0, 4)));
  EXPECT_THROW(x(11.0), Error);
  EXPECT_THROW(Trajectory("sin(t)", Interval(0, std::numeric_limits<double>::infinity())), Error);
  EXPECT_THROW(Trajectory(Function({"t", "u"}, "t+u"), Interval(0, 1)), DimensionError);
  EXPECT_THROW(x.set(1.0, 1.0), Error);
}

TEST(TubeTrajectory, InvalidSamplesThrow) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(Trajectory(std::map<double, double>{}), Error);
  EXPECT_THROW(Trajectory(std::vector<double>{0, 1}, std::vector<double>{0}), DimensionError);
  EXPECT_THROW(Trajectory(std::vector<double>{0, 1}, std::vector<double>{0, nan}), Error);
  EXPECT_THROW(Trajectory(std::vector<double>{1, 0}, std::vector<double>{0, 0}), Error);
  Trajectory single(std::vector<double>{2.0}, std::vector<double>{7.0});
  EXPECT_EQ(single(2.0), Interval(7));
  EXPECT_EQ(single(Interval(2, 2)), Interval(7));
}

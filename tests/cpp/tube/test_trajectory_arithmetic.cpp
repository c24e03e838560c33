// Trajectory arithmetic (composite trajectories) and TrajectoryVector.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sillage/error.h"
#include "sillage/tube/trajectory_arithmetic.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_builders.h"

using namespace sillage;

namespace {
Trajectory ramp() { return Trajectory(std::vector<double>{0, 1, 3}, std::vector<double>{0, 2, -2}); }
}  // namespace

TEST(TrajectoryArithmetic, ExactValuesAtSamples) {
  const Trajectory x = ramp(), y("2*t", Interval(0, 2));
  const Trajectory s = x + y;
  EXPECT_FALSE(s.is_sampled());
  EXPECT_FALSE(s.is_analytic());
  EXPECT_EQ(s.domain(), Interval(0, 2));  // the intersection
  EXPECT_EQ(s(1.0), Interval(4));
  EXPECT_EQ((x - y)(1.0), Interval(0));
  EXPECT_EQ((x * y)(1.0), Interval(4));
  EXPECT_EQ((x / y)(1.0), Interval(1));
  EXPECT_EQ((-x)(1.0), Interval(-2));
  EXPECT_EQ((x + 1.0)(1.0), Interval(3));
  EXPECT_EQ((1.0 - x)(1.0), Interval(-1));
  EXPECT_EQ((3.0 * x)(1.0), Interval(6));
  EXPECT_EQ((x / 4.0)(1.0), Interval(0.5));
  EXPECT_EQ((8.0 / x)(1.0), Interval(4));
  EXPECT_EQ(sqr(x)(1.0), Interval(4));
  EXPECT_EQ(abs(-x)(1.0), Interval(2));
  EXPECT_EQ(sqrt(sqr(x))(1.0), Interval(2));
  EXPECT_TRUE(exp(x)(0.0).contains(1.0));
  EXPECT_TRUE(cos(x)(0.0).contains(1.0));
  EXPECT_TRUE(atan2(x, x + 0.0)(1.0).contains(std::atan2(2.0, 2.0)));
}

TEST(TrajectoryArithmetic, EnclosesOverIntervalsOfTime) {
  const Trajectory x = ramp();
  const Trajectory d = x - x;  // evaluated independently: an enclosure, not {0}
  EXPECT_EQ(d(Interval(0, 1)), Interval(-2, 2));
  EXPECT_EQ(d(0.5), Interval(0));
  EXPECT_TRUE((x * 2.0)(Interval::empty()).is_empty());
  // Rigorous: every value is inside
  const Trajectory p = x * Trajectory("sin(t)", Interval(0, 3));
  for (double t = 0; t <= 3; t += 0.125) {
    const double xt = t <= 1 ? 2 * t : 2 - 2 * (t - 1);
    EXPECT_TRUE(p(t).contains(xt * std::sin(t))) << t;
  }
  // A tube built from a composite trajectory
  auto td = TDomain::create(0, 3, 0.5);
  const Tube tube = tube_from_data(td, x + 1.0, 0.0);
  EXPECT_EQ(tube.gate(2), Interval(3));
  EXPECT_EQ(tube.slice(1), Interval(2, 3));
}

TEST(TrajectoryArithmetic, Errors) {
  const Trajectory x = ramp(), late("t", Interval(5, 6));
  EXPECT_THROW(x + late, Error);
  EXPECT_THROW(x + std::nan(""), Error);
  EXPECT_THROW((x + 1.0)(4.0), Error);  // outside the domain
  Trajectory c = x * 2.0;
  EXPECT_THROW(c.set(0.5, 1.0), Error);  // only sampled trajectories take samples
}

TEST(TrajectoryVector, SampledAnalyticAndArithmetic) {
  const TrajectoryVector v(std::vector<double>{0, 1, 2}, std::vector<std::vector<double>>{{0, 10}, {1, 11}, {4, 12}});
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v.domain(), Interval(0, 2));
  EXPECT_TRUE(v[0].is_sampled());
  EXPECT_EQ(v(1.0), IntervalVector({Interval(1), Interval(11)}));
  EXPECT_EQ(v(Interval(0, 2)), IntervalVector({Interval(0, 4), Interval(10, 12)}));
  const TrajectoryVector w("(t, 2*t)", Interval(0, 4));
  ASSERT_EQ(w.size(), 2u);
  EXPECT_TRUE(w[1].is_analytic());
  EXPECT_EQ(w(1.0), IntervalVector({Interval(1), Interval(2)}));
  EXPECT_EQ((v + w)(1.0), IntervalVector({Interval(2), Interval(13)}));
  EXPECT_EQ((v + w).domain(), Interval(0, 2));
  EXPECT_EQ((v - w)(2.0), IntervalVector({Interval(2), Interval(8)}));
  EXPECT_EQ((2.0 * v)(1.0), IntervalVector({Interval(2), Interval(22)}));
  EXPECT_EQ((v * w[0])(2.0), IntervalVector({Interval(8), Interval(24)}));
  EXPECT_EQ((v / 2.0)(2.0), IntervalVector({Interval(2), Interval(6)}));
  EXPECT_EQ((-v)(0.0), IntervalVector({Interval(0), Interval(-10)}));
  EXPECT_EQ(TrajectoryVector("t^2", Interval(0, 1)).size(), 1u);
}

TEST(TrajectoryVector, Errors) {
  EXPECT_THROW(TrajectoryVector(std::vector<Trajectory>{}), DimensionError);
  EXPECT_THROW(TrajectoryVector(std::vector<double>{0, 1}, std::vector<std::vector<double>>{{0, 1}}), DimensionError);
  EXPECT_THROW(TrajectoryVector(std::vector<double>{0, 1}, std::vector<std::vector<double>>{{0, 1}, {2}}),
               DimensionError);
  EXPECT_THROW(TrajectoryVector(std::vector<Trajectory>{ramp(), Trajectory("t", Interval(5, 6))}), Error);
  const TrajectoryVector v("(t, t)", Interval(0, 1));
  EXPECT_THROW(v[2], OutOfRangeError);
  EXPECT_THROW(v + TrajectoryVector("t", Interval(0, 1)), DimensionError);
}

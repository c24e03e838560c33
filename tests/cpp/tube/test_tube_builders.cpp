// Tubes from data (3.13): interpolation ± error, two bounds, and data plus
// derivative bounds; hand-computed values and random true trajectories.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sillage/error.h"
#include "sillage/tube/tube_builders.h"

using namespace sillage;

TEST(TubeBuilders, FromDataWithErrorExact) {
  auto td = TDomain::create(std::vector<double>{0.0, 1.0, 2.0});
  Trajectory d(std::vector<double>{0.0, 0.5, 2.0}, std::vector<double>{0.0, 2.0, 1.0});
  Tube x = tube_from_data(td, d, 0.5);
  EXPECT_EQ(x.slice(0), Interval(-0.5, 2.5));  // samples 0, 2 and the interpolation ends
  EXPECT_EQ(x.gate(1), d(1.0) + Interval(-0.5, 0.5));
  EXPECT_EQ(x.gate(0), Interval(-0.5, 0.5));
  EXPECT_EQ(x.gate(2), Interval(0.5, 1.5));
  EXPECT_TRUE(x.contains(d));
  EXPECT_THROW(tube_from_data(td, d, -1.0), Error);
  EXPECT_THROW(tube_from_data(td, d, std::nan("")), Error);
  EXPECT_THROW(tube_from_data(TDomain::create(0.0, 3.0, 1.0), d, 0.1), Error);
}

TEST(TubeBuilders, FromBounds) {
  auto td = TDomain::create(std::vector<double>{0.0, 1.0, 2.0});
  Trajectory lb(std::vector<double>{0.0, 2.0}, std::vector<double>{0.0, 2.0});  // t
  Trajectory ub(std::vector<double>{0.0, 2.0}, std::vector<double>{1.0, 5.0});  // 1 + 2t
  Tube x = tube_from_bounds(td, lb, ub);
  EXPECT_EQ(x.slice(0), Interval(0, 3));
  EXPECT_EQ(x.slice(1), Interval(1, 5));
  EXPECT_EQ(x.gate(1), Interval(1, 3));
  Tube e = tube_from_bounds(td, ub, lb);  // ub above lb everywhere: empty gates
  EXPECT_TRUE(e.gate(1).is_empty());
  EXPECT_TRUE(e.is_empty());
}

TEST(TubeBuilders, FromDataAndDerivativeExact) {
  auto td = TDomain::create(std::vector<double>{0.0, 1.0, 2.0, 3.0});
  // samples x(0) = 0, x(2) = 0 exactly, |x'| <= 1
  Trajectory d(std::vector<double>{0.0, 2.0}, std::vector<double>{0.0, 0.0});
  Tube x = tube_from_data(td, d, 0.0, Interval(-1, 1));
  EXPECT_EQ(x.gate(0), Interval(0, 0));
  EXPECT_EQ(x.gate(1), Interval(-1, 1));  // [-1,1] from both sides
  EXPECT_EQ(x.gate(2), Interval(0, 0));
  EXPECT_EQ(x.slice(0), Interval(-1, 1));  // forward [0,1]*[-1,1] ∩ backward [1,2]*[-1,1]
  EXPECT_EQ(x.gate(3), Interval(-1, 1));  // after the last sample: forward only
  EXPECT_EQ(x.slice(2), Interval(-1, 1));
  Tube y = tube_from_data(td, d, 0.5, Interval(0, 1));  // x' >= 0: x(1) in [-0.5,0.5]
  EXPECT_EQ(y.gate(1), Interval(-0.5, 0.5));
  EXPECT_THROW(tube_from_data(td, Trajectory("t", Interval(0, 3)), 0.0, Interval(-1, 1)), Error);
  EXPECT_THROW(tube_from_data(td, d, 0.0, Interval::empty()), Error);
}

TEST(TubeBuilders, FromDataAndDerivativeIsTightOnWideSlices) {
  // one slice over both samples: the hull of the diamond is [-1, 1], not the
  // [-2, 2] that the forward and backward cones give separately
  Trajectory d(std::vector<double>{0.0, 2.0}, std::vector<double>{0.0, 0.0});
  Tube x = tube_from_data(TDomain::create(std::vector<double>{0.0, 2.0}), d, 0.0, Interval(-1, 1));
  EXPECT_EQ(x.slice(0), Interval(-1, 1));
  // asymmetric: x(0) = 0, x(3) = 1, x' in [0, 1]: x <= min(t, 1), x >= max(0, t - 2)
  Trajectory e(std::vector<double>{0.0, 3.0}, std::vector<double>{0.0, 1.0});
  Tube y = tube_from_data(TDomain::create(std::vector<double>{0.0, 1.5, 3.0}), e, 0.0, Interval(0, 1));
  EXPECT_EQ(y.slice(0), Interval(0, 1));
  EXPECT_EQ(y.slice(1), Interval(0, 1));
  EXPECT_EQ(y.gate(1), Interval(0, 1));
  Tube z = tube_from_data(TDomain::create(std::vector<double>{0.0, 3.0}), e, 0.0, Interval(0, 0.2));
  EXPECT_TRUE(z.is_empty());  // no x' <= 0.2 climbs 1 in 3
}

TEST(TubeBuilders, RandomTrueTrajectoriesStayInside) {
  // truth x(t) = sin(2t) + 0.3 t (|x'| <= 2.3), sampled with error <= 0.01
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> noise(-0.01, 0.01), u(0.0, 10.0);
  auto truth = [](double t) { return std::sin(2 * t) + 0.3 * t; };
  std::vector<double> ts, ys;
  for (double t = 0.0; t <= 10.0; t += 0.37) {
    ts.push_back(t);
    ys.push_back(truth(t) + noise(rng));
  }
  for (double dt : {0.1, 0.83, 2.9}) {  // slices finer and coarser than the samples
    auto td = TDomain::create(-0.5, 10.5, dt);  // beyond the data on both sides
    const Tube x = tube_from_data(td, Trajectory(ts, ys), 0.01, Interval(-2.3, 2.3));
    EXPECT_FALSE(x.is_empty());
    if (dt < 0.5) {
      // (over wide slices the natural enclosure of the analytic truth is too
      // loose for contains() to prove anything: only pointwise checks there)
      EXPECT_TRUE(x.contains(Trajectory("sin(2*t) + 0.3*t", Interval(-0.5, 10.5))));
      EXPECT_LT(x.slice(50).diam(), 1.0);
    }
    for (std::size_t k = 0; k <= td->nb_slices(); ++k) {
      ASSERT_TRUE(x.gate(k).inflate(1e-9).contains(truth(td->t(k)))) << "gate " << k << ", dt = " << dt;
    }
    for (int i = 0; i < 2000; ++i) {
      const double t = u(rng);
      ASSERT_TRUE(x(t).inflate(1e-9).contains(truth(t))) << "t = " << t << ", dt = " << dt;
    }
  }
}

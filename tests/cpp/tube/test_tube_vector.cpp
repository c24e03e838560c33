// TubeVector: construction, live component references, evaluation.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sillage/error.h"
#include "sillage/tube/tube_arithmetic.h"
#include "sillage/tube/tube_vector.h"

using namespace sillage;

TEST(TubeVector, ConstantAndBox) {
  auto td = TDomain::create(std::vector<double>{0.0, 1.0, 2.0});
  TubeVector x(td, 3, Interval(0, 1));
  EXPECT_EQ(x.size(), 3u);
  EXPECT_EQ(x.nb_slices(), 2u);
  EXPECT_EQ(x(0.5), IntervalVector(3, Interval(0, 1)));
  TubeVector y(td, IntervalVector{Interval(0, 1), Interval(2, 4)});
  EXPECT_EQ(y[1].slice(1), Interval(2, 4));
  EXPECT_EQ(y.volume(), 4.0);  // 2 slices * (1 * 2)
  EXPECT_EQ(y.codomain(), (IntervalVector{Interval(0, 1), Interval(2, 4)}));
  EXPECT_THROW(TubeVector(td, 0), DimensionError);
  EXPECT_THROW((void)y[2], OutOfRangeError);  // an index, like Tube::slice(k)
}

TEST(TubeVector, ComponentsAreLiveReferences) {
  auto td = TDomain::create(std::vector<double>{0.0, 1.0, 2.0});
  TubeVector x(td, 2, Interval(0, 10));
  x[1].set(Interval(1, 2), 0);
  EXPECT_EQ(x.slice(0), (IntervalVector{Interval(0, 10), Interval(1, 2)}));
  Tube& r = x[0];
  r &= Tube(td, Interval(3, 4));
  EXPECT_EQ(x(Interval(0, 2))[0], Interval(3, 4));
  td->sample(0.5);
  EXPECT_EQ(x.nb_slices(), 3u);
  EXPECT_EQ(x[1].slice(1), Interval(1, 2));
  const TubeVector s = x.subvector(1, 1);
  EXPECT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0], x[1]);
  EXPECT_THROW(x.subvector(1, 2), DimensionError);
}

TEST(TubeVector, FromVectorExpression) {
  auto td = TDomain::create(0.0, 6.0, 0.05);
  TubeVector x(td, "(cos(t), sin(t) + [-0.01,0.01])");
  ASSERT_EQ(x.size(), 2u);
  EXPECT_EQ(x[0], Tube(td, "cos(t)"));  // the same evaluation as the scalar one
  std::vector<Trajectory> truth{Trajectory("cos(t)", Interval(0, 6)), Trajectory("sin(t)", Interval(0, 6))};
  EXPECT_TRUE(x.contains(truth));
  std::vector<Trajectory> off{Trajectory("cos(t)", Interval(0, 6)), Trajectory("sin(t)+0.02", Interval(0, 6))};
  EXPECT_FALSE(x.contains(off));
  EXPECT_THROW((void)x.contains({truth[0]}), DimensionError);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 6.0);
  for (int i = 0; i < 500; ++i) {
    const double t = u(rng);
    if (td->is_time_point(t)) continue;
    const IntervalVector v = x(t);
    ASSERT_TRUE(v[0].contains(std::cos(t)));
    ASSERT_TRUE(v[1].contains(std::sin(t)));
  }
}

TEST(TubeVector, SetAndCompare) {
  auto td = TDomain::create(std::vector<double>{0.0, 1.0, 2.0});
  TubeVector x(td, 2, Interval(0, 10));
  TubeVector y = x;
  y.set(IntervalVector{Interval(1, 2), Interval(3, 4)}, 1);
  EXPECT_TRUE(y.is_subset(x));
  EXPECT_FALSE(x.is_subset(y));
  EXPECT_EQ(y.gate(1), (IntervalVector{Interval(1, 2), Interval(3, 4)}));
  y.set_gate(0, IntervalVector{Interval(5), Interval(5)});
  EXPECT_EQ(y.gate(0), (IntervalVector{Interval(5), Interval(5)}));
  TubeVector z = x;
  z &= y;
  EXPECT_EQ(z, y);
  z |= x;
  EXPECT_EQ(z, x);
  EXPECT_THROW(x.set(IntervalVector(3)), DimensionError);
  EXPECT_THROW(x &= TubeVector(td, 3), DimensionError);
  EXPECT_EQ(x.max_thickness(), 10.0);
  EXPECT_FALSE(x.is_empty());
}

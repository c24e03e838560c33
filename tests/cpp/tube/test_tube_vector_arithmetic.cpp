// Component-wise tube vector arithmetic and inversion.
#include <gtest/gtest.h>

#include <vector>

#include "sillage/error.h"
#include "sillage/tube/tube_arithmetic.h"
#include "sillage/tube/tube_vector_arithmetic.h"

using namespace sillage;

namespace {
Tube ramp(const std::shared_ptr<TDomain>& td, double shift) {
  return Tube(td, std::vector<Interval>{Interval(0, 1) + shift, Interval(0.5, 2) + shift, Interval(1, 3) + shift});
}
}  // namespace

TEST(TubeVectorArithmetic, Componentwise) {
  auto td = TDomain::create(0, 3, 1);
  const TubeVector v(std::vector<Tube>{ramp(td, 0), ramp(td, 1)});
  const Tube x = ramp(td, 0);
  EXPECT_EQ((v + v)[1].slice(0), Interval(2, 4));
  EXPECT_EQ((v - v)[0].slice(2), Interval(-2, 2));
  EXPECT_EQ((v * x)[1], x * ramp(td, 1));
  EXPECT_EQ((x * v)[0], x * x);
  EXPECT_EQ((v / Interval(2))[0].slice(2), Interval(0.5, 1.5));
  EXPECT_EQ((Interval(1) - v)[0].gate(0), Interval(0, 1));
  const IntervalVector box{Interval(0, 1), Interval(10)};
  EXPECT_EQ((v + box)[1].slice(0), Interval(11, 12));
  EXPECT_EQ((box - v)[1], Interval(10) - ramp(td, 1));
  EXPECT_EQ((box * v)[0].slice(1), Interval(0, 2));
  EXPECT_EQ((-v)[0], -x);
  EXPECT_THROW(v + TubeVector(td, 3), DimensionError);
  EXPECT_THROW(v + IntervalVector(3), DimensionError);
  EXPECT_THROW(v + Tube(TDomain::create(0, 3, 1)), DimensionError);
}

TEST(TubeVectorArithmetic, Inverse) {
  auto td = TDomain::create(0, 3, 1);
  const TubeVector v(std::vector<Tube>{ramp(td, 0), ramp(td, 1)});
  EXPECT_EQ(inverse(v, IntervalVector{Interval(0.2, 0.4), Interval(1.2, 1.4)}), Interval(0, 1));
  EXPECT_EQ(inverse(v, IntervalVector{Interval(0.6, 0.7), Interval(1.6, 1.7)}), Interval(0, 2));
  EXPECT_TRUE(inverse(v, IntervalVector{Interval(5, 6), Interval(0, 9)}).is_empty());
  // Both components at once: tighter than intersecting the components' inverses
  const Tube a(td, std::vector<Interval>{Interval(0, 1), Interval(1, 5), Interval(0, 1)});
  const Tube b(td, std::vector<Interval>{Interval(4, 5), Interval(0, 4), Interval(4, 5)});
  const Interval y(0, 0.5);
  EXPECT_EQ(a.inverse(y), Interval(0, 3));
  EXPECT_EQ(b.inverse(y), Interval(1, 2));
  EXPECT_TRUE(inverse(TubeVector(std::vector<Tube>{a, b}), IntervalVector{y, y}).is_empty());
  EXPECT_THROW(inverse(v, IntervalVector(3)), DimensionError);
}

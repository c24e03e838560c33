// Expressions undefined at a gate or on a slice (issue 12, item 2): the
// natural form encloses f over the part of its argument where f is defined;
// where f is defined nowhere, nothing is known (the whole line), so the tube
// is not empty. Also: a gate off its neighbouring slices is taken as given.
#include <gtest/gtest.h>

#include "sillage/error.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_integral.h"
#include "sillage/tube/tube_vector.h"

using namespace sillage;

TEST(TubeUndefined, SingularAtTheFirstGate) {
  auto td = TDomain::create(0.0, 10.0, 0.1);
  for (const char* e : {"sin(t)/t", "log(t)", "1/t", "t*log(t)", "atan2(t, t)"}) {
    const Tube v(td, e);
    EXPECT_FALSE(v.is_empty()) << e;
    EXPECT_TRUE(v.gate(0).is_all_reals()) << e;  // undefined at t = 0: nothing known
    EXPECT_FALSE(v.slice(0).is_empty()) << e;    // defined on (0, 0.1]
    EXPECT_FALSE(v(5.0).is_empty()) << e;
    EXPECT_FALSE(integral(v, 10.0).is_empty()) << e;
    EXPECT_FALSE(v.codomain().is_empty()) << e;
    for (std::size_t k = 1; k <= v.nb_slices(); ++k) ASSERT_TRUE(v.gate(k).is_bounded()) << e << " gate " << k;
  }
  const Tube s(td, "sin(t)/t");
  EXPECT_TRUE(s.slice(0).contains(1.0));
  EXPECT_EQ(Tube(td, "1/t").slice(0), Interval(1.0) / Interval(0.0, td->t(1)));  // [10, inf) up to t_1's rounding
  EXPECT_TRUE(Tube(td, "atan2(t, t)").slice(0).is_superset(Interval::pi() / 4));
}

TEST(TubeUndefined, SlicesOutsideTheDomain) {
  auto td = TDomain::create(0.0, 10.0, 1.0);
  const Tube x(td, "sqrt(t - 4.5)");
  EXPECT_FALSE(x.is_empty());
  for (std::size_t k = 0; k < 4; ++k) EXPECT_TRUE(x.slice(k).is_all_reals()) << k;  // defined nowhere
  EXPECT_EQ(x.slice(4), sqrt(Interval(-0.5, 0.5)));  // over [4.5, 5] only
  EXPECT_TRUE(x.gate(4).is_all_reals());
  EXPECT_EQ(x.gate(9), sqrt(Interval(4.5)));
  const TubeVector v(td, "(sin(t)/t, sqrt(t - 4.5))");
  EXPECT_FALSE(v.is_empty());
  EXPECT_EQ(v[0], Tube(td, "sin(t)/t"));
  EXPECT_EQ(v[1], x);
}

// A gate disjoint from a neighbouring slice is not malformed input: the tube
// holds no continuous trajectory, an answer that CtcDeriv and a network give
// (tests/cpp/cn/test_cn_emptiness.cpp). Wrong sizes are still refused.
TEST(TubeUndefined, AGateOffItsSlicesIsTakenAsGiven) {
  auto td = TDomain::create(std::vector<double>{0.0, 1.0, 2.0});
  const std::vector<Interval> slices = {Interval(0, 1), Interval(2, 3)};
  const std::vector<Interval> gates = {Interval(5), Interval(1.5), Interval(4)};
  const Tube x(td, slices, gates);
  EXPECT_EQ(std::vector<Interval>(x.slices().begin(), x.slices().end()), slices);
  EXPECT_EQ(std::vector<Interval>(x.gates().begin(), x.gates().end()), gates);
  EXPECT_FALSE(x.is_empty());  // each slice and gate alone is not empty
  EXPECT_THROW(Tube(td, slices, {Interval(0.5), Interval(1)}), DimensionError);
  EXPECT_THROW(Tube(td, {Interval(0, 1)}, gates), DimensionError);
}

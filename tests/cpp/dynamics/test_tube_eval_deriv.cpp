// Tube::eval(t, v) and Tube::inverse(y, v): the polygon of each slice, hand
// cases and, on random tubes around a known trajectory, containment of the
// truth and inclusion in the derivative-free answers.
#include <gtest/gtest.h>

#include <random>

#include "deriv_test_util.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/error.h"

using namespace sillage;
using sillage::test::SineSum;

namespace {

// One slice [0, 1], gates 0 and 0, v = [-1, 1]: the diamond of half-height 1/2.
struct Diamond {
  std::shared_ptr<TDomain> td = TDomain::create(std::vector<double>{0.0, 1.0});
  Tube x{td, std::vector<Interval>{Interval()}, std::vector<Interval>{Interval(0), Interval(0)}};
  Tube v{td, Interval(-1, 1)};
};

}  // namespace

TEST(TubeEvalDeriv, DiamondPoints) {
  Diamond d;
  EXPECT_EQ(d.x.eval(0.5, d.v), Interval(-0.5, 0.5));
  EXPECT_EQ(d.x.eval(0.25, d.v), Interval(-0.25, 0.25));
  EXPECT_EQ(d.x.eval(0.75, d.v), Interval(-0.25, 0.25));
  EXPECT_EQ(d.x.eval(0.0, d.v), Interval(0));
  EXPECT_EQ(d.x.eval(1.0, d.v), Interval(0));
  EXPECT_EQ(d.x(0.5), Interval());  // the slice box knows nothing
}

TEST(TubeEvalDeriv, DiamondIntervals) {
  Diamond d;
  EXPECT_EQ(d.x.eval(Interval(0, 0.25), d.v), Interval(-0.25, 0.25));
  EXPECT_EQ(d.x.eval(Interval(0.25, 0.75), d.v), Interval(-0.5, 0.5));
  EXPECT_EQ(d.x.eval(Interval(0, 1), d.v), Interval(-0.5, 0.5));
  EXPECT_EQ(d.x.eval(Interval(0.625, 1), d.v), Interval(-0.375, 0.375));
  EXPECT_TRUE(d.x.eval(Interval::empty(), d.v).is_empty());
  EXPECT_THROW(d.x.eval(Interval(0.5, 2), d.v), Error);
  EXPECT_THROW(d.x.eval(Interval(-1), d.v), Error);
}

TEST(TubeEvalDeriv, DiamondInverse) {
  Diamond d;
  EXPECT_EQ(d.x.inverse(Interval(0.25, 1), d.v), Interval(0.25, 0.75));
  EXPECT_EQ(d.x.inverse(Interval(-1, -0.5), d.v), Interval(0.5));
  EXPECT_EQ(d.x.inverse(Interval(0), d.v), Interval(0, 1));
  EXPECT_TRUE(d.x.inverse(Interval(2, 3), d.v).is_empty());
  EXPECT_TRUE(d.x.inverse(Interval::empty(), d.v).is_empty());
  EXPECT_EQ(d.x.inverse(Interval(0.25, 1)), Interval(0, 1));  // without v: the whole slice
}

TEST(TubeEvalDeriv, GateSeenFromBothSlices) {
  // Two slices; gate 1 unknown, gate 0 = 0, gate 2 = 2, v = [0, 1]. At t = 1
  // slice 0 allows [0, 1], slice 1 allows [1, 2]: x(1) = 1.
  auto td = TDomain::create(std::vector<double>{0.0, 1.0, 2.0});
  Tube x(td, std::vector<Interval>{Interval(), Interval()}, std::vector<Interval>{Interval(0), Interval(), Interval(2)});
  Tube v(td, Interval(0, 1));
  EXPECT_EQ(x.eval(1.0, v), Interval(1));
  // Over an interval each slice is read alone (eval does not contract):
  // slice 0 on [0.5, 1] gives [0, 1], slice 1 on [1, 1.5] gives [1, 2].
  EXPECT_EQ(x.eval(Interval(0.5, 1.5), v), Interval(0, 2));
  EXPECT_EQ(x.inverse(Interval(1.5, 5), v), Interval(1, 2));
  // Once contracted, gate 1 = 1 and the polygons are the tight ones.
  CtcDeriv().contract(x, v);
  EXPECT_EQ(x.gate(1), Interval(1));
  EXPECT_EQ(x.eval(Interval(0.5, 1.5), v), Interval(0.5, 1.5));
  EXPECT_EQ(x.inverse(Interval(1.5, 5), v), Interval(1.5, 2));
}

TEST(TubeEvalDeriv, UnboundedAndEmpty) {
  auto td = TDomain::create(std::vector<double>{0.0, 1.0});
  Tube x(td, std::vector<Interval>{Interval(-3, 3)}, std::vector<Interval>{Interval(0), Interval()});
  // Nondecreasing: x(t) in [0, 3].
  const Tube up(td, Interval(0, rounding::kInf));
  EXPECT_EQ(x.eval(0.5, up), Interval(0, 3));
  EXPECT_EQ(x.inverse(Interval(-2, -1), up), Interval::empty());
  // Whole line: nothing but the slice.
  const Tube any(td);
  EXPECT_EQ(x.eval(0.5, any), Interval(-3, 3));
  EXPECT_EQ(x.inverse(Interval(-2, -1), any), Interval(0, 1));
  // Empty derivative or gate: no trajectory.
  EXPECT_TRUE(x.eval(0.5, Tube(td, Interval::empty())).is_empty());
  EXPECT_TRUE(x.inverse(Interval(0), Tube(td, Interval::empty())).is_empty());
  Tube y(td, std::vector<Interval>{Interval(-3, 3)});
  y.set_gate(0, Interval(0));
  y.set_gate(1, Interval(5));  // off the slice: no trajectory
  EXPECT_TRUE(y.eval(0.5, Tube(td, Interval(-1, 1))).is_empty());
  // Errors.
  EXPECT_THROW(x.eval(0.5, Tube(TDomain::create(0.0, 1.0, 0.5))), DimensionError);
  EXPECT_THROW(x.inverse(Interval(0), Tube(TDomain::create(0.0, 1.0, 0.5))), DimensionError);
}

TEST(TubeEvalDeriv, LongRangeUsesSlices) {
  // 1000 slices, x = t ± 0.1 with v = 1: eval over a long range is the hull
  // of the interior slices and of the two end polygons.
  auto td = TDomain::create(0.0, 10.0, 0.01);
  Tube x(td, "t + [-0.1, 0.1]"), v(td, Interval(1));
  const Interval r = x.eval(Interval(0.005, 9.995), v);
  EXPECT_TRUE(r.is_subset(x(Interval(0.005, 9.995))));
  EXPECT_LE(r.lb(), 0.005 - 0.1 + 1e-9);
  EXPECT_GE(r.ub(), 9.995 + 0.1 - 1e-9);
}

TEST(TubeEvalDeriv, RandomTubesContainTruthAndAreTighter) {
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 200; ++trial) {
    SineSum f(rng);
    const auto td = sillage::test::random_tdomain(rng, std::uniform_int_distribution<int>(1, 20)(rng));
    std::uniform_real_distribution<double> e(1e-6, 0.3), u(0, 1);
    const std::size_t n = td->nb_slices();
    std::vector<Interval> xs(n), gs(n + 1), vs(n);
    for (std::size_t k = 0; k < n; ++k) {
      const Interval xt = f.x(td->slice_domain(k)), vt = f.v(td->slice_domain(k));
      xs[k] = Interval(rounding::next_down(xt.lb() - e(rng)), rounding::next_up(xt.ub() + e(rng)));
      vs[k] = Interval(vt.lb() - e(rng), vt.ub() + e(rng));
    }
    for (std::size_t k = 0; k <= n; ++k) {
      const Interval g = f.x(Interval(td->t(k)));
      gs[k] = u(rng) < 0.5 ? xs[std::min(k, n - 1)]
                           : Interval(rounding::next_down(g.lb() - e(rng)), rounding::next_up(g.ub() + e(rng)));
    }
    Tube x(td, xs, gs);
    const Tube v(td, vs);
    if (trial % 2) {
      ASSERT_TRUE(CtcDeriv().contract(x, v));
    }
    std::uniform_real_distribution<double> ut(td->t0(), td->tf());
    for (int i = 0; i < 30; ++i) {
      double a = ut(rng), b = ut(rng);
      if (i % 5 == 0) b = a;
      if (i % 7 == 0) a = td->t(std::uniform_int_distribution<std::size_t>(0, n)(rng));
      if (a > b) std::swap(a, b);
      const Interval t(a, b);
      const Interval r = x.eval(t, v);
      ASSERT_TRUE(r.is_subset(x(t))) << trial;
      for (int j = 0; j <= 4; ++j) {
        const double s = a + (b - a) * j / 4;
        if (s < a || s > b) continue;
        ASSERT_TRUE(f.x(Interval(s)).is_subset(r)) << trial << " t = " << s << " " << r;
      }
      // inverse: a time where the truth is in y is kept.
      const Interval y = f.x(Interval(a)).inflate(u(rng) * 0.2);
      const Interval inv = x.inverse(y, v);
      ASSERT_TRUE(inv.contains(a)) << trial << " " << inv << " a = " << a;
      ASSERT_TRUE(inv.is_subset(x.inverse(y))) << trial;
    }
  }
}

TEST(TubeEvalDeriv, InverseRestrictedToATimeInterval) {
  // y(t) = t on [0, 10]: the times where y meets [3, 7], within [2, 5] -> [3, 5].
  auto td = TDomain::create(0.0, 10.0, 0.5);
  const Tube y(td, "t"), w(td, Interval(1.0));
  const Interval all = y.inverse(Interval(3, 7), w);
  const Interval part = y.inverse(Interval(3, 7), w, Interval(2, 5));
  EXPECT_TRUE(part.is_superset(Interval(3, 5)));
  EXPECT_TRUE(part.is_subset(Interval(2.999999, 5.0)));
  EXPECT_TRUE(part.is_subset(all));
  EXPECT_TRUE(y.inverse(Interval(3, 7), w, Interval(8, 9)).is_empty());
  EXPECT_THROW(y.inverse(Interval(3, 7), w, Interval(9, 11)), Error);
}

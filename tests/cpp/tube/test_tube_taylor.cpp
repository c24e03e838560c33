// Primitives from Taylor increments (tube_taylor.h): exact values on a linear
// integrand, truth containment with noise, second-order tightness, errors.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sillage/error.h"
#include "sillage/tube/trajectory.h"
#include "sillage/tube/tube_integral.h"
#include "sillage/tube/tube_taylor.h"

using namespace sillage;

TEST(TubeTaylor, LinearIntegrandIsIntegratedExactly) {
  // w(t) = t, w' = 1 on [0, 1], δ = 1/2: ∫_0^{1/2} t = 1/8 from either gate.
  auto td = TDomain::create(0.0, 1.0, 0.5);
  const Tube w(td, "t"), dw(td, Interval(1.0));
  const auto inc = taylor_increments(w, dw);
  ASSERT_EQ(inc.size(), 2u);
  EXPECT_EQ(inc[0], Interval(0.125));
  EXPECT_EQ(inc[1], Interval(0.375));
  const Tube p = primitive_taylor(w, dw, Interval(0.0));
  EXPECT_EQ(p.gate(0), Interval(0.0));
  EXPECT_EQ(p.gate(1), Interval(0.125));
  EXPECT_EQ(p.gate(2), Interval(0.5));
  // Slices from both gates and the slopes [0, 1/2], [1/2, 1].
  EXPECT_EQ(p.slice(0), Interval(0.0, 0.125));
  EXPECT_EQ(p.slice(1), Interval(0.125, 0.5));
}

TEST(TubeTaylor, NoisyIntegrandKeepsEveryTruthAndIsSecondOrder) {
  // x = sin(t) + a sin(7t), |a| <= 0.01: p(t) = 1 - cos t + a (1 - cos 7t)/7.
  auto td = TDomain::create(0.0, 10.0, 0.01);
  const Interval noise(-0.01, 0.01);
  const Tube w(td, "sin(t)"), dw(td, "cos(t)");
  const Tube p = primitive_taylor(w, dw, Interval(0.0), noise);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.01, 0.01);
  for (int i = 0; i < 20; ++i) {
    const double a = i == 0 ? 0.01 : i == 1 ? -0.01 : u(rng);
    const Trajectory truth("1 - cos(t) + " + std::to_string(a) + "*(1 - cos(7*t))/7", td->t0_tf());
    EXPECT_TRUE(p.contains(truth)) << a;
  }
  // The plain primitive of w + noise is first order in δ: much wider.
  const Tube plain = primitive(Tube(td, "sin(t) + [-0.01, 0.01]"), Interval(0.0));
  const double end = p.gate(td->nb_slices()).diam(), end_plain = plain.gate(td->nb_slices()).diam();
  EXPECT_LT(end, 0.2 + 1e-3);  // 2 * 0.01 * 10: the noise alone, plus O(δ² T)
  EXPECT_LT(end, end_plain - 0.05) << end << " vs plain " << end_plain;
}

TEST(TubeTaylor, KnownGatesAreIntersected) {
  auto td = TDomain::create(0.0, 1.0, 0.25);
  const Tube x(td, Interval(-1, 1));
  const std::vector<Interval> inc(4, Interval(-0.25, 0.25));
  std::vector<Interval> gates(5);
  gates[4] = Interval(0.0);  // known final value: the backward pass uses it
  const Tube p = primitive_from_increments(x, inc, Interval(0.0), gates);
  EXPECT_EQ(p.gate(2), Interval(-0.5, 0.5));
  EXPECT_EQ(p.gate(3), Interval(-0.25, 0.25));
}

TEST(TubeTaylor, Errors) {
  auto td = TDomain::create(0.0, 1.0, 0.25), other = TDomain::create(0.0, 1.0, 0.5);
  EXPECT_THROW(taylor_increments(Tube(td), Tube(other)), DimensionError);
  EXPECT_THROW(primitive_from_increments(Tube(td), std::vector<Interval>(3), Interval(0.0)), DimensionError);
  EXPECT_THROW(primitive_from_increments(Tube(td), std::vector<Interval>(4), Interval(0.0), std::vector<Interval>(4)),
               DimensionError);
}

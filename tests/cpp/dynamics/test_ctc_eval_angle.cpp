// CtcEvalAngle: z = x(t) for a heading known modulo 2π at an uncertain time.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "sillage/cn/contractor_network.h"
#include "sillage/dynamics/ctc_eval_angle.h"
#include "sillage/error.h"
#include "sillage/interval/angle.h"

using namespace sillage;

namespace {

// The heading turns at 1 rad/s from 0.05: ψ(t) = t + 0.05, known nowhere.
TEST(CtcEvalAngle, AnArcAtAnUncertainTimeNarrowsTheGatesAroundIt) {
  const auto td = TDomain::create(0, 10, 0.5);
  Tube x(td), v(td, Interval(0.9, 1.1));
  const Interval t(5.1, 5.3);  // the true time 5.2: ψ = 5.25 ≡ 5.25 - 2π
  Interval z = Interval(5.25).inflate(0.02) - Interval(2 * M_PI);
  ASSERT_TRUE(CtcEvalAngle().contract(t, z, x, v));
  // Gates 10 (t = 5) and 11 (5.5): z + [0.9, 1.1] (τ - [t]).
  for (const std::size_t k : {10u, 11u}) {
    const double truth = td->t(k) + 0.05;
    EXPECT_TRUE(angle_contains(x.gate(k), truth)) << k << " " << x.gate(k);
    EXPECT_LT(x.gate(k).diam(), 0.04 + 2 * 0.4 * 1.1) << k;
  }
  EXPECT_TRUE(angle_contains(x.slice(10), 5.3));
  EXPECT_TRUE(x.gate(0).is_unbounded());  // only the region of [t]
  EXPECT_TRUE(angle_contains(z, 5.25));
}

TEST(CtcEvalAngle, TheTubeNarrowsTheMeasurementAndEmptinessIsReported) {
  const auto td = TDomain::create(0, 10, 0.5);
  Tube x(td, Interval(1.0, 1.2) + Interval(4 * M_PI)), v(td, Interval(-0.1, 0.1));
  Interval z(-10, 10);  // nothing measured
  ASSERT_TRUE(CtcEvalAngle().contract(Interval(3, 3.2), z, x, v));
  EXPECT_TRUE(angle_contains(z, 1.1));
  EXPECT_LT(z.diam(), 0.2 + 2 * 0.1 * 0.2 + 1e-9);
  Interval far = Interval(2.5, 2.6);  // not reachable from [1, 1.2] (mod 2π) in 0.2 s at 0.1 rad/s
  EXPECT_FALSE(CtcEvalAngle().contract(Interval(3, 3.2), far, x, v));
  EXPECT_TRUE(x.is_empty());
  EXPECT_TRUE(far.is_empty());
}

TEST(CtcEvalAngle, OutsideTheDomainSaysNothingAndMismatchedTubesAreAnError) {
  const auto td = TDomain::create(0, 10, 0.5);
  Tube x(td), v(td, Interval(1.0));
  Interval z(0.1, 0.2);
  EXPECT_TRUE(CtcEvalAngle().contract(Interval(20, 21), z, x, v));
  EXPECT_EQ(z, Interval(0.1, 0.2));
  Tube w(TDomain::create(0, 10, 1));
  EXPECT_THROW(CtcEvalAngle().contract(Interval(1), z, x, w), DimensionError);
}

TEST(CtcEvalAngle, InANetworkWithItsDerivative) {
  const auto td = TDomain::create(0, 10, 0.5);
  auto x = std::make_shared<Tube>(td);
  auto v = std::make_shared<Tube>(td, Interval(0.9, 1.1));
  auto t = std::make_shared<Interval>(5.1, 5.3);
  auto z = std::make_shared<Interval>(Interval(5.25).inflate(0.02) + Interval(2 * M_PI));
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcEvalAngle>(), {t, z, x, v});
  cn.contract();
  EXPECT_TRUE(angle_contains(x->gate(10), 5.05));
  EXPECT_LT(x->gate(10).diam(), 1.0);
  EXPECT_THROW(cn.add(std::make_shared<CtcEvalAngle>(), {x, z, x, v}), DimensionError);
}

}  // namespace

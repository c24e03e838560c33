// CtcDerivAngle: x' = v for a heading known modulo 2π. A true heading that
// turns many times, enclosed by representatives shifted by random turns,
// stays on every contracted arc; a known start and rate give the exact lift;
// a bearing-like fix late in the mission narrows the past back below a turn.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_deriv_angle.h"
#include "sillage/error.h"
#include "sillage/interval/angle.h"
#include "sillage/interval/elementary.h"

using namespace sillage;

namespace {

const double kTwoPi = 2 * M_PI;

// A heading that turns: ψ(t) = 0.7 t + 0.5 sin(1.3 t), ψ' = 0.7 + 0.65 cos(1.3 t).
double psi(double t) { return 0.7 * t + 0.5 * std::sin(1.3 * t); }
Interval rate(const Interval& t) { return Interval(0.7) + Interval(0.65) * cos(Interval(1.3) * t); }

TEST(CtcDerivAngle, TheTruthStaysOnEveryArcWhateverTheTurnsOfTheRepresentatives) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> turns(-5, 5);
  std::uniform_real_distribution<double> margin(0.01, 2.5);
  for (int trial = 0; trial < 40; ++trial) {
    const auto td = TDomain::create(0, 30, 0.25);
    const std::size_t n = td->nb_slices();
    Tube v(td), x(td);
    std::vector<Interval> s(n), g(n + 1);
    for (std::size_t k = 0; k < n; ++k) {
      v.set(rate(td->slice_domain(k)).inflate(0.05), k);
      const Interval truth(std::min(psi(td->t(k)), psi(td->t(k + 1))) - 0.6, std::max(psi(td->t(k)), psi(td->t(k + 1))) + 0.6);
      x.set(truth.inflate(margin(rng)) + Interval(turns(rng) * kTwoPi), k);
    }
    for (std::size_t k = 0; k <= n; ++k) {
      const Interval around = Interval(psi(td->t(k))).inflate(k % 7 == 0 ? 0.01 : margin(rng));
      x.set_gate(k, k % 5 == 3 ? Interval() : around + Interval(turns(rng) * kTwoPi));
    }
    const Tube before = x;
    ASSERT_TRUE(CtcDerivAngle().contract(x, v));
    for (std::size_t k = 0; k < n; ++k) {
      ASSERT_TRUE(x.slice(k).is_subset(before.slice(k)));
      ASSERT_TRUE(x.gate(k).is_subset(before.gate(k)));
      ASSERT_TRUE(angle_contains(x.gate(k), psi(td->t(k)))) << "gate " << k << " " << x.gate(k);
      for (int j = 0; j <= 4; ++j) {
        const double t = td->t(k) + (td->t(k + 1) - td->t(k)) * j / 4;
        ASSERT_TRUE(angle_contains(x.slice(k), psi(t))) << "slice " << k << " " << x.slice(k) << " at " << t;
      }
    }
    // Somewhere it shrank: gates 0, 7, 14... were 0.02 wide.
    EXPECT_LT(x.gate(1).diam(), before.gate(1).diam() + 1e-9);
  }
}

TEST(CtcDerivAngle, AKnownStartAndRateGiveTheLift) {
  const auto td = TDomain::create(0, 10, 1);
  Tube x(td), v(td, Interval(1.0));
  x.set_gate(0, Interval(0, 0.1));
  ASSERT_TRUE(CtcDerivAngle().contract(x, v));
  for (std::size_t k = 0; k <= 10; ++k) {
    EXPECT_LT(x.gate(k).diam(), 0.1 + 1e-9) << k;
    EXPECT_TRUE(angle_contains(x.gate(k), static_cast<double>(k) + 0.05)) << k;
  }
  EXPECT_TRUE(angle_contains(x.slice(3), 3.6));
  EXPECT_LT(x.slice(3).diam(), 1.1 + 1e-9);
}

// Dead reckoning lets the heading grow past a turn; an arc known at the end
// (a bearing) narrows the past again, which one real interval could not.
TEST(CtcDerivAngle, AFixNarrowsThePastBelowATurn) {
  const auto td = TDomain::create(0, 20, 0.5);
  Tube x(td), v(td, Interval(0.5, 1.5));
  x.set_gate(0, Interval(0, 0.1));
  ASSERT_TRUE(CtcDerivAngle().contract(x, v));
  EXPECT_TRUE(angle_is_circle(x.gate(40)));
  // The truth turned at 1 rad/s: ψ(20) = 20.05 ≡ 20.05 - 6π.
  x.set_gate(40, angle_meet(x.gate(40), Interval(20.0, 20.1) - Interval(6 * M_PI)));
  ASSERT_FALSE(x.gate(40).is_empty());
  ASSERT_TRUE(CtcDerivAngle().contract(x, v));
  EXPECT_TRUE(angle_contains(x.gate(20), 10.05));
  // Gate 39: [20, 20.1] - 0.5 [0.5, 1.5] = [19.25, 19.85] (modulo 2π), from a whole circle.
  EXPECT_TRUE(angle_contains(x.gate(39), 19.25) && angle_contains(x.gate(39), 19.85));
  EXPECT_NEAR(x.gate(39).diam(), 0.6, 1e-9);
  EXPECT_FALSE(angle_is_circle(x.gate(36)));
}

TEST(CtcDerivAngle, EmptinessAndErrors) {
  const auto td = TDomain::create(0, 2, 1);
  Tube x(td), v(td, Interval(1.0));
  x.set_gate(0, Interval(0, 0.1));
  x.set_gate(1, Interval(3, 3.1));  // 1 rad/s cannot reach it (modulo 2π either)
  EXPECT_FALSE(CtcDerivAngle().contract(x, v));
  EXPECT_TRUE(x.is_empty());
  const auto other = TDomain::create(0, 2, 1);
  Tube y(td), w(other);
  EXPECT_THROW(CtcDerivAngle().contract(y, w), DimensionError);
  // The real CtcDeriv refuses an angle tube (its sweeps would compare different turns).
  Tube a(td), rate(td, Interval(1.0));
  a.set_angle(true);
  EXPECT_THROW(CtcDeriv().contract(a, rate), Error);
  EXPECT_THROW(CtcDeriv().contract_local(a, rate, 0, 1, TubeChanges()), Error);
}

TEST(CtcDerivAngle, InANetwork) {
  const auto td = TDomain::create(0, 10, 0.5);
  auto x = std::make_shared<Tube>(td);
  auto v = std::make_shared<Tube>(td, Interval(0.9, 1.1));
  x->set_gate(0, Interval(0, 0.1));
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcDerivAngle>(), {x, v});
  cn.contract();
  EXPECT_TRUE(angle_contains(x->gate(20), 10.05));
  EXPECT_LT(x->gate(20).diam(), 2.2);
}

// A pointwise contractor on an angle tube whose gate and slices are on
// different turns: no real intersection of the gate with its slices.
TEST(CtcDerivAngle, APointwiseContractorLeavesTheTurnsAlone) {
  const auto td = TDomain::create(0, 2, 1);
  auto psi = std::make_shared<Tube>(td, Interval(0.9, 1.1));
  psi->set_angle(true);
  psi->set_gate(1, Interval(1.0, 1.05) + Interval(2 * M_PI));  // the same arc, one turn on
  const Tube copy = *psi;
  EXPECT_TRUE(copy.is_angle());
  auto c = std::make_shared<Tube>(td);
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcFunction>(Function({"c", "psi"}, "c - cos(psi)")), {c, psi});
  cn.add(std::make_shared<CtcDerivAngle>(), {psi, std::make_shared<Tube>(td, Interval(-0.2, 0.2))});
  cn.contract();
  EXPECT_FALSE(psi->is_empty());
  EXPECT_TRUE(angle_contains(psi->gate(1), 1.02));
  EXPECT_TRUE(c->gate(1).contains(std::cos(1.02)));
}

}  // namespace

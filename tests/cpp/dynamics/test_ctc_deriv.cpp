// CtcDeriv (thesis 4.2): single slices worked out by hand from the slice rule
// (gates, polygon hull, degenerate and unbounded cases, emptiness), the
// sweeps of Alg. 3-5 on small tubes with exact expected values, the range and
// time-interval forms, TubeVectors and errors. Each test runs with both
// rounding policies.
#include <gtest/gtest.h>

#include "deriv_test_util.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/error.h"
#include "sillage/tube/tube_vector.h"

using namespace sillage;
using sillage::test::BothRoundings;

namespace {

const double kInf = rounding::kInf;

std::shared_ptr<TDomain> unit() { return TDomain::create(std::vector<double>{0.0, 1.0}); }

// One slice of width 1: slice s, gates a and b.
// Gates a, b set as given, even off the slice s (the constructor would refuse).
Tube slice_tube(const Interval& a, const Interval& s, const Interval& b) {
  Tube x(unit(), std::vector<Interval>{s});
  x.set_gate(0, a);
  x.set_gate(1, b);
  return x;
}

struct SliceCase {
  Tube x;
  Tube v;
};

SliceCase run_slice(const Interval& a, const Interval& s, const Interval& b, const Interval& v,
                    TimePropag p = TimePropag::FWD_BWD) {
  Tube x = slice_tube(a, s, b);
  Tube vt(x.tdomain(), v);
  CtcDeriv(p).contract(x, vt);
  return {x, vt};
}

}  // namespace

class CtcDerivHand : public BothRoundings {};
INSTANTIATE_TEST_SUITE_P(Rounding, CtcDerivHand, ::testing::Bool(), sillage::test::rounding_name);

TEST_P(CtcDerivHand, OpenFanFromAPoint) {
  // a = 0, v = [-1, 1]: b = [-1, 1]; the polygon is the triangle (0,0),
  // (1,-1), (1,1): its hull over the slice is [-1, 1].
  const auto r = run_slice(Interval(0), Interval(), Interval(), Interval(-1, 1));
  EXPECT_EQ(r.x.gate(0), Interval(0));
  EXPECT_EQ(r.x.gate(1), Interval(-1, 1));
  EXPECT_EQ(r.x.slice(0), Interval(-1, 1));
}

TEST_P(CtcDerivHand, DiamondBetweenTwoPoints) {
  // a = b = 0, v = [-1, 1]: the polygon is the diamond (0,0), (1/2,±1/2),
  // (1,0): U(τ) = min(τ, 1 - τ), maximum 1/2 at the crossing τ = 1/2.
  const auto r = run_slice(Interval(0), Interval(), Interval(0), Interval(-1, 1));
  EXPECT_EQ(r.x.slice(0), Interval(-0.5, 0.5));
  EXPECT_EQ(r.x.gate(0), Interval(0));
  EXPECT_EQ(r.x.gate(1), Interval(0));
}

TEST_P(CtcDerivHand, AsymmetricCrossing) {
  // a = [0, 1], b = [2, 3], v = [-1, 3]. Gates already consistent:
  // b ∩ (a + v) = [2,3] ∩ [-1,4], a ∩ (b - v) = [0,1] ∩ [-1,4].
  // U(τ) = min(1 + 3τ, 3 + (1-τ)) crosses at τ = 3/4: 13/4.
  // L(τ) = max(0 - τ, 2 - 3(1-τ)) crosses at τ = 1/4: -1/4.
  const auto r = run_slice(Interval(0, 1), Interval(), Interval(2, 3), Interval(-1, 3));
  EXPECT_EQ(r.x.gate(0), Interval(0, 1));
  EXPECT_EQ(r.x.gate(1), Interval(2, 3));
  EXPECT_EQ(r.x.slice(0), Interval(-0.25, 3.25));
}

TEST_P(CtcDerivHand, CrossingWithInexactRatio) {
  // Same with v = [-1, 4]: U crosses at τ = 3/5, value 17/5 (not a double):
  // the bound is the double just above 3.4, or one more ulp at most.
  const auto r = run_slice(Interval(0, 1), Interval(), Interval(2, 3), Interval(-1, 4));
  const double up = r.x.slice(0).ub();
  EXPECT_GE(up, 3.4);  // 3.4 rounds up to the double above 17/5
  EXPECT_LE(up, rounding::next_up(rounding::next_up(3.4)));
  // L(τ) = max(-τ, 2 - 4(1-τ)) crosses at τ = 2/5: -2/5.
  const double lo = r.x.slice(0).lb();
  EXPECT_LE(lo, -0.4);
  EXPECT_GE(lo, rounding::next_down(rounding::next_down(-0.4)));
}

TEST_P(CtcDerivHand, GateContraction) {
  // a = [0, 1], b = [-10, 10], v = [1, 2]: b = [1, 3]; then with b = [2.5, 2.75]
  // the backward rule gives a = [0.5, 1].
  auto r = run_slice(Interval(0, 1), Interval(), Interval(-10, 10), Interval(1, 2));
  EXPECT_EQ(r.x.gate(1), Interval(1, 3));
  EXPECT_EQ(r.x.slice(0), Interval(0, 3));  // v >= 0: hull of the gates
  r = run_slice(Interval(0, 1), Interval(), Interval(2.5, 2.75), Interval(1, 2));
  EXPECT_EQ(r.x.gate(0), Interval(0.5, 1));
  EXPECT_EQ(r.x.gate(1), Interval(2.5, 2.75));
  EXPECT_EQ(r.x.slice(0), Interval(0.5, 2.75));
}

TEST_P(CtcDerivHand, SliceCodomainBoundsTheGates) {
  // s = [0, 1], v = 1: x(t) = x(0) + t stays in [0, 1], so x(0) <= 0 and x(1) >= 1.
  const auto r = run_slice(Interval(), Interval(0, 1), Interval(), Interval(1));
  EXPECT_EQ(r.x.gate(0), Interval(0));
  EXPECT_EQ(r.x.gate(1), Interval(1));
  EXPECT_EQ(r.x.slice(0), Interval(0, 1));
}

TEST_P(CtcDerivHand, DegenerateDerivative) {
  // v = 2: b = a + 2 = [2, 3]; polygon = the band between two parallel lines.
  const auto r = run_slice(Interval(0, 1), Interval(), Interval(), Interval(2));
  EXPECT_EQ(r.x.gate(1), Interval(2, 3));
  EXPECT_EQ(r.x.slice(0), Interval(0, 3));
  // Degenerate gates consistent with v = 1: the segment from 0 to 1.
  const auto s = run_slice(Interval(0), Interval(), Interval(1), Interval(1));
  EXPECT_EQ(s.x.slice(0), Interval(0, 1));
  EXPECT_EQ(s.x.gate(1), Interval(1));
}

TEST_P(CtcDerivHand, InconsistentGatesGiveEmpty) {
  Tube x = slice_tube(Interval(0), Interval(), Interval(2));
  const Tube v(x.tdomain(), Interval(1));
  EXPECT_FALSE(CtcDeriv().contract(x, v));
  EXPECT_TRUE(x.is_empty());
  EXPECT_TRUE(x.slice(0).is_empty());
  EXPECT_TRUE(x.gate(0).is_empty());
  EXPECT_TRUE(x.gate(1).is_empty());
}

TEST_P(CtcDerivHand, EmptyInputsGiveEmpty) {
  for (int which = 0; which < 4; ++which) {
    Tube x = slice_tube(Interval(0, 1), Interval(-5, 5), Interval(0, 2));
    Tube v(x.tdomain(), Interval(-1, 1));
    if (which == 0) v.set(Interval::empty());
    if (which == 1) x.set_gate(0, Interval::empty());
    if (which == 2) x.set_gate(1, Interval::empty());
    if (which == 3) x.write().slices()[0] = Interval::empty();
    EXPECT_FALSE(CtcDeriv().contract(x, v)) << which;
    EXPECT_TRUE(x.slice(0).is_empty() && x.gate(0).is_empty() && x.gate(1).is_empty()) << which;
  }
  // A gate disjoint from its slice.
  Tube x = slice_tube(Interval(0), Interval(1, 2), Interval());
  EXPECT_FALSE(CtcDeriv().contract(x, Tube(x.tdomain())));
  EXPECT_TRUE(x.is_empty());
}

TEST_P(CtcDerivHand, NondecreasingWithUnboundedDerivative) {
  // v = [0, +inf): b⁻ >= a⁻, nothing above.
  auto r = run_slice(Interval(1, 2), Interval(), Interval(), Interval(0, kInf));
  EXPECT_EQ(r.x.gate(1), Interval(1, kInf));
  EXPECT_EQ(r.x.gate(0), Interval(1, 2));
  EXPECT_EQ(r.x.slice(0), Interval(1, kInf));
  // With b known: a⁺ <= b⁺ and the slice is the hull of the gates.
  r = run_slice(Interval(0, 5), Interval(), Interval(1, 2), Interval(0, kInf));
  EXPECT_EQ(r.x.gate(0), Interval(0, 2));
  EXPECT_EQ(r.x.gate(1), Interval(1, 2));
  EXPECT_EQ(r.x.slice(0), Interval(0, 2));
  // Decreasing: v = (-inf, 0].
  r = run_slice(Interval(0, 5), Interval(), Interval(1, 2), Interval(-kInf, 0));
  EXPECT_EQ(r.x.gate(0), Interval(1, 5));
  EXPECT_EQ(r.x.slice(0), Interval(1, 5));
}

TEST_P(CtcDerivHand, UnboundedDerivativeOnOneSideStraddling) {
  // v = [-1, +inf): x may rise at any speed, falls at slope 1 at most.
  // a = b = 0: U(τ) = min(τ·inf, σ·1) = σ for τ > 0, supremum 1 (closure);
  // L(τ) = max(-τ, -σ·inf) = -τ for σ > 0, infimum -1.
  const auto r = run_slice(Interval(0), Interval(), Interval(0), Interval(-1, kInf));
  EXPECT_EQ(r.x.slice(0), Interval(-1, 1));
}

TEST_P(CtcDerivHand, WholeLineDerivativeOnlyIntersectsGatesWithSlices) {
  const auto r = run_slice(Interval(-3, 3), Interval(-1, 10), Interval(5, 20), Interval());
  EXPECT_EQ(r.x.gate(0), Interval(-1, 3));
  EXPECT_EQ(r.x.gate(1), Interval(5, 10));
  EXPECT_EQ(r.x.slice(0), Interval(-1, 10));
}

TEST_P(CtcDerivHand, InfiniteGates) {
  // Nothing known on x, v = [-1, 1]: nothing to contract.
  auto r = run_slice(Interval(), Interval(), Interval(), Interval(-1, 1));
  EXPECT_EQ(r.x.slice(0), Interval());
  EXPECT_EQ(r.x.gate(1), Interval());
  // Half-lines: a <= 0, v in [-1, 1] -> b <= 1, slice <= 1.
  r = run_slice(Interval(-kInf, 0), Interval(), Interval(), Interval(-1, 1));
  EXPECT_EQ(r.x.gate(1), Interval(-kInf, 1));
  EXPECT_EQ(r.x.slice(0), Interval(-kInf, 1));
  // a >= 0 and b <= 0: a = [0, 1], b = [-1, 0]; U = min(1 + τ, 0 + σ) is 1
  // at τ = 0, L = max(-τ, -1 - σ) is -1 at τ = 1.
  r = run_slice(Interval(0, kInf), Interval(), Interval(-kInf, 0), Interval(-1, 1));
  EXPECT_EQ(r.x.gate(0), Interval(0, 1));
  EXPECT_EQ(r.x.gate(1), Interval(-1, 0));
  EXPECT_EQ(r.x.slice(0), Interval(-1, 1));
}

TEST_P(CtcDerivHand, NonUnitWidthIsRigorous) {
  // δ = 0.1 (not a double): b = a + δ[1, 1] must contain 0.1 exactly.
  auto td = TDomain::create(std::vector<double>{0.0, 0.1});
  Tube x(td, std::vector<Interval>{Interval()}, std::vector<Interval>{Interval(0), Interval()});
  CtcDeriv().contract(x, Tube(td, Interval(1)));
  EXPECT_LE(x.gate(1).lb(), 0.1);
  EXPECT_GE(x.gate(1).ub(), 0.1);
  EXPECT_LE(x.gate(1).diam(), 3e-17);
  // Times far from 0: t = 1e6 + k·0.1, widths inexact.
  auto td2 = TDomain::create(std::vector<double>{1e6, 1e6 + 0.1});
  Tube y(td2, std::vector<Interval>{Interval()}, std::vector<Interval>{Interval(0), Interval()});
  CtcDeriv().contract(y, Tube(td2, Interval(1)));
  const Interval w = Interval(td2->t(1)) - Interval(td2->t(0));
  EXPECT_TRUE(w.is_subset(y.gate(1)));
}

// ---- sweeps on five slices: v = [0.5, 1], x(0) = 0 (thesis Fig. 4.3 style) ----

namespace {

struct Five {
  std::shared_ptr<TDomain> td = TDomain::create(0.0, 5.0, 1.0);
  Tube x{td};
  Tube v{td, Interval(0.5, 1)};
  Five() { x.set_gate(0, Interval(0)); }
};

}  // namespace

TEST_P(CtcDerivHand, ForwardSweep) {
  Five f;
  EXPECT_TRUE(CtcDeriv(TimePropag::FORWARD).contract(f.x, f.v));
  for (std::size_t k = 0; k <= 5; ++k) EXPECT_EQ(f.x.gate(k), Interval(0.5 * k, 1.0 * k)) << k;
  // v >= 0: each slice is the hull of its gates.
  for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(f.x.slice(k), Interval(0.5 * k, k + 1.0)) << k;
}

TEST_P(CtcDerivHand, ForwardBackwardWithFinalCondition) {
  Five f;
  f.x.set_gate(5, Interval(3));
  EXPECT_TRUE(CtcDeriv().contract(f.x, f.v));
  const Interval gates[] = {Interval(0), Interval(0.5, 1), Interval(1, 1.5), Interval(1.5, 2), Interval(2, 2.5),
                            Interval(3)};
  for (std::size_t k = 0; k <= 5; ++k) EXPECT_EQ(f.x.gate(k), gates[k]) << k;
  for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(f.x.slice(k), gates[k] | gates[k + 1]) << k;
}

TEST_P(CtcDerivHand, ForwardOnlyDoesNotPropagateBackward) {
  Five f;
  f.x.set_gate(5, Interval(3));
  EXPECT_TRUE(CtcDeriv(TimePropag::FORWARD).contract(f.x, f.v));
  EXPECT_EQ(f.x.gate(4), Interval(2, 4));
  EXPECT_EQ(f.x.slice(4), Interval(2, 3));  // the last slice sees its right gate
  EXPECT_EQ(f.x.slice(3), Interval(1.5, 4));
}

TEST_P(CtcDerivHand, BackwardOnly) {
  Five f;
  f.x.set_gate(5, Interval(3));
  EXPECT_TRUE(CtcDeriv(TimePropag::BACKWARD).contract(f.x, f.v));
  const Interval gates[] = {Interval(0), Interval(-1, 1), Interval(0, 1.5), Interval(1, 2), Interval(2, 2.5),
                            Interval(3)};
  for (std::size_t k = 0; k <= 5; ++k) EXPECT_EQ(f.x.gate(k), gates[k]) << k;
  // Slice 0: U(τ) = min(0 + τ, 1 - 0.5(1-τ)) -> 1; L(τ) = max(0.5τ, -1 - (1-τ)) -> 0.
  EXPECT_EQ(f.x.slice(0), Interval(0, 1));
  // Slice 1: a = [-1, 1], b = [0, 1.5]: U -> min(2, 1.5) = 1.5, L(0) = max(-1, -1) = -1.
  EXPECT_EQ(f.x.slice(1), Interval(-1, 1.5));
}

TEST_P(CtcDerivHand, FlagsCombine) {
  EXPECT_EQ(TimePropag::FORWARD | TimePropag::BACKWARD, TimePropag::FWD_BWD);
  EXPECT_TRUE(has(TimePropag::FWD_BWD, TimePropag::BACKWARD));
  EXPECT_FALSE(has(TimePropag::FORWARD, TimePropag::BACKWARD));
  EXPECT_EQ(CtcDeriv().time_propag(), TimePropag::FWD_BWD);
}

TEST_P(CtcDerivHand, SecondCallChangesNothing) {
  Five f;
  f.x.set_gate(5, Interval(3));
  f.x.set(Interval(-0.5, 2.2), 2);
  const CtcDeriv c;
  c.contract(f.x, f.v);
  const Tube once = f.x;
  const auto version = f.x.version();
  EXPECT_TRUE(c.contract(f.x, f.v));
  EXPECT_EQ(f.x, once);
  EXPECT_EQ(f.x.version(), version);  // not touched: nothing changed
}

TEST_P(CtcDerivHand, TouchOnlyWhenChanged) {
  Five f;
  const auto v0 = f.x.version();
  CtcDeriv().contract(f.x, f.v);
  EXPECT_GT(f.x.version(), v0);
}

// ---- restricted forms ----

TEST_P(CtcDerivHand, SliceRangeTouchesOnlyItsPart) {
  Five f;
  f.x.set_gate(2, Interval(1));
  const Tube before = f.x;
  EXPECT_TRUE(CtcDeriv().contract(f.x, f.v, 2, 3));
  for (std::size_t k : {0u, 1u, 4u}) EXPECT_EQ(f.x.slice(k), before.slice(k)) << k;
  for (std::size_t k : {0u, 1u, 5u}) EXPECT_EQ(f.x.gate(k), before.gate(k)) << k;
  EXPECT_EQ(f.x.gate(2), Interval(1));
  EXPECT_EQ(f.x.gate(3), Interval(1.5, 2));
  EXPECT_EQ(f.x.gate(4), Interval(2, 3));
  EXPECT_EQ(f.x.slice(3), Interval(1.5, 3));
  EXPECT_THROW(CtcDeriv().contract(f.x, f.v, 3, 2), Error);
  EXPECT_THROW(CtcDeriv().contract(f.x, f.v, 0, 5), Error);
}

TEST_P(CtcDerivHand, TimeIntervalForm) {
  Five f;
  f.x.set_gate(2, Interval(1));
  Tube y = f.x;
  CtcDeriv().contract(f.x, f.v, Interval(2.5, 3.5));  // slices 2 and 3
  CtcDeriv().contract(y, f.v, 2, 3);
  EXPECT_EQ(f.x, y);
  Tube z = f.x, w = f.x;
  CtcDeriv().contract(z, f.v, Interval(3.0));  // a time point: slices 2 and 3
  CtcDeriv().contract(w, f.v, 2, 3);
  EXPECT_EQ(z, w);
  Tube u = f.x, u2 = f.x;
  CtcDeriv().contract(u, f.v, Interval(2.0, 4.0));  // slices 2, 3 (not 1 and 4: only touched)
  CtcDeriv().contract(u2, f.v, 2, 3);
  EXPECT_EQ(u, u2);
  EXPECT_TRUE(CtcDeriv().contract(f.x, f.v, Interval::empty()));
  EXPECT_THROW(CtcDeriv().contract(f.x, f.v, Interval(4, 6)), Error);
}

TEST_P(CtcDerivHand, TubeVectorComponentWise) {
  Five f;
  TubeVector x(f.td, 2), v(f.td, 2);
  x[0].set_gate(0, Interval(0));
  x[1].set_gate(5, Interval(0));
  v[0] = f.v;
  v[1] = Tube(f.td, Interval(-1, 1));
  EXPECT_TRUE(CtcDeriv().contract(x, v));
  EXPECT_EQ(x[0].gate(5), Interval(2.5, 5));
  EXPECT_EQ(x[1].gate(0), Interval(-5, 5));
  // One empty component empties the vector.
  x[1].set_gate(0, Interval(10));
  EXPECT_FALSE(CtcDeriv().contract(x, v));
  EXPECT_TRUE(x[0].is_empty());
  EXPECT_TRUE(x[1].is_empty());
}

TEST_P(CtcDerivHand, Errors) {
  Five f;
  const auto other = TDomain::create(0.0, 5.0, 1.0);
  Tube v2(other, Interval(0, 1));
  EXPECT_THROW(CtcDeriv().contract(f.x, v2), DimensionError);
  EXPECT_THROW(CtcDeriv().contract(f.x, v2, 0, 1), DimensionError);
  EXPECT_THROW(CtcDeriv().contract(f.x, v2, Interval(0, 1)), DimensionError);
  TubeVector x(f.td, 2), v(f.td, 3), w(other, 2);
  EXPECT_THROW(CtcDeriv().contract(x, v), DimensionError);
  EXPECT_THROW(CtcDeriv().contract(x, w), DimensionError);
  try {
    CtcDeriv().contract(f.x, v2);
    FAIL();
  } catch (const DimensionError& e) {
    EXPECT_NE(std::string(e.what()).find("same TDomain"), std::string::npos) << e.what();
  }
}

TEST_P(CtcDerivHand, AliasedXAndV) {
  // x' = x with x(0) = 1 on [0, 1], x in [0, 10]: x = e^t, contracted
  // without losing it (the derivative tube shrinks while it is used).
  auto td = TDomain::create(0.0, 1.0, 0.125);
  Tube x(td, Interval(0, 10));
  x.set_gate(0, Interval(1));
  for (int i = 0; i < 5; ++i) CtcDeriv().contract(x, x);
  EXPECT_TRUE(x.gate(8).contains(std::exp(1.0)));
  EXPECT_LT(x.gate(8).ub(), 10.0);
}

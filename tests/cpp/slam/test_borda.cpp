// Borda's double weighing (thesis 7.1.3, (7.5)) as a temporal SLAM with a
// scalar configuration: h = identity, p the mass in the right pan of a
// balance with arms of unknown lengths. The thesis gives no figures; the
// scenario (one slice = 1/64 s, binary-exact phase boundaries):
//   [0, 1]  the unknown object, p = m = 6.3 kg (stated: [0.5, 9.5] kg),
//           nothing touches the pan: |w| <= 1 g/s;
//   [1, 2]  the object is lifted off: w in [-10, 0] kg/s, p(2) = 0 (the pan
//           is seen empty);
//   [2, 3]  a calibrated flow pours the reference: w in 10 kg/s +- 0.5 %.
// z is the pointer angle g(p) + [-5, 5] mrad with g unknown to the solver
// (g(x) = 0.5 atan((x - 5) / 3) here). The implication p(t1) = p(t2) ⇒
// z(t1) = z(t2) must give m from the reference, whatever g, with no map of g.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>

#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/error.h"
#include "sillage/expr/function.h"
#include "sillage/interval/elementary.h"
#include "sillage/slam/ctc_p_implies_z.h"
#include "sillage/slam/scalar_loops.h"
#include "sillage/slam/temporal_slam.h"

using namespace sillage;

namespace {

constexpr double kMass = 6.3;

// The true mass over [t] (inside one phase or on its boundary; p* is linear there).
Interval true_mass(const Interval& t) {
  if (t.ub() <= 1.0) return Interval(kMass);
  if (t.ub() <= 2.0) return Interval(kMass) * (Interval(2.0) - t);
  return Interval(10.0) * (t - Interval(2.0));
}

using Pointer = std::function<Interval(const Interval&)>;

Interval arms(const Interval& x) { return Interval(0.5) * atan((x - Interval(5.0)) / Interval(3.0)); }

struct Borda {
  std::shared_ptr<TDomain> td = TDomain::create(0.0, 3.0, 1.0 / 64);
  TubeVector p{td, 1}, w{td, 1}, z{td, 1};

  explicit Borda(const Pointer& g = arms, double bias = 0.0) {
    const std::size_t n = td->nb_slices();
    for (std::size_t k = 0; k < n; ++k) {
      const Interval t(td->t(k), td->t(k + 1));
      const Interval wk = t.ub() <= 1.0   ? Interval(-1e-3, 1e-3)
                          : t.ub() <= 2.0 ? Interval(-10.0, 0.0)
                                          : Interval(10.0) * Interval(0.995, 1.005);
      w[0].set(wk, k);
      z[0].set(g(true_mass(t)) + Interval(bias) + Interval(-5e-3, 5e-3), k);
    }
    for (std::size_t k = 0; k <= n; ++k) {
      w[0].set_gate(k, k == 0 ? w[0].slice(0) : k == n ? w[0].slice(n - 1) : w[0].slice(k - 1) | w[0].slice(k));
      z[0].set_gate(k, g(true_mass(Interval(td->t(k)))) + Interval(bias) + Interval(-5e-3, 5e-3));
    }
    p[0].set_gate(0, Interval(0.5, 9.5));   // the stated range of the object
    p[0].set_gate(2 * 64, Interval(0.0));    // t = 2: the pan seen empty
    CtcDeriv().contract(p, w);
  }

  // The true mass in every slice and gate of p.
  bool holds_truth() const {
    for (std::size_t k = 0; k < td->nb_slices(); ++k) {
      if (!true_mass(Interval(td->t(k), td->t(k + 1))).is_subset(p[0].slice(k))) return false;
    }
    for (std::size_t k = 0; k <= td->nb_slices(); ++k) {
      if (!p[0].gate(k).contains(true_mass(Interval(td->t(k))).mid())) return false;
    }
    return true;
  }
};

}  // namespace

TEST(Borda, DeadReckoningKnowsNothingOfTheMass) {
  Borda b;
  EXPECT_TRUE(b.holds_truth());
  EXPECT_GT(b.p[0].gate(0).diam(), 8.9);  // [0.5, 9.5] and the 1 g/s of phase 1
}

TEST(Borda, TheImplicationWeighsTheObject) {
  Borda b;
  const TubeVector dr = b.p;
  const auto rows = CtcPImpliesZ(1.0 / 64).contract(b.p, b.w, b.z);
  ASSERT_FALSE(rows.empty());
  EXPECT_GT(rows[0].nb_proofs, 0u);
  EXPECT_TRUE(b.p.is_subset(dr));
  EXPECT_TRUE(b.holds_truth());
  // p(t1) = p(t2) with t2 where the reference reads as the object did: the
  // mass to about the flow over the few slices whose z matches.
  const Interval m = b.p[0].gate(0);
  EXPECT_TRUE(m.contains(kMass));
  EXPECT_LT(m.diam(), 0.8) << m.str();
  EXPECT_GT(rows.back().contraction_t0, 0.9);
  for (const SlamRow& r : rows) std::printf("  %s\n", to_string(r).c_str());
  std::printf("  mass %s\n", m.str().c_str());
}

TEST(Borda, FastIsNeverNarrowerThanAccurate) {
  Borda fast, accurate;
  CtcPImpliesZ(1.0 / 64, true).contract(fast.p, fast.w, fast.z);
  CtcPImpliesZ(1.0 / 64).contract(accurate.p, accurate.w, accurate.z);
  EXPECT_TRUE(fast.holds_truth());
  EXPECT_TRUE(fast.p[0].gate(0).contains(kMass));
  for (std::size_t k = 0; k <= fast.td->nb_slices(); ++k) {
    EXPECT_TRUE(accurate.p[0].gate(k).is_subset(fast.p[0].gate(k))) << k;
  }
}

TEST(Borda, AnyBalanceAnyBias) {
  // Other arms (another g) and a constant unknown bias of the pointer: the
  // mass is still inside; the bias changes nothing, bit for bit (7.4.3).
  const Pointer other = [](const Interval& x) { return Interval(2.0) * atan(x - Interval(4.0)); };
  Borda b(other), biased(other, 0.75);
  CtcPImpliesZ(1.0 / 64).contract(b.p, b.w, b.z);
  CtcPImpliesZ(1.0 / 64).contract(biased.p, biased.w, biased.z);
  EXPECT_TRUE(b.holds_truth());
  EXPECT_LT(b.p[0].gate(0).diam(), 0.8);
  for (std::size_t k = 0; k <= b.td->nb_slices(); ++k) EXPECT_EQ(b.p[0].gate(k), biased.p[0].gate(k)) << k;
}

TEST(Borda, APointerThatNeverComesBackEmptiesP) {
  // A pointer reading that never returns to the value of phase 1: no t2 can
  // match, so the proven loops are nowhere in T_z: inconsistent.
  Borda b;
  for (std::size_t k = 2 * 64; k < b.td->nb_slices(); ++k) b.z[0].set(Interval(5.0, 6.0), k);
  for (std::size_t k = 2 * 64 + 1; k <= b.td->nb_slices(); ++k) b.z[0].set_gate(k, Interval(5.0, 6.0));
  CtcPImpliesZ(1.0 / 64).contract(b.p, b.w, b.z);
  EXPECT_TRUE(b.p.is_empty());
}

TEST(ScalarLoopExists, SignChangeOnConnectedBoxesAboveTheDiagonal) {
  Borda b;
  // Phase 1 against the pour: f = p(t2) - p(t1) < 0 at t2 = 2, > 0 at t2 = 3.
  const std::vector<IntervalVector> column = {IntervalVector{{0.5, 0.6}, {2.0, 2.5}},
                                              IntervalVector{{0.5, 0.6}, {2.5, 3.0}}};
  EXPECT_TRUE(scalar_loop_exists(column, b.p, b.w));
  // One sign only (the pour below 0.5 kg): no proof.
  EXPECT_FALSE(scalar_loop_exists({IntervalVector{{0.5, 0.6}, {2.0, 2.04}}}, b.p, b.w));
  // Two boxes that do not touch: not connected, no proof.
  EXPECT_FALSE(scalar_loop_exists({IntervalVector{{0.5, 0.6}, {2.0, 2.2}}, IntervalVector{{0.5, 0.6}, {2.9, 3.0}}},
                                  b.p, b.w));
  // Reaching the diagonal: the zero could be the trivial t1 = t2.
  EXPECT_FALSE(scalar_loop_exists({IntervalVector{{0.5, 2.5}, {2.0, 3.0}}}, b.p, b.w));
  EXPECT_FALSE(scalar_loop_exists({}, b.p, b.w));
}

TEST(ScalarLoops, PiecesAreColumnsAndTheTrueLoopIsProven) {
  Borda b;
  const auto loops = scalar_loops(1.0 / 64, b.p, b.w);
  ASSERT_FALSE(loops.empty());
  std::size_t proven_phase1 = 0;
  for (const ScalarLoop& l : loops) {
    EXPECT_LE(l.hull[0].diam(), 2.0 / 64 + 1e-12);
    EXPECT_LT(l.hull[0].ub(), l.hull[1].ub());
    for (const auto& x : l.boxes) EXPECT_LT(x[0].ub(), x[1].lb());
    // The true partner of t1 in phase 1 is t2 = 2 + m / 10.
    if (l.proven && l.hull[0].ub() <= 1.0) {
      ++proven_phase1;
      EXPECT_TRUE(l.hull[1].contains(2.0 + kMass / 10)) << repr(l);
    }
  }
  EXPECT_GE(proven_phase1, 60u);  // nearly every column of phase 1
}

TEST(ScalarLoops, Errors) {
  Borda b;
  EXPECT_THROW(scalar_loops(0.0, b.p, b.w), Error);
  const TubeVector p2(b.td, 2);
  EXPECT_THROW(scalar_loops(0.1, p2, b.w), DimensionError);
  EXPECT_THROW(scalar_loop_exists({IntervalVector{{0, 1}, {2, 4}}}, b.p, b.w), Error);
  EXPECT_THROW(CtcPImpliesZ(0.1).contract(b.p, p2, b.z), DimensionError);
}

TEST(Borda, TemporalSlamWithAScalarH) {
  // x = the mass, f(x, u) = u (the flow), h = identity: Alg. 15 with h of one output.
  Borda b;
  TubeVector x = b.p, v = b.w;
  const auto rows = temporal_slam(x, v, b.w, b.z, Function({"x", "u"}, "u"), Function({"x"}, "x"),
                                  [] {
                                    TemporalSlamOptions o;
                                    o.eps = 1.0 / 64;
                                    return o;
                                  }());
  ASSERT_FALSE(rows.empty());
  EXPECT_TRUE(x[0].gate(0).contains(kMass));
  EXPECT_LT(x[0].gate(0).diam(), 0.8);
}

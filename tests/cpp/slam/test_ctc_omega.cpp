// CtcOmega (Alg. 12, (7.22)): on a two-box paving it equals Alg. 12 as
// printed (one tube copy per box, hull of the copies), bit for bit; an
// inconsistent box is left out of the union; no consistent box empties p;
// the truth is kept; errors.
#include <gtest/gtest.h>

#include <memory>
#include <numbers>
#include <vector>

#include "sillage/error.h"
#include "sillage/slam/ctc_omega.h"
#include "sillage/tube/trajectory.h"

using namespace sillage;

namespace {

// p*(t) = (cos t, 0.3 t) on [0, 2π], thin early and drifting late; the true
// loop of the first component is t1 = 1.2, t2 = 2π - 1.2, but the second
// component has no loop: use a 1-D p for the loop tests.
struct Drift {
  std::shared_ptr<TDomain> td = TDomain::create(0.0, 2 * std::numbers::pi, 0.01);
  TubeVector p{std::vector<Tube>{Tube(td, "cos(t) + [-1,1]*(0.02 + 0.1*t)")}};
  TubeVector w{std::vector<Tube>{Tube(td, "-sin(t) + [-0.01,0.01]")}};
  Trajectory truth{"cos(t)", td->t0_tf()};
};

IntervalVector tbox(Interval t1, Interval t2) { return IntervalVector{t1, t2}; }

// Alg. 12 as printed: a copy of the tube per box, the hull of the copies.
TubeVector literal_omega(const std::vector<IntervalVector>& boxes, const TubeVector& p, const TubeVector& w) {
  TubeVector out(p.tdomain(), p.size(), Interval::empty());
  for (const auto& b : boxes) {
    TubeVector q = p;
    Interval t1 = b[0], t2 = b[1];
    if (CtcT1T2().contract(t1, t2, q, w)) out |= q;
  }
  return out;
}

}  // namespace

TEST(CtcOmega, TwoBoxPavingEqualsTheHullOfTheCopies) {
  Drift c;
  // A holds the true loop (1.2, 2π - 1.2), B another one (1.05, 2π - 1.05).
  const std::vector<IntervalVector> boxes{tbox({1.1, 1.3}, {4.9, 5.3}), tbox({1.0, 1.1}, {5.2, 5.4})};
  const TubeVector expected = literal_omega(boxes, c.p, c.w);
  const TubeVector before = c.p;
  ASSERT_TRUE(CtcOmega().contract(boxes, c.p, c.w));
  EXPECT_TRUE(c.p == expected);
  EXPECT_TRUE(c.p.is_subset(before));
  EXPECT_LT(c.p.volume(), before.volume());
  EXPECT_TRUE(c.p[0].contains(c.truth));
  // Each box alone contracts more than their union.
  for (const auto& b : boxes) {
    TubeVector q = before;
    ASSERT_TRUE(CtcOmega().contract({b}, q, c.w));
    EXPECT_TRUE(q.is_subset(c.p));
  }
}

TEST(CtcOmega, InconsistentBoxIsLeftOutOfTheUnion) {
  Drift c;
  // C: p([t1]) ≈ [0.1, 0.6] and p around t = 3.1 ≈ [-1.4, -0.6]: no loop.
  const IntervalVector a = tbox({1.1, 1.3}, {4.9, 5.3}), cbox = tbox({1.1, 1.3}, {2.9, 3.3});
  TubeVector with_c = c.p, alone = c.p;
  ASSERT_TRUE(CtcOmega().contract({a, cbox}, with_c, c.w));
  ASSERT_TRUE(CtcOmega().contract({a}, alone, c.w));
  EXPECT_TRUE(with_c == alone);
}

TEST(CtcOmega, NoConsistentBoxEmptiesTheTube) {
  Drift c;
  EXPECT_FALSE(CtcOmega().contract({tbox({1.1, 1.3}, {2.9, 3.3})}, c.p, c.w));
  EXPECT_TRUE(c.p.is_empty());
  Drift d;
  EXPECT_FALSE(CtcOmega().contract({}, d.p, d.w));
  EXPECT_TRUE(d.p.is_empty());
}

TEST(CtcOmega, SparseHullLeavesTheReferenceAndTheWorkTubeAsTheyWere) {
  Drift c;
  const std::vector<IntervalVector> boxes{tbox({1.1, 1.3}, {4.9, 5.3}), tbox({1.1, 1.3}, {2.9, 3.3}),
                                          tbox({1.0, 1.1}, {5.2, 5.4})};
  TubeVector work = c.p;
  const OmegaHull h = CtcOmega().hull(boxes, c.p, c.w, work);
  EXPECT_TRUE(work == c.p);
  EXPECT_EQ(h.nb_boxes, 3u);
  EXPECT_EQ(h.nb_consistent, 2u);
  EXPECT_FALSE(h.empty);
  EXPECT_GT(h.atoms.size(), 0u);
  EXPECT_GE(h.nb_touched, h.atoms.size());
  // Touched atoms are a window, not the tube: the thin start stays as it was.
  EXPECT_LT(h.atoms.size(), 2 * c.p.nb_slices() + 1);
  EXPECT_NE(h.atoms.front().atom, 0u);
  TubeVector q = c.p;
  h.apply_to(q);
  EXPECT_TRUE(q == literal_omega(boxes, c.p, c.w));
}

TEST(CtcOmega, BadInputSaysWhatAndWhere) {
  Drift c;
  EXPECT_THROW(CtcOmega().contract({IntervalVector(3)}, c.p, c.w), DimensionError);
  TubeVector w2(c.td, 2);
  EXPECT_THROW(CtcOmega().contract({tbox({1, 2}, {3, 4})}, c.p, w2), DimensionError);
}

// Many boxes (visited in a spread order, stopping once no atom can shrink):
// still Alg. 12 as printed, bit for bit, for tilings that contract (small
// window) and that do not (a wide window whose hull is the reference).
TEST(CtcOmega, ManyBoxesEqualTheHullOfTheCopies) {
  for (const auto& [a, b] : {std::pair{Interval(1.1, 1.3), Interval(4.9, 5.3)},
                            std::pair{Interval(0.6, 1.8), Interval(4.3, 5.9)}}) {
    for (int k : {1, 2, 3, 7, 16}) {
      std::vector<IntervalVector> boxes;
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j)
          boxes.push_back(tbox(Interval(a.lb() + a.diam() * i / k, a.lb() + a.diam() * (i + 1) / k),
                               Interval(b.lb() + b.diam() * j / k, b.lb() + b.diam() * (j + 1) / k)));
      Drift c;
      const TubeVector expected = literal_omega(boxes, c.p, c.w);
      CtcOmega().contract(boxes, c.p, c.w);
      EXPECT_TRUE(c.p == expected) << k << " x " << k << " boxes";
      EXPECT_TRUE(c.p.contains(std::vector<Trajectory>{c.truth}));
    }
  }
}

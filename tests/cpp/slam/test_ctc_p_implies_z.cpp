// CtcPImpliesZ (Alg. 13-14, (7.9)) on a small synthetic SLAM: the loop of a
// figure eight is detected and proven, [p](t_f) shrinks, the truth stays in
// every gate and slice at every iteration; accurate after fast is never
// wider; results do not depend on the thread count; a constant bias on z
// changes nothing (7.4.3); an observation that contradicts the loop empties
// p; errors.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "small_slam.h"
#include "sillage/error.h"
#include "sillage/slam/ctc_p_implies_z.h"

using namespace sillage;
using slam_test::SmallSlam;

TEST(CtcPImpliesZ, FastProvesTheLoop) {
  // The hull [b] of Ω ∩ 𝕋_z spans the loop's time uncertainty, over which
  // the robot moves as far as its drift: [b] alone cannot pull the end back
  // here (the accurate algorithm can, below).
  SmallSlam s;
  const TubeVector dr = s.p;
  const auto rows = CtcPImpliesZ(0.01, true).contract(s.p, s.w, s.z);
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows[0].nb_detections, 1u);
  EXPECT_EQ(rows[0].nb_proofs, 1u);
  EXPECT_TRUE(rows[0].fast);
  EXPECT_TRUE(s.p.is_subset(dr));
  EXPECT_TRUE(s.p.contains(s.truth));
}

TEST(CtcPImpliesZ, AccuratePullsTheEndBack) {
  // Each box of Ω ∩ 𝕋_z pins p(t2) to p(t1) and carries it to t_f; the union
  // over the boxes still excludes the drift between the two passages.
  SmallSlam s;
  const TubeVector dr = s.p;
  const auto rows = CtcPImpliesZ(0.01, false).contract(s.p, s.w, s.z);
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows[0].nb_proofs, 1u);
  EXPECT_FALSE(rows[0].fast);
  EXPECT_GT(rows.back().contraction_tf, 0.1);
  EXPECT_GT(rows[0].nb_atoms_touched, 0u);
  EXPECT_TRUE(s.p.is_subset(dr));
  EXPECT_TRUE(s.p.contains(s.truth));
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].iteration, i + 1);
    EXPECT_GE(rows[i].cumulated_seconds, rows[i - 1].cumulated_seconds);
    EXPECT_GE(rows[i].contraction_tf, rows[i - 1].contraction_tf);
  }
}

TEST(CtcPImpliesZ, EveryIterationKeepsTheTruth) {
  for (bool fast : {true, false}) {
    SmallSlam s;
    CtcPImpliesZ ctc(0.01, fast);
    for (int it = 0; it < 4; ++it) {
      SlamRow row;
      const TubeVector before = s.p;
      const bool more = ctc.iterate(s.p, s.w, s.z, row);
      ASSERT_TRUE(s.p.contains(s.truth)) << "fast " << fast << ", iteration " << it;
      ASSERT_TRUE(s.p.is_subset(before));
      if (!more) break;
    }
  }
}

TEST(CtcPImpliesZ, AccurateAfterFastIsNeverWider) {
  SmallSlam s;
  CtcPImpliesZ(0.01, true).contract(s.p, s.w, s.z);
  const TubeVector fast = s.p;
  const auto rows = CtcPImpliesZ(0.01, false).contract(s.p, s.w, s.z);
  EXPECT_FALSE(rows.front().fast);
  EXPECT_TRUE(s.p.is_subset(fast));
  EXPECT_TRUE(s.p.contains(s.truth));
}

TEST(CtcPImpliesZ, ResultsDoNotDependOnTheThreadCount) {
  TubeVector one(SmallSlam().p), two(one);
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    SmallSlam s;
    CtcPImpliesZ(0.01, false).contract(s.p, s.w, s.z);
    one = s.p;
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    SmallSlam s;
    CtcPImpliesZ(0.01, false).contract(s.p, s.w, s.z);
    two = s.p;
  }
  EXPECT_TRUE(slam_test::same_values(one, two));
}

TEST(CtcPImpliesZ, ConstantUnknownBiasChangesNothing) {
  // z + b for an unknown constant b: z(t1) = z(t2) is unchanged (7.4.3), so
  // is every contraction, bit for bit, for b exactly representable.
  SmallSlam plain, biased(0.01, "3.25");
  const auto rp = CtcPImpliesZ(0.01, false).contract(plain.p, plain.w, plain.z);
  const auto rb = CtcPImpliesZ(0.01, false).contract(biased.p, biased.w, biased.z);
  EXPECT_GT(rp.back().contraction_tf, 0.1);
  EXPECT_TRUE(slam_test::same_values(plain.p, biased.p));
}

TEST(CtcPImpliesZ, ObservationContradictingAProvenLoopEmptiesP) {
  // z strictly increasing: z(t1) = z(t2) never holds, yet the loop is proven.
  SmallSlam s;
  const TubeVector z(std::vector<Tube>{Tube(s.td, "t")});
  const auto rows = CtcPImpliesZ(0.01, true).contract(s.p, s.w, z);
  EXPECT_GE(rows.front().nb_proofs, 1u);
  EXPECT_TRUE(s.p.is_empty());
}

TEST(CtcPImpliesZ, UninformativeObservationGainsLess) {
  // z unknown: 𝕋_z is everything, only the loop itself is known.
  SmallSlam s, informed;
  const auto rows = CtcPImpliesZ(0.01, false).contract(s.p, s.w, TubeVector(s.td, 1));
  const auto rows_z = CtcPImpliesZ(0.01, false).contract(informed.p, informed.w, informed.z);
  EXPECT_TRUE(s.p.contains(s.truth));
  EXPECT_TRUE(slam_test::subset_values(informed.p, s.p));
  EXPECT_LT(rows.back().contraction_tf, rows_z.back().contraction_tf);
}

TEST(CtcPImpliesZ, BadInputSaysWhatAndWhere) {
  SmallSlam s;
  EXPECT_THROW(CtcPImpliesZ(0.0), Error);
  EXPECT_THROW(CtcPImpliesZ(-1.0), Error);
  TubeVector p3(s.td, 3);
  EXPECT_THROW(CtcPImpliesZ(0.01).contract(p3, s.w, s.z), DimensionError);
  const TubeVector short_z(TDomain::create(0.0, 1.0, 0.1), 1);
  EXPECT_THROW(CtcPImpliesZ(0.01).contract(s.p, s.w, short_z), Error);
  CtcPImpliesZ c(0.05);
  EXPECT_THROW(c.set_ratio(1.0), Error);
  EXPECT_THROW(c.set_max_iterations(0), Error);
}

// The _run forms of the loops (outcome.h): the t-plane detections keep the
// paving so far (still an enclosure of every loop: a known loop's t-pair lies
// in a detection), the degree, count and split keep no value once stopped
// or cancelled (a partial degree is no answer); the throwing forms agree.
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "plane_maps.h"
#include "sillage/loops/component_split.h"
#include "sillage/loops/loop_function.h"
#include "sillage/loops/loop_sivia.h"
#include "sillage/loops/topological_degree.h"
#include "sillage/loops/tplane.h"
#include "sillage/loops/zero_tests.h"
#include "sillage/tube/tube_vector.h"

using namespace sillage;
using namespace sillage::test;

namespace {

constexpr double pi = std::numbers::pi;
// The limaçon of test_tplane.cpp: one loop, at (t1, t2) = (2π/3, 4π/3).
const char* kLimaconV = "(-sin(t) - 2*sin(2*t) + [-0.01,0.01], cos(t) + 2*cos(2*t) + [-0.01,0.01])";

bool some_detection_holds(const TPlane& tp, double t1, double t2) {
  const IntervalVector point{Interval(t1), Interval(t2)};
  for (const Loop& l : tp.detections()) {
    for (const IntervalVector& b : l.boxes()) {
      if (point.is_subset(b)) return true;
    }
  }
  return false;
}

struct Limacon {
  std::shared_ptr<TDomain> td = TDomain::create(0.3, 2 * pi - 0.3, 0.001);
  TubeVector v{td, kLimaconV};
};

const PlaneFunction kIdentity = [](const IntervalVector& t) { return t; };
const PlaneJacobian kIdentityJacobian = [](const IntervalVector&) { return IntervalMatrix::identity(2); };
const std::vector<IntervalVector> kSquare{box(-1, 1, -1, 1)};

}  // namespace

TEST(LoopsRun, DetectionsConvergedAreTheThrowingForms) {
  Limacon m;
  TPlane run(m.td), thrown(m.td);
  const Summary s = run.compute_detections_run(0.05, m.v);
  thrown.compute_detections(0.05, m.v);
  EXPECT_EQ(s.status, Status::Converged);
  EXPECT_EQ(s.reason, "");
  EXPECT_EQ(s.work, run.paving().nb_nodes());
  EXPECT_TRUE(run.paving() == thrown.paving());
  EXPECT_EQ(run.nb_detections(), 1u);
}

TEST(LoopsRun, StoppedDetectionsStillHoldTheLoop) {
  Limacon m;
  TPlane tp(m.td);
  Budget b;
  b.max_boxes = 500;
  const Summary s = tp.compute_detections_run(1e-9, m.v, b);
  EXPECT_EQ(s.status, Status::Stopped);
  EXPECT_EQ(s.reason,
            "TPlane::compute_detections: budget exceeded: 501 boxes > max_boxes = 500; raise budget.max_boxes "
            "(0: no limit) or use a larger eps");
  EXPECT_GE(tp.nb_detections(), 1u);
  EXPECT_EQ(tp.eps(), 1e-9);
  EXPECT_TRUE(some_detection_holds(tp, 2 * pi / 3, 4 * pi / 3));
  // The throwing form keeps the previous results whole.
  EXPECT_THROW(tp.compute_detections(1e-9, m.v, b), BudgetExceeded);
  EXPECT_TRUE(some_detection_holds(tp, 2 * pi / 3, 4 * pi / 3));
}

TEST(LoopsRun, CancelledDetectionsAreTheWholeSquare) {
  Limacon m;
  TPlane tp(m.td);
  Budget b;
  b.cancel.cancel();
  const Summary s = tp.compute_detections_run(0.05, m.v, b);
  EXPECT_EQ(s.status, Status::Cancelled);
  EXPECT_EQ(s.reason, "TPlane::compute_detections: cancelled");
  ASSERT_EQ(tp.nb_detections(), 1u);  // the square left undetermined: one incomplete detection
  EXPECT_FALSE(tp.detections()[0].complete());
  EXPECT_TRUE(some_detection_holds(tp, 2 * pi / 3, 4 * pi / 3));
}

TEST(LoopsRun, NoLoopIsNoSolution) {
  auto td = TDomain::create(0, 100, 0.1);
  const TubeVector v(td, "(1 + [-0.01,0.01], 0.5 + [-0.01,0.01])");
  TPlane tp(td);
  const Summary s = tp.compute_detections_run(0.01, v);
  EXPECT_EQ(s.status, Status::NoSolution);
  EXPECT_EQ(s.reason, "TPlane::compute_detections: no loop: every t-box is proven outside the feasible loops");
  EXPECT_EQ(tp.nb_detections(), 0u);
  const SiviaResult r = loop_sivia_run(LoopFunction(v), tp.domain(), 0.01);
  EXPECT_EQ(r.summary.status, Status::NoSolution);
  EXPECT_EQ(r.summary.reason, "loop_sivia: no loop: every t-box is proven outside the feasible loops");
}

TEST(LoopsRun, ProgressIsCalledPerRound) {
  Limacon m;
  TPlane tp(m.td);
  Budget b;
  std::size_t calls = 0, last_work = 0;
  b.progress_every = 100;
  b.progress = [&](const Progress& p) {
    ++calls;
    EXPECT_EQ(p.round, calls);
    EXPECT_STREQ(p.where, "TPlane::compute_detections");
    EXPECT_GT(p.work, last_work);
    last_work = p.work;
  };
  const Summary s = tp.compute_detections_run(0.01, m.v, b);
  EXPECT_EQ(s.status, Status::Converged);
  EXPECT_GT(calls, 0u);
  EXPECT_EQ(s.rounds, calls);
  EXPECT_EQ(s.work / 100, calls);
}

TEST(LoopsRun, DegreeStoppedOrCancelledHasNoValue) {
  DegreeOptions o;
  const DegreeRun full = topological_degree_run(kSquare, kIdentity, o);
  EXPECT_EQ(full.summary.status, Status::Converged);
  ASSERT_TRUE(full.value && full.value->degree);
  EXPECT_EQ(*full.value->degree, 1);
  EXPECT_EQ(full.summary.work, full.value->nb_evaluations);
  EXPECT_EQ(DegreeRun(full).take().degree, topological_degree(kSquare, kIdentity, o).degree);

  o.budget.max_boxes = 2;
  DegreeRun stopped = topological_degree_run(kSquare, kIdentity, o);
  EXPECT_EQ(stopped.summary.status, Status::Stopped);
  EXPECT_EQ(stopped.summary.reason,
            "topological_degree: budget exceeded: 3 boxes > max_boxes = 2; raise options.budget.max_boxes (0: no "
            "limit)");
  EXPECT_FALSE(stopped.value);
  EXPECT_THROW(std::move(stopped).take(), BudgetExceeded);

  o.budget = Budget{};
  o.budget.cancel.cancel();
  DegreeRun cancelled = topological_degree_run(kSquare, kIdentity, o);
  EXPECT_EQ(cancelled.summary.status, Status::Cancelled);
  EXPECT_FALSE(cancelled.value);
  EXPECT_THROW(std::move(cancelled).take(), Cancelled);
  // Errors are still thrown.
  EXPECT_THROW(topological_degree_run(std::vector<IntervalVector>{}, kIdentity), Error);
}

TEST(LoopsRun, CountAndSplitStoppedHaveNoValue) {
  CountOptions co;
  const CountRun count = count_zeros_run(kSquare, 1, kIdentity, kIdentityJacobian, co);
  EXPECT_EQ(count.summary.status, Status::Converged);
  ASSERT_TRUE(count.value && count.value->count);
  EXPECT_EQ(*count.value->count, 1u);
  co.budget.max_boxes = 0;
  co.budget.cancel.cancel();
  const CountRun cancelled = count_zeros_run(kSquare, 1, kIdentity, kIdentityJacobian, co);
  EXPECT_EQ(cancelled.summary.status, Status::Cancelled);
  EXPECT_EQ(cancelled.summary.reason, "count_zeros: cancelled");
  EXPECT_FALSE(cancelled.value);

  SplitOptions so;
  const SplitRun split = split_region_run(kSquare, kIdentity, kIdentityJacobian, so);
  EXPECT_EQ(split.summary.status, Status::Converged);
  ASSERT_TRUE(split.value);
  EXPECT_EQ(split.value->count(), std::optional<std::size_t>(1));
  so.budget.max_boxes = 1;
  const SplitRun stopped = split_region_run(kSquare, kIdentity, kIdentityJacobian, so);
  EXPECT_EQ(stopped.summary.status, Status::Stopped);
  EXPECT_EQ(stopped.summary.reason,
            "split_region: budget exceeded: 2 boxes > max_boxes = 1; raise options.budget.max_boxes (0: no limit)");
  EXPECT_FALSE(stopped.value);
}

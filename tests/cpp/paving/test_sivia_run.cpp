// sivia_run and kernel_sivia_run (sivia.h, outcome.h): one Summary for every
// ending. A spent budget or a cancellation keeps the paving so far, whose
// unclassified boxes are Boundary leaves: it still encloses the solution set.
// The progress hook is called every progress_every boxes, in order.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include "sillage/budget.h"
#include "sillage/outcome.h"
#include "sillage/paving/sivia_function.h"

using namespace sillage;

namespace {

// The ring 1 <= x^2 + y^2 <= 4 over [-3, 3]^2.
const Function kRing({"x", "y"}, "x^2 + y^2");
const IntervalVector kBox{Interval(-3, 3), Interval(-3, 3)};

SiviaOptions sequential(std::size_t max_boxes) {
  SiviaOptions o;
  o.parallel = false;
  o.budget.max_boxes = max_boxes;
  return o;
}

// Points of the ring on a polar grid (near its two circles too).
std::vector<std::pair<double, double>> ring_points() {
  std::vector<std::pair<double, double>> pts;
  for (int i = 0; i < 64; ++i) {
    const double a = 2 * M_PI * i / 64;
    for (double r : {1.0001, 1.25, 1.5, 1.75, 1.9999}) pts.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return pts;
}

// The leaves of the outer approximation: Inner and Boundary.
std::vector<IntervalVector> outer_leaves(const Paving& p) {
  std::vector<IntervalVector> outer = p.inner(), boundary = p.boundary();
  outer.insert(outer.end(), boundary.begin(), boundary.end());
  return outer;
}

// Every point of ring_points() is in a leaf of the outer approximation of p.
void expect_encloses(const Paving& p) {
  const std::vector<IntervalVector> outer = outer_leaves(p);
  for (const auto& [x, y] : ring_points()) {
    const IntervalVector pt{Interval(x), Interval(y)};
    bool in = false;
    for (const auto& b : outer) in = in || b.intersects(pt);
    EXPECT_TRUE(in) << x << " " << y;
  }
}

}  // namespace

TEST(SiviaRun, ConvergedIsTheThrowingFormsPaving) {
  SiviaOptions unlimited;
  unlimited.budget.max_boxes = 0;
  const SiviaResult r = sivia_run(kBox, kRing, Interval(1, 4), 0.05, unlimited);
  EXPECT_EQ(r.summary.status, Status::Converged);
  EXPECT_EQ(r.summary.reason, "");
  EXPECT_TRUE(r.summary.finished());
  EXPECT_EQ(r.summary.work, r.paving.nb_nodes());
  EXPECT_EQ(r.paving, sivia(kBox, kRing, Interval(1, 4), 0.05, unlimited));
  for (bool parallel : {false, true}) {
    SiviaOptions o = unlimited;
    o.parallel = parallel;
    EXPECT_EQ(sivia_run(kBox, kRing, Interval(1, 4), 0.05, o).paving, r.paving) << parallel;
  }
}

TEST(SiviaRun, StoppedKeepsAnEnclosure) {
  const SiviaOptions full = sequential(0);
  const Paving complete = sivia(kBox, kRing, Interval(1, 4), 0.01, full);
  for (std::size_t max_boxes : {1, 2, 10, 100, 1000, 5000}) {
    const SiviaResult r = sivia_run(kBox, kRing, Interval(1, 4), 0.01, sequential(max_boxes));
    EXPECT_EQ(r.summary.status, Status::Stopped) << max_boxes;
    EXPECT_EQ(r.summary.reason, "sivia: budget exceeded: " + std::to_string(max_boxes + 1) +
                                    " boxes > max_boxes = " + std::to_string(max_boxes) +
                                    "; raise options.budget.max_boxes (0: no limit) or use a larger eps");
    EXPECT_FALSE(r.summary.finished());
    // The nodes counted are the nodes stored: a few past the limit (the boxes
    // being processed end as Boundary leaves).
    EXPECT_EQ(r.summary.work, r.paving.nb_nodes());
    EXPECT_GT(r.paving.nb_nodes(), max_boxes);
    EXPECT_LT(r.paving.nb_nodes(), max_boxes + 200);
    expect_encloses(r.paving);
    // Coarser than the full paving, never beyond it.
    EXPECT_GE(r.paving.outer_volume() + 1e-9, complete.outer_volume());
    EXPECT_LE(r.paving.volume(PavingTag::Inner), complete.volume(PavingTag::Inner) + 1e-9);
    // The throwing form raises the same message.
    try {
      sivia(kBox, kRing, Interval(1, 4), 0.01, sequential(max_boxes));
      ADD_FAILURE() << "no BudgetExceeded";
    } catch (const BudgetExceeded& e) {
      EXPECT_EQ(e.what(), r.summary.reason);
    }
  }
  // In parallel too, the partial paving is an enclosure.
  SiviaOptions par = sequential(3000);
  par.parallel = true;
  const SiviaResult r = sivia_run(kBox, kRing, Interval(1, 4), 0.01, par);
  EXPECT_EQ(r.summary.status, Status::Stopped);
  expect_encloses(r.paving);
}

TEST(SiviaRun, CancelledKeepsAnEnclosure) {
  for (bool parallel : {false, true}) {
    SiviaOptions o = sequential(0);
    o.parallel = parallel;
    o.budget.max_bytes = 0;
    // Cancelled before the start: the first box is separated, then left.
    o.budget.cancel.cancel();
    SiviaResult r = sivia_run(kBox, kRing, Interval(1, 4), 1e-3, o);
    EXPECT_EQ(r.summary.status, Status::Cancelled);
    EXPECT_EQ(r.summary.reason, "sivia: cancelled");
    expect_encloses(r.paving);
    EXPECT_THROW(std::move(r).take(), Cancelled);
    // From another thread, during a long run.
    o.budget.cancel.reset();
    const CancelToken token = o.budget.cancel;
    std::thread canceller([token] {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      token.cancel();
    });
    r = sivia_run(kBox, kRing, Interval(1, 4), 1e-9, o);
    canceller.join();
    EXPECT_EQ(r.summary.status, Status::Cancelled) << parallel;
    expect_encloses(r.paving);
  }
}

TEST(SiviaRun, NoSolutionSaysWhy) {
  const SiviaResult r = sivia_run(kBox, kRing, Interval(20, 30), 0.01, sequential(0));
  EXPECT_EQ(r.summary.status, Status::NoSolution);
  EXPECT_EQ(r.summary.reason, "sivia: every box of the initial box is proven outside X (X ∩ x0 is empty)");
  EXPECT_TRUE(r.summary.finished());
  EXPECT_TRUE(r.paving.boundary().empty());
  EXPECT_NO_THROW(sivia(kBox, kRing, Interval(20, 30), 0.01));  // not an error
  const SiviaResult e = sivia_run(IntervalVector::empty(2), kRing, Interval(1, 4), 0.01);
  EXPECT_EQ(e.summary.status, Status::NoSolution);
  EXPECT_EQ(e.summary.reason, "sivia: the initial box is empty");
  EXPECT_EQ(status_name(Status::NoSolution), std::string("no solution"));
}

TEST(SiviaRun, KernelSiviaStopped) {
  const Function lo({"x", "y"}, "x^2 + y^2 - 1"), hi({"x", "y"}, "x^2 + y^2 - 0.5");
  const SiviaResult r = kernel_sivia_run(kBox, lo, hi, 0.01, sequential(500));
  EXPECT_EQ(r.summary.status, Status::Stopped);
  EXPECT_EQ(r.summary.reason.rfind("kernel_sivia: budget exceeded: 501 boxes > max_boxes = 500", 0), 0u);
  // The kernel 0.5 <= x^2 + y^2 <= 1 holds (0.75, 0) and (0, -0.9).
  bool a = false, b = false;
  for (const auto& box : outer_leaves(r.paving)) {
    a = a || (box[0].contains(0.75) && box[1].contains(0));
    b = b || (box[0].contains(0) && box[1].contains(-0.9));
  }
  EXPECT_TRUE(a && b);
}

TEST(SiviaRun, ProgressHookPerRound) {
  SiviaOptions o = sequential(0);
  std::vector<Progress> calls;
  o.budget.progress = [&calls](const Progress& p) { calls.push_back(p); };
  o.budget.progress_every = 100;
  const SiviaResult r = sivia_run(kBox, kRing, Interval(1, 4), 0.01, o);
  ASSERT_EQ(r.summary.status, Status::Converged);
  ASSERT_EQ(calls.size(), r.paving.nb_nodes() / 100);
  EXPECT_EQ(r.summary.rounds, calls.size());
  for (std::size_t i = 0; i < calls.size(); ++i) {
    EXPECT_STREQ(calls[i].where, "sivia");
    EXPECT_EQ(calls[i].round, i + 1);
    EXPECT_EQ(calls[i].work, 100 * (i + 1));
    if (i > 0) {
      EXPECT_GE(calls[i].seconds, calls[i - 1].seconds);
    }
  }
  // Same paving as without the hook.
  EXPECT_EQ(r.paving, sivia(kBox, kRing, Interval(1, 4), 0.01, sequential(0)));
  // In parallel: one call at a time, rounds in order, work never decreasing.
  calls.clear();
  o.parallel = true;
  const SiviaResult p = sivia_run(kBox, kRing, Interval(1, 4), 0.01, o);
  ASSERT_EQ(calls.size(), p.paving.nb_nodes() / 100);
  for (std::size_t i = 0; i < calls.size(); ++i) {
    EXPECT_EQ(calls[i].round, i + 1);
    if (i > 0) {
      EXPECT_GE(calls[i].work, calls[i - 1].work);
    }
  }
  // A hook that throws ends the run with its exception; progress_every = 0: never called.
  o.budget.progress = [](const Progress&) { throw std::runtime_error("enough"); };
  EXPECT_THROW(sivia_run(kBox, kRing, Interval(1, 4), 0.01, o), std::runtime_error);
  o.budget.progress_every = 0;
  EXPECT_EQ(sivia_run(kBox, kRing, Interval(1, 4), 0.01, o).summary.rounds, 0u);
}

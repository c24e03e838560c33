// temporal_slam (Alg. 15) on the figure eight with a 3-D state (x1, x2,
// depth), f(x, u) = u (velocities measured), h(x) = (x1, x2): fast then
// accurate, rows numbered, the truth in every gate and slice of x after each
// algorithm, accurate never wider than fast; errors.
#include <gtest/gtest.h>

#include "small_slam.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/error.h"
#include "sillage/expr/function.h"
#include "sillage/slam/temporal_slam.h"

using namespace sillage;

namespace {

struct Mission {
  slam_test::SmallSlam s;
  TubeVector x{s.td, 3}, v{s.td, 3};
  TubeVector u{std::vector<Tube>{s.w[0], s.w[1], Tube(s.td, Interval(-0.01, 0.01))}};
  Function f{{"x1", "x2", "x3", "u1", "u2", "u3"}, "(u1, u2, u3)"};
  Function h{{"x1", "x2", "x3"}, "(x1, x2)"};
  std::vector<Trajectory> truth{s.truth[0], s.truth[1], Trajectory("-5", s.td->t0_tf())};
  Mission() { x.set_gate(0, IntervalVector{s.p.gate(0)[0], s.p.gate(0)[1], Interval(-5.05, -4.95)}); }
};

}  // namespace

TEST(TemporalSlam, FastThenAccurateKeepTheTruth) {
  Mission m;
  TemporalSlamOptions o;
  o.eps = 0.01;
  o.accurate = false;
  const auto fast = temporal_slam(m.x, m.v, m.u, m.s.z, m.f, m.h, o);
  ASSERT_FALSE(fast.empty());
  EXPECT_TRUE(fast.front().fast);
  EXPECT_TRUE(m.x.contains(m.truth));
  const TubeVector after_fast = m.x;
  o.fast = false;
  o.accurate = true;
  const auto acc = temporal_slam(m.x, m.v, m.u, m.s.z, m.f, m.h, o);
  ASSERT_FALSE(acc.empty());
  EXPECT_FALSE(acc.front().fast);
  EXPECT_TRUE(m.x.contains(m.truth));
  EXPECT_TRUE(m.x.is_subset(after_fast));
  EXPECT_GT(acc.back().contraction_tf, 0.1);
  EXPECT_EQ(acc.back().nb_proofs, 1u);
}

TEST(TemporalSlam, BothInOneCallNumberTheRows) {
  Mission m;
  TemporalSlamOptions o;
  o.eps = 0.01;
  const auto rows = temporal_slam(m.x, m.v, m.u, m.s.z, m.f, m.h, o);
  ASSERT_GE(rows.size(), 2u);
  EXPECT_TRUE(rows.front().fast);
  EXPECT_FALSE(rows.back().fast);
  EXPECT_GT(rows.back().contraction_tf, 0.1);  // against dead reckoning
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].iteration, i + 1);
    if (i) {
      EXPECT_GE(rows[i].cumulated_seconds, rows[i - 1].cumulated_seconds);
    }
  }
  EXPECT_TRUE(m.x.contains(m.truth));
}

TEST(TemporalSlam, BadInputSaysWhatAndWhere) {
  Mission m;
  TemporalSlamOptions o;
  EXPECT_THROW(temporal_slam(m.x, m.v, m.u, m.s.z, Function({"x1", "x2"}, "(x1, x2)"), m.h, o), DimensionError);
  EXPECT_THROW(temporal_slam(m.x, m.v, m.u, m.s.z, m.f, Function({"x1", "x2", "x3"}, "(x1, x2, x1)"), o), DimensionError);
  TubeVector v2(m.s.td, 2);
  EXPECT_THROW(temporal_slam(m.x, v2, m.u, m.s.z, m.f, m.h, o), DimensionError);
  o.fast = o.accurate = false;
  EXPECT_THROW(temporal_slam(m.x, m.v, m.u, m.s.z, m.f, m.h, o), Error);
}

// on_iteration sees every row, in order, with the p of that iteration: the
// truth inside p at every gate and slice of every iteration, the accurate
// iterations never wider than the last fast one, the rows' seconds untouched
// by the observer.
TEST(TemporalSlam, EveryIterationIsObservedAndKeepsTheTruth) {
  Mission m;
  TemporalSlamOptions o;
  o.eps = 0.01;
  std::vector<std::size_t> seen;
  std::size_t lost = 0, wider = 0;
  TubeVector last_fast(m.s.td, 2);
  o.on_iteration = [&](const SlamRow& r, const TubeVector& p) {
    seen.push_back(r.iteration);
    ASSERT_EQ(p.size(), 2u);
    if (!p.contains(std::vector<Trajectory>{m.truth[0], m.truth[1]})) ++lost;
    if (r.fast) last_fast = p;
    else if (!p.is_subset(last_fast)) ++wider;
  };
  const auto rows = temporal_slam(m.x, m.v, m.u, m.s.z, m.f, m.h, o);
  ASSERT_EQ(seen.size(), rows.size());
  for (std::size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], i + 1);
  EXPECT_EQ(lost, 0u);
  EXPECT_EQ(wider, 0u);
  EXPECT_TRUE(m.x.contains(m.truth));
}

// An observer that throws stops the run with its error (nothing swallowed).
TEST(TemporalSlam, AThrowingObserverStopsTheRun) {
  Mission m;
  TemporalSlamOptions o;
  o.eps = 0.01;
  o.on_iteration = [](const SlamRow&, const TubeVector&) { throw Error("observer: stop"); };
  EXPECT_THROW(temporal_slam(m.x, m.v, m.u, m.s.z, m.f, m.h, o), Error);
}

// C_f works both ways: v = f(x, u) = (u1, x1 - x2) with v2 = 0 known forces
// x1 = x2 (the backward pass of HC4 contracts x, u is only read).
TEST(TemporalSlam, EvolutionContractsTheStateBackward) {
  const auto td = TDomain::create(0.0, 1.0, 0.1);
  TubeVector x(td, 2), v(td, IntervalVector{Interval(-1, 1), Interval(0, 0)});
  x.set_gate(0, IntervalVector{Interval(0, 1), Interval(0.5, 3)});
  const TubeVector u(td, IntervalVector{Interval(0, 0)}), z(td, IntervalVector{Interval(0, 0)});
  const Function f({"x1", "x2", "u1"}, "(u1, x1 - x2)"), h({"x1", "x2"}, "(x1, x2)");
  TemporalSlamOptions o;
  o.eps = 0.1;
  o.accurate = false;
  o.max_rounds = 1;
  temporal_slam(x, v, u, z, f, h, o);
  EXPECT_TRUE(x[1].gate(0).is_subset(Interval(0.5, 1)));
  EXPECT_TRUE(x[0].gate(0).is_subset(Interval(0.5, 1)));
  EXPECT_TRUE(x[0].gate(10).is_subset(Interval(0.5, 1)));  // x' = v = 0 carries it forward
  EXPECT_TRUE(x[1].contains(Trajectory("0.75", td->t0_tf())));
}

// temporal_slam_run (outcome.h): its Summary says how the run ended, the
// tubes are enclosures of the truth whatever the status, and the progress
// hook is called once per iteration of C_{p⇒z}.

namespace {

TemporalSlamResult run(Mission& m, const TemporalSlamOptions& o) {
  return temporal_slam_run(m.x, m.v, m.u, m.s.z, m.f, m.h, o);
}

TemporalSlamOptions options() {
  TemporalSlamOptions o;
  o.eps = 0.01;
  return o;
}

}  // namespace

TEST(TemporalSlamRun, ConvergedWithAProgressRoundPerIteration) {
  Mission m;
  TemporalSlamOptions o = options();
  std::size_t calls = 0;
  o.progress = [&](const Progress& p) {
    ++calls;
    EXPECT_EQ(p.round, calls);
    EXPECT_EQ(p.work, calls);
    EXPECT_STREQ(p.where, "temporal_slam");
  };
  const TemporalSlamResult r = run(m, o);
  EXPECT_EQ(r.summary.status, Status::Converged) << r.summary.str();
  EXPECT_EQ(r.summary.reason, "");
  EXPECT_EQ(r.summary.work, r.rows.size());
  EXPECT_EQ(r.summary.rounds, r.rows.size());
  EXPECT_EQ(calls, r.rows.size());
  EXPECT_TRUE(m.x.contains(m.truth));
  Mission again;
  EXPECT_EQ(temporal_slam(again.x, again.v, again.u, again.s.z, again.f, again.h, options()).size(), r.rows.size());
}

TEST(TemporalSlamRun, MaxRoundsIsStopped) {
  Mission m;
  TemporalSlamOptions o = options();
  o.fast = false;  // the accurate algorithm needs two rounds here
  o.max_rounds = 1;
  const TemporalSlamResult r = run(m, o);
  EXPECT_EQ(r.summary.status, Status::Stopped);
  EXPECT_EQ(r.summary.reason,
            "temporal_slam: the accurate algorithm ran max_rounds = 1 rounds without reaching its fixed point; raise "
            "options.max_rounds");
  EXPECT_TRUE(m.x.contains(m.truth));
  // The throwing form returns the rows of a stopped run, as before.
  Mission again;
  EXPECT_EQ(temporal_slam(again.x, again.v, again.u, again.s.z, again.f, again.h, o).size(), r.rows.size());
}

TEST(TemporalSlamRun, CancelledKeepsTheTubesSoFar) {
  Mission m;
  TemporalSlamOptions o = options();
  o.progress = [&o](const Progress&) { o.cancel.cancel(); };  // after the first iteration
  const TemporalSlamResult r = run(m, o);
  EXPECT_EQ(r.summary.status, Status::Cancelled);
  EXPECT_EQ(r.summary.reason, "temporal_slam: cancelled");
  EXPECT_EQ(r.rows.size(), 1u);
  EXPECT_TRUE(m.x.contains(m.truth));
  Mission again;
  TemporalSlamOptions c = options();
  c.cancel.cancel();
  EXPECT_THROW(temporal_slam(again.x, again.v, again.u, again.s.z, again.f, again.h, c), Cancelled);
}

TEST(TemporalSlamRun, EmptiedIsNoSolutionWithWhere) {
  Mission m;
  const std::size_t n = m.x.nb_slices();
  m.x.set_gate(n, IntervalVector{Interval(100, 101), Interval(100, 101), Interval(-5, -5)});  // out of reach
  const TemporalSlamResult r = run(m, options());
  EXPECT_EQ(r.summary.status, Status::NoSolution);
  EXPECT_EQ(r.summary.reason, "temporal_slam: x emptied by x' = v in round 1 of the fast algorithm");
  EXPECT_TRUE(r.rows.empty());
  EXPECT_TRUE(m.x.is_empty());
}

// examples/problems/temporal_slam.toml (the figure eight of
// tests/cpp/slam/small_slam.h as a problem file) against the C++ temporal
// SLAM on the same initial domains: the hand-written network
// (CtcDeriv, CtcPImpliesZ) and temporal_slam() (Alg. 15, accurate only).
#include <gtest/gtest.h>

#include <cmath>

#include "problem_text.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/expr/function.h"
#include "sillage/problem/solve_problem.h"
#include "sillage/slam/ctc_p_implies_z.h"
#include "sillage/slam/temporal_slam.h"

using namespace sillage;

namespace {

Problem slam_problem() { return load_problem(problem_test::problems_dir() + "/temporal_slam.toml"); }

// The file's initial domains, copied (the network of the file is not run).
struct Start {
  TubeVector p, w, z;
};

Start start_of(const Problem& file) {
  const BuiltProblem b = build_network(file, *file.time.delta);
  return {*b.var("p").tubes, *b.var("w").tubes, *b.var("z").tubes};
}

void expect_same(const TubeVector& a, const TubeVector& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t k = 0; k <= a.nb_slices(); ++k) {
      ASSERT_EQ(a[i].gate(k), b[i].gate(k)) << i << " gate " << k;
      if (k < a.nb_slices()) {
        ASSERT_EQ(a[i].slice(k), b[i].slice(k)) << i << " slice " << k;
      }
    }
}

}  // namespace

// The small_slam.h inputs are what the file states: the same tubes, bit for bit.
TEST(ProblemTemporalSlam, FileStatesTheSmallSlamInputs) {
  const Problem file = slam_problem();
  const Start s = start_of(file);
  const auto td = s.p.tdomain();
  ASSERT_EQ(td->nb_slices(), 500u);
  const Tube w0(td, "10*cos(t - 0.5) + [-0.2, 0.2]"), w1(td, "10*cos(2*t - 1) + [-0.2, 0.2]");
  const Tube z(td, "sin(10*sin(t - 0.5)/3) + cos(5*sin(2*t - 1)/4) + sin(t - 0.5) + [-0.01, 0.01]");
  expect_same(s.w, TubeVector(std::vector<Tube>{w0, w1}));
  expect_same(s.z, TubeVector(std::vector<Tube>{z}));
  EXPECT_TRUE(s.p[0].gate(0).is_subset(Interval(-4.85, -4.75).inflate(1e-15)));
  EXPECT_TRUE(Interval(-4.85, -4.75).is_subset(s.p[0].gate(0)));
  EXPECT_TRUE(Interval(-4.26, -4.16).is_subset(s.p[1].gate(0)));
}

// The file's network is the hand-written one: the same tubes, bit for bit.
TEST(ProblemTemporalSlam, SameTubesAsTheHandWrittenNetwork) {
  const Problem file = slam_problem();
  const Start s = start_of(file);
  auto p = std::make_shared<TubeVector>(s.p), w = std::make_shared<TubeVector>(s.w);
  auto z = std::make_shared<TubeVector>(s.z);
  ContractorNetwork cn;
  cn.set_ratio(0);
  cn.add(std::make_shared<CtcDeriv>(), {p, w});
  cn.add(std::make_shared<CtcPImpliesZ>(0.01), {p, w, z});
  ASSERT_FALSE(cn.contract().empty);
  const SolveResult r = solve_problem(file);
  ASSERT_FALSE(r.empty) << r.why_empty;
  expect_same(*r.built.var("p").tubes, *p);
  expect_same(*r.built.var("w").tubes, *w);
}

// temporal_slam (Alg. 15, accurate) with x = p, f(x, u) = u, u = w, h the
// identity, on the file's initial domains.
TEST(ProblemTemporalSlam, AgainstTemporalSlam) {
  const Problem file = slam_problem();
  const Start s = start_of(file);
  TubeVector x = s.p, v = s.w;
  TemporalSlamOptions o;
  o.eps = 0.01;
  o.fast = false;
  const auto rows = temporal_slam(x, v, s.w, s.z, Function({"x1", "x2", "u1", "u2"}, "(u1, u2)"),
                                  Function({"x1", "x2"}, "(x1, x2)"), o);
  ASSERT_FALSE(rows.empty());
  const SolveResult r = solve_problem(file);
  ASSERT_FALSE(r.empty) << r.why_empty;
  // Bit for bit: Alg. 15's rounds (C_d/dt, then C_p=>z to its fixed point,
  // while it contracts) are the network's FIFO rounds with the wake ratio 0.
  expect_same(*r.built.var("p").tubes, x);
  expect_same(*r.built.var("w").tubes, v);
  // What the loop brings: p(tf) narrower than dead reckoning (docs/slam.md:
  // more than 10 %), the truth inside at every gate.
  EXPECT_GT(rows.back().contraction_tf, 0.1);
  for (std::size_t k = 0; k <= x.nb_slices(); ++k) {
    const double t = x.tdomain()->t(k);
    ASSERT_TRUE(x[0].gate(k).contains(10 * std::sin(t - 0.5)) && x[1].gate(k).contains(5 * std::sin(2 * t - 1))) << t;
  }
}

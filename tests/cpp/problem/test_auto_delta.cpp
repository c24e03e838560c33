// The automatic δ (solve_problem.h): by uniform halving and by time regions
// (only the slices whose thickness over their gates is above a quantile are
// split). Every step encloses the truth; regions split only the thick
// slices, keep every earlier time point, and end on fewer slices.
#include <gtest/gtest.h>

#include <cmath>

#include "problem_text.h"
#include "sillage/problem/refined_points.h"
#include "sillage/problem/solve_problem.h"

using namespace sillage;

namespace {

// x' = v with v = cos(t) ± 0.01, x(0) = 0: the truth is sin(t). The slices
// are thick where |v| is large (x moves fast), thin near t = π/2, 3π/2.
const std::string kProblem =
    "[time]\ndomain = [0, 6]\ndelta = \"auto\"\n"
    "[var.x]\nkind = \"tube\"\nat = [{ t = 0, value = 0 }]\n"
    "[var.v]\nkind = \"tube\"\nvalue = \"cos(t) + [-0.01, 0.01]\"\n"
    "[[constraint]]\nkind = \"deriv\"\nx = \"x\"\nv = \"v\"\n";

void expect_truth_inside(const BuiltProblem& b) {
  const Tube& x = (*b.var("x").tubes)[0];
  for (std::size_t k = 0; k < x.nb_slices(); ++k) {
    EXPECT_TRUE(x.gate(k).contains(std::sin(b.td->t(k)))) << k;
    const double mid = (b.td->t(k) + b.td->t(k + 1)) / 2;
    EXPECT_TRUE(x.slice(k).contains(std::sin(mid))) << k;
  }
}

}  // namespace

TEST(AutoDelta, RegionsSplitOnlyTheThickSlices) {
  const Problem p = problem_test::parse(kProblem);
  BuiltProblem b = build_network(p, 6.0 / 64);
  ASSERT_FALSE(b.cn->contract().empty);
  const std::vector<double> pts = detail::refined_points(b, 0.5);
  // Every old point kept, about half the slices split (ties at the quantile are not split).
  for (std::size_t k = 0; k <= b.td->nb_slices(); ++k)
    EXPECT_TRUE(std::binary_search(pts.begin(), pts.end(), b.td->t(k))) << k;
  EXPECT_GT(pts.size(), 64u + 1 + 16);
  EXPECT_LE(pts.size(), 64u + 1 + 32);
  // The split slices are the ones of largest excess thickness over their gates, summed over x and v.
  const auto excess = [&](std::size_t k) {
    double e = 0;
    for (const char* name : {"x", "v"}) {
      const Tube& y = (*b.var(name).tubes)[0];
      e += std::max(0.0, y.slice(k).diam() - std::max(y.gate(k).diam(), y.gate(k + 1).diam()));
    }
    return e;
  };
  double split_min = INFINITY, kept_max = 0;
  for (std::size_t k = 0; k < b.td->nb_slices(); ++k) {
    const bool split = std::binary_search(pts.begin(), pts.end(), (b.td->t(k) + b.td->t(k + 1)) / 2);
    (split ? split_min : kept_max) = split ? std::min(split_min, excess(k)) : std::max(kept_max, excess(k));
  }
  EXPECT_GT(split_min, kept_max);
  // q = 1: no slice above the largest, so every slice is split (halving).
  EXPECT_EQ(detail::refined_points(b, 1.0).size(), 2u * 64 + 1);
  EXPECT_THROW((void)detail::refined_points(b, 1.5), Error);
  // The network on these points: a valid enclosure, thinner.
  BuiltProblem fine = build_network(p, pts);
  ASSERT_FALSE(fine.cn->contract().empty);
  expect_truth_inside(fine);
  EXPECT_LT(mean_thickness(fine), mean_thickness(b));
  EXPECT_THROW((void)build_network(p, std::vector<double>{0, 3}), Error);  // not up to tf
}

TEST(AutoDelta, RegionsAgainstHalving) {
  const Problem p = problem_test::parse(kProblem);
  SolveOptions halving, regions;
  halving.refinement = DeltaRefinement::Halving;
  regions.refinement = DeltaRefinement::Regions;
  std::vector<std::size_t> slices;
  for (const SolveOptions& o : {halving, regions}) {
    SolveOptions with_steps = o;
    with_steps.on_step = [](const ScheduleStep& s) { EXPECT_GT(s.slices, 0u); };
    const SolveResult r = solve_problem(p, with_steps);
    ASSERT_FALSE(r.empty);
    ASSERT_GE(r.schedule.size(), 2u);
    expect_truth_inside(r.built);
    // Each step thinner than the first, the last within the tolerance of the one before.
    EXPECT_LT(r.schedule.back().mean_thickness, r.schedule.front().mean_thickness);
    const double a = r.schedule[r.schedule.size() - 2].mean_thickness, z = r.schedule.back().mean_thickness;
    EXPECT_LE(std::abs(a - z), 0.01 * a);
    slices.push_back(r.schedule.back().slices);
  }
  EXPECT_LT(slices[1], slices[0]);
  EXPECT_EQ(SolveOptions{}.refinement, DeltaRefinement::Halving);  // the default (docs/cli.md: the faster)
}

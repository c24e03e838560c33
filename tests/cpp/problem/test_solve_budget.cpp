// A solve's budget (SolveOptions::budget): spent, the result is the domains
// contracted so far, still enclosures, with why they are not the fixed point;
// cancelled, Cancelled out of solve_problem.
#include <gtest/gtest.h>

#include "problem_text.h"
#include "sillage/problem/solve_problem.h"

using namespace sillage;

namespace {

// x = y and y = 0.99999 x from [0, 10^6]: millions of contractor runs to the fixed point {0}.
const std::string kSlow =
    "[time]\ndomain = [0, 1]\ndelta = 0.5\n[network]\nratio = 0\n[var.x]\nkind = \"interval\"\n"
    "value = \"[0, 1000000]\"\n[var.y]\nkind = \"interval\"\nvalue = \"[0, 1000000]\"\n"
    "[[constraint]]\nkind = \"expr\"\nexpr = \"x - y\"\n[[constraint]]\nkind = \"expr\"\nexpr = \"y - 0.99999*x\"\n";

}  // namespace

TEST(SolveBudget, SpentIsAnAnswerWithWhy) {
  SolveOptions o;
  o.budget.max_boxes = 1000;
  const SolveResult r = solve_problem(problem_test::parse(kSlow), o);
  EXPECT_FALSE(r.empty);
  EXPECT_NE(r.stopped.find("1001 contractor calls > max_boxes = 1000"), std::string::npos) << r.stopped;
  const Interval& x = *r.built.var("x").interval;
  EXPECT_TRUE(x.contains(0.0));  // the only solution, still enclosed
  EXPECT_LT(x.ub(), 1e6);         // contracted, not to the fixed point
  EXPECT_GT(x.ub(), 1.0);
  ASSERT_EQ(r.schedule.size(), 1u);  // no further delta tried
}

TEST(SolveBudget, CancelledIsAnException) {
  SolveOptions o;
  o.budget.cancel.cancel();
  EXPECT_THROW((void)solve_problem(problem_test::parse(kSlow), o), Cancelled);
}

// SolveResult::summary: the network's outcome for the whole solve.
TEST(SolveSummary, StoppedWithTheBudgetAsReason) {
  SolveOptions o;
  o.budget.max_boxes = 1000;
  const SolveResult r = solve_problem(problem_test::parse(kSlow), o);
  EXPECT_EQ(r.summary.status, Status::Stopped);
  EXPECT_FALSE(r.summary.finished());
  EXPECT_EQ(r.summary.reason, r.stopped);
  EXPECT_EQ(r.summary.work, 1000u);  // the contractor calls done before the 1001st
  EXPECT_EQ(r.summary.work, r.schedule.back().stats.contractor_calls);
  EXPECT_GE(r.summary.rounds, 1u);
  EXPECT_GE(r.summary.seconds, r.contract_seconds());
}

namespace {

// x in [0, 10] with x - c = 0: the solution {c}, none for c outside [0, 10].
std::string point_problem(const std::string& c) {
  return "[time]\ndomain = [0, 1]\ndelta = 0.5\n[var.x]\nkind = \"interval\"\nvalue = \"[0, 10]\"\n"
         "[[constraint]]\nkind = \"expr\"\nexpr = \"x - " + c + "\"\n";
}

}  // namespace

TEST(SolveSummary, ConvergedAtTheFixedPoint) {
  const SolveResult r = problem_test::solve_text(point_problem("1"));
  EXPECT_EQ(r.summary.status, Status::Converged);
  EXPECT_TRUE(r.summary.finished());
  EXPECT_EQ(r.summary.reason, "");
  EXPECT_EQ(r.summary.work, r.schedule.back().stats.contractor_calls);
  EXPECT_EQ(r.summary.rounds, r.schedule.back().stats.iterations);
  EXPECT_GT(r.summary.work, 0u);
  EXPECT_EQ(*r.built.var("x").interval, Interval(1.0));
}

TEST(SolveSummary, NoSolutionWithTheConstraintAsReason) {
  const SolveResult r = problem_test::solve_text(point_problem("20"));
  ASSERT_TRUE(r.empty);
  EXPECT_EQ(r.summary.status, Status::NoSolution);
  EXPECT_TRUE(r.summary.finished());
  EXPECT_EQ(r.summary.reason, r.why_empty);
  EXPECT_NE(r.summary.reason.find("test.toml"), std::string::npos) << r.summary.reason;  // the constraint's place
  EXPECT_NE(r.summary.str().find("no solution"), std::string::npos) << r.summary.str();
}

TEST(SolveSummary, AutoDeltaCountsEveryStep) {
  SolveOptions o;
  o.auto_delta = true;
  o.tolerance = 0;  // never settles: refine until the slices run out
  o.max_slices = 512;
  const SolveResult r = solve_problem(problem_test::parse(point_problem("1")), o);
  ASSERT_GE(r.schedule.size(), 2u);
  std::size_t work = 0;
  for (const ScheduleStep& s : r.schedule) work += s.stats.contractor_calls;
  EXPECT_EQ(r.summary.status, Status::Converged);
  EXPECT_EQ(r.summary.work, work);
}

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

// Inputs that `sillage check` used to pass and `solve` then refused, or that
// no check could end: each refused by the loader, at its place.
#include <gtest/gtest.h>

#include <fstream>

#include "data_tables.h"
#include "problem_text.h"
#include "sillage/error.h"
#include "sillage/problem/check_summary.h"
#include "sillage/problem/solve_problem.h"

using namespace sillage;
using problem_test::data_dir;
using problem_test::expect_error;
using problem_test::table;

// A truth whose times go back or repeat is no trajectory: said by line, with
// the key that reads it (solve used to fail on it naming no file).
TEST(LoadRefusals, ATruthInTimeOrder) {
  std::ofstream(data_dir() + "/truth_back.csv") << "t,x\n0,0\n1,1\n0.5,2\n";
  std::ofstream(data_dir() + "/truth_twice.csv") << "t,x\n0,0\n1,1\n1,2\n";
  const auto problem = [](const std::string& file) {
    return table("truth", file) +
           "[time]\ndomain = [0, 1]\ndelta = 0.5\n[var.x]\nkind = \"tube\"\n"
           "[[constraint]]\nkind = \"expr\"\nexpr = \"x\"\n"
           "[output]\ntruth = { data = \"truth\", time = \"t\", columns = { x = \"x\" } }\n";
  };
  expect_error(problem("truth_back.csv"), "test.toml:12:34: found the stamps 1 at " + data_dir() +
                                              "/truth_back.csv:3 and 0.5 at line 4 of 'truth', not increasing, "
                                              "expected a truth with strictly increasing times");
  expect_error(problem("truth_twice.csv"), "the stamps 1 at " + data_dir() + "/truth_twice.csv:3 and 1 at line 4");
}

// A problem file that is a device (/dev/zero): refused at once, not read without end.
TEST(LoadRefusals, ADeviceIsNoProblemFile) {
  std::string msg;
  try {
    (void)load_problem("/dev/zero");
  } catch (const Error& e) {
    msg = e.what();
  }
  EXPECT_NE(msg.find("'/dev/zero' is a device, not a problem file (TOML)"), std::string::npos) << msg;
}

// An eval over several tubes at one time has a node per row: an emptiness
// names the row by its line, whichever domain the row's CtcEval emptied.
TEST(LoadRefusals, AnInconsistentRowOverTwoTubesIsNamed) {
  std::ofstream(data_dir() + "/two_tubes.csv") << "t,a,b\n0.5,0,0\n1,5,5\n";
  const SolveResult r = problem_test::solve_text(table("m", "two_tubes.csv") +
                                        "[time]\ndomain = [0, 2]\ndelta = 0.1\n[var.x]\nkind = \"tube\"\nvalue = \"[-1, 1]\"\n"
                                        "[var.y]\nkind = \"tube\"\nvalue = \"[-1, 1]\"\n[var.v]\nkind = \"tube\"\nvalue = \"[-1, 1]\"\n"
                                        "[[constraint]]\nkind = \"deriv\"\nx = \"x\"\nv = \"v\"\n"
                                        "[[constraint]]\nkind = \"eval\"\ndata = \"m\"\ny = [\"x\", \"y\"]\nv = [\"v\", \"\"]\n"
                                        "time = \"t\"\nexpr = \"(x - a, y - b)\"\n");
  ASSERT_TRUE(r.empty);
  EXPECT_NE(r.why_empty.find("(m line 3) emptied"), std::string::npos) << r.why_empty;
}

// A slice width that the loader accepts but no machine could hold: refused
// with the figure before anything is built (was a bare std::bad_alloc).
TEST(LoadRefusals, ASolveThatCannotFitIsRefusedWithItsFigure) {
  const Problem p = problem_test::parse("[time]\ndomain = [0, 1]\ndelta = 2.5e-8\n"
                                        "[var.x]\nkind = \"tube_vector\"\ndim = 1000\n"
                                        "[[constraint]]\nkind = \"expr\"\nexpr = \"x[0]\"\n");
  EXPECT_GT(peak_memory_estimate(p, 40'000'000), std::size_t{5'000'000'000'000});
  std::string msg;
  try {
    (void)solve_problem(p);
  } catch (const Error& e) {
    msg = e.what();
  }
  EXPECT_NE(msg.find("delta = 2.4999999999999999e-08 gives 40000000 slices: about 5587.9 GiB of memory at the peak of "
                     "the solve, more than this machine's"),
            std::string::npos)
      << msg;
  EXPECT_NE(check_summary(p).find("memory: about 5722054.0 MiB at the peak of a solve (an estimate)"), std::string::npos)
      << check_summary(p);
}

// An eval's v states y' = v: without a deriv constraint the eval adds it, and
// the sets are those of the file that writes it just before (each CtcEval
// swept its fronts over the whole tube: quadratic in the rows).
TEST(LoadRefusals, AnEvalsDerivativeHoldsOverTheTube) {
  std::ofstream(data_dir() + "/fixes.csv") << "t,a\n0.5,0\n1,0.4\n1.5,0.1\n";
  const std::string head = table("m", "fixes.csv") + "[time]\ndomain = [0, 2]\ndelta = 0.1\n[var.x]\nkind = \"tube\"\n"
                           "[var.v]\nkind = \"tube\"\nvalue = \"[-1, 1]\"\n";
  const std::string eval = "[[constraint]]\nkind = \"eval\"\ndata = \"m\"\ny = \"x\"\nv = \"v\"\ntime = \"t\"\n"
                           "expr = \"x - a + [-0.01, 0.01]\"\n";
  const SolveResult implied = problem_test::solve_text(head + eval);
  const SolveResult written =
      problem_test::solve_text(head + "[[constraint]]\nkind = \"deriv\"\nx = \"x\"\nv = \"v\"\n" + eval);
  ASSERT_FALSE(implied.empty) << implied.why_empty;
  EXPECT_EQ(implied.built.cn->nb_ctc(), 2u);  // CtcDeriv, then the rows' CtcEvalList
  const Tube &a = (*implied.built.var("x").tubes)[0], &b = (*written.built.var("x").tubes)[0];
  for (std::size_t k = 0; k <= a.nb_slices(); ++k) ASSERT_EQ(a.gate(k), b.gate(k)) << "gate " << k;
  EXPECT_LT(a.gate(0).diam(), 1.1);  // 0 +- 0.01 at 0.5, |x'| <= 1: bounded at t = 0
}

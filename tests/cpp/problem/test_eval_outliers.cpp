// Outliers in problem files (issue 40 §1): `q` on an eval, over all its rows,
// per window of W seconds or per M consecutive rows (one CtcQEval per
// half-overlapping window). The robot on a line (x = sin(t) + 1) with one
// range corrupted: no solution without q, the truth inside with it.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "problem_text.h"
#include "sillage/problem/check_summary.h"
#include "sillage/problem/eval_rows.h"
#include "sillage/problem/online_problem.h"
#include "sillage/problem/report_html.h"

using namespace sillage;
using problem_test::expect_error;
using problem_test::parse;

namespace {

// beacon_ranges.csv with the ranges of the rows `bad` (0-based) 3 m too long.
std::string corrupted(const std::vector<std::size_t>& bad) {
  const auto dir = std::filesystem::temp_directory_path() / ("sillage_outliers_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ifstream in(problem_test::problems_dir() + "/data/beacon_ranges.csv");
  std::string name = "ranges";
  for (const std::size_t b : bad) name += "_" + std::to_string(b);
  const auto path = dir / (name + ".csv");
  std::ofstream out(path);
  std::size_t row = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || line[0] == 't') {
      out << line << "\n";
      continue;
    }
    if (std::find(bad.begin(), bad.end(), row++) != bad.end()) {
      const std::size_t comma = line.rfind(',');
      line = line.substr(0, comma + 1) + std::to_string(std::stod(line.substr(comma + 1)) + 3);
    }
    out << line << "\n";
  }
  return path.string();
}

std::string problem(const std::string& ranges, const std::string& keys) {
  return "[time]\ndomain = [0, 20]\ndelta = 0.05\n[data.ranges]\nfile = \"" + ranges +
         "\"\n[data.truth]\nfile = \"data/line_truth.csv\"\n"
         "[var.x]\nkind = \"tube\"\nvalue = \"[-10, 10]\"\n"
         "[var.v]\nkind = \"tube\"\nvalue = \"cos(t) + [-0.01, 0.01]\"\n"
         "[[constraint]]\nkind = \"deriv\"\nx = \"x\"\nv = \"v\"\n"
         "[[constraint]]\nkind = \"eval\"\ndata = \"ranges\"\ny = \"x\"\nv = \"v\"\ntime = \"t\"\ntime_error = 0.01\n"
         "errors = { r = 0.001 }\n" + keys + "expr = \"abs(x - b) - r\"\n"
         "[output]\ntruth = { data = \"truth\", time = \"t\", columns = { x = \"x\" } }\n";
}

}  // namespace

TEST(EvalOutliers, OneWrongRangeEmptiesTheStrictSolveNotTheRelaxedOnes) {
  const std::string ranges = corrupted({4});
  EXPECT_TRUE(problem_test::solve_text(problem(ranges, "")).empty);
  for (const std::string keys : {"q = 1\n", "q = 1\nq_rows = 4\n", "q = 1\nq_window = 6\n", "q = 2\n"}) {
    const Problem p = parse(problem(ranges, keys));
    const SolveResult r = solve_problem(p);
    ASSERT_FALSE(r.empty) << keys << r.why_empty;
    const TruthCheck c = check_truth(p, r.built);
    EXPECT_EQ(c.inside, c.samples) << keys << c.first_misses.front();
    EXPECT_GT(c.samples, 100u);
  }
}

TEST(EvalOutliers, OnCleanDataTheRelaxedSolveHoldsTheStrictOne) {
  const std::string clean = problem_test::problems_dir() + "/data/beacon_ranges.csv";
  const SolveResult strict = problem_test::solve_text(problem(clean, ""));
  const SolveResult relaxed = problem_test::solve_text(problem(clean, "q = 1\nq_rows = 4\n"));
  ASSERT_FALSE(strict.empty);
  ASSERT_FALSE(relaxed.empty);
  const Tube& a = (*strict.built.var("x").tubes)[0];
  const Tube& b = (*relaxed.built.var("x").tubes)[0];
  for (std::size_t k = 0; k <= a.nb_slices(); ++k) EXPECT_TRUE(a.gate(k).is_subset(b.gate(k))) << k;
}

TEST(EvalOutliers, GroupsOfRowsAndWindows) {
  ConstraintSpec c;
  c.q = 1;
  std::vector<Interval> t;
  for (int i = 0; i < 10; ++i) t.push_back(Interval(i));
  c.q_rows = 4;
  const auto rows = detail::outlier_groups(c, t);
  ASSERT_EQ(rows.size(), 4u);  // [0, 4), [2, 6), [4, 8), [6, 10)
  EXPECT_EQ(rows[1], (std::vector<std::size_t>{2, 3, 4, 5}));
  EXPECT_EQ(rows[3], (std::vector<std::size_t>{6, 7, 8, 9}));
  c.q_rows = 0;
  c.q_window = 4;  // [0, 4], [2, 6], [4, 8], [6, 10]
  const auto windows = detail::outlier_groups(c, t);
  ASSERT_EQ(windows.size(), 4u);
  EXPECT_EQ(windows[0], (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(windows[3], (std::vector<std::size_t>{6, 7, 8, 9}));
  c.q = 5;  // a window of 5 rows or fewer states nothing
  EXPECT_TRUE(detail::outlier_groups(c, t).empty());
  c.q_window = 0;
  EXPECT_EQ(detail::outlier_groups(c, t).size(), 1u);
}

TEST(EvalOutliers, KeysAreCheckedAtTheirPlace) {
  const std::string clean = problem_test::problems_dir() + "/data/beacon_ranges.csv";
  expect_error(problem(clean, "q = -1\n"), "an integer >= 0");
  expect_error(problem(clean, "q = 1.5\n"), "an integer >= 0");
  expect_error(problem(clean, "q_window = 5\n"), "q_window without q");
  expect_error(problem(clean, "q = 1\nq_window = 5\nq_rows = 4\n"), "both q_window and q_rows");
  expect_error(problem(clean, "q = 2\nq_rows = 2\n"), "a number of rows > q = 2");
  expect_error(problem(clean, "q = 1\nq_window = 0\n"), "seconds > 0");
  const Problem p = parse(problem(clean, "q = 1\nq_rows = 4\n"));
  EXPECT_NE(p.constraints[1].label.find("at most 1 wrong in any 4 rows"), std::string::npos) << p.constraints[1].label;
  EXPECT_NE(check_summary(p).find("4        nodes"), std::string::npos) << check_summary(p);  // 9 rows: 4 groups
  EXPECT_THROW(OnlineProblem op(p), ProblemError);  // not online yet
}

TEST(EvalOutliers, TooManyWrongRowsInAWindowAreNamed) {
  // Rows 3 and 4 (CSV lines 6 and 7) wrong, in one window of 4 rows that allows 1.
  const SolveResult r = problem_test::solve_text(problem(corrupted({3, 4}), "q = 1\nq_rows = 4\n"));
  ASSERT_TRUE(r.empty);
  EXPECT_NE(r.why_empty.find("CtcQEval (q = 1: 2 of its 4 fixes violated by every trajectory:"), std::string::npos)
      << r.why_empty;
  EXPECT_NE(r.why_empty.find("line 6, "), std::string::npos) << r.why_empty;
  EXPECT_NE(r.why_empty.find("line 7)"), std::string::npos) << r.why_empty;
  EXPECT_NE(r.why_empty.find("at most 1 wrong in any 4 rows"), std::string::npos) << r.why_empty;
  // Allowed 2 per window, the same rows are no longer a contradiction.
  EXPECT_FALSE(problem_test::solve_text(problem(corrupted({3, 4}), "q = 2\nq_rows = 5\n")).empty);
}

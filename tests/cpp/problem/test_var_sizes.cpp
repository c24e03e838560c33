// What a user reads of a solve: the box diameter of each variable over time
// and at the truth's times (var_sizes), and how much of each stated bound the
// truth used (audit_problem), in the console, results.json and the report.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "problem_text.h"
#include "sillage/problem/bound_audit.h"
#include "sillage/problem/report_html.h"
#include "sillage/problem/var_sizes.h"
#include "sillage/problem/write_results.h"

using namespace sillage;

namespace {

// A truth at t = 0.5, 1, 2.5 (and 4, outside [0, 3]); one observation z = 1 at t = 1.
std::string tables() {
  const auto d = std::filesystem::temp_directory_path() / ("sillage_var_sizes_" + std::to_string(::getpid()));
  std::filesystem::create_directories(d);
  std::ofstream(d / "truth.csv") << "t,x\n0.5,0.3\n1,0.9\n2.5,1.25\n4,2\n";
  std::ofstream(d / "obs.csv") << "t,z\n1,1\n";
  return "[data.truth]\nfile = \"" + (d / "truth.csv").string() + "\"\n[data.obs]\nfile = \"" +
         (d / "obs.csv").string() + "\"\n";
}

// x: slice k is [0, 1] * [k, k + 1] = [0, k + 1] (width k + 1), gate k [0, k].
const std::string kProblem = R"(
[time]
domain = [0, 3]
delta = 1
[var.x]
kind = "tube"
unit = "m"
value = "[0, 1] * t"
at = [{ t = 1, value = "[0.5, 1.5]" }]
[var.y]
kind = "tube_vector"
dim = 2
value = ["[0, 2]", "[0, 0.5]"]
[var.a]
kind = "interval"
value = "[1, 4]"
[[constraint]]
kind = "expr"
expr = "a - [0, 10]"
[output]
truth = { data = "truth", time = "t", columns = { x = ["x"] } }
)";

}  // namespace

TEST(VarSizes, DiametersOverTimeAndAtTheTruthsTimes) {
  const Problem p = problem_test::parse(tables() + kProblem);
  const SolveResult r = solve_problem(p);
  ASSERT_FALSE(r.empty);
  const std::vector<VarSize> sizes = var_sizes(p, r.built);
  ASSERT_EQ(sizes.size(), 3u);
  EXPECT_EQ(sizes[0].name, "a");  // the order of Problem::vars (by name)
  const VarSize &a = sizes[0], &x = sizes[1], &y = sizes[2];
  // x: slices of widths 1, 2, 3; at the truth's times the slice [0, 1], the gate [0.5, 1] (its 'at'), the slice [0, 3].
  EXPECT_EQ(x.name, "x");
  EXPECT_EQ(x.unit, "m");
  EXPECT_EQ(x.over_time.samples, 3u);
  ASSERT_TRUE(x.at_truth.has_value());
  EXPECT_EQ(x.at_truth->samples, 3u);  // t = 4 is outside [0, 3]
  EXPECT_DOUBLE_EQ(x.over_time.mean, 2.0);
  EXPECT_DOUBLE_EQ(x.over_time.median, 2.0);
  EXPECT_DOUBLE_EQ(x.over_time.max, 3.0);
  EXPECT_DOUBLE_EQ(x.at_truth->mean, 1.5);
  EXPECT_DOUBLE_EQ(x.at_truth->median, 1.0);
  EXPECT_DOUBLE_EQ(x.at_truth->max, 3.0);
  // y: the largest width over its components, 2 everywhere; no unit stated.
  EXPECT_EQ(y.unit, "");
  EXPECT_DOUBLE_EQ(y.over_time.mean, 2.0);
  EXPECT_DOUBLE_EQ(y.over_time.median, 2.0);
  EXPECT_DOUBLE_EQ(y.at_truth->max, 2.0);
  // a: its one value.
  EXPECT_DOUBLE_EQ(a.over_time.max, 3.0);
  EXPECT_EQ(a.over_time.samples, 1u);
  EXPECT_FALSE(a.at_truth.has_value());
  EXPECT_NE(x.str().find("x: box diameter mean"), std::string::npos) << x.str();
  EXPECT_NE(x.str().find(" m, median"), std::string::npos) << x.str();
  EXPECT_NE(x.str().find("at the 3 truth times"), std::string::npos) << x.str();
  const std::string table = sizes_table(sizes);
  EXPECT_NE(table.find("variable  unit  over time"), std::string::npos) << table;
  EXPECT_NE(table.find("\nx         m     2 / 2 / 3"), std::string::npos) << table;
  EXPECT_NE(table.find("1.5 / 1 / 3\n"), std::string::npos) << table;
}

TEST(VarSizes, StatsAreWeightedByDuration) {
  const SizeStats s = size_stats({1, 2, 10}, {1, 1, 0.5});
  EXPECT_DOUBLE_EQ(s.mean, (1 + 2 + 5) / 2.5);
  EXPECT_DOUBLE_EQ(s.median, 2.0);  // half the weight (1.25) is reached at 2
  EXPECT_DOUBLE_EQ(s.max, 10.0);
  EXPECT_EQ(s.samples, 3u);
  EXPECT_EQ(size_stats({}, {}).samples, 0u);
}

TEST(VarSizes, InTheResultsAndTheReport) {
  const Problem p = problem_test::parse(tables() + kProblem);
  const SolveResult r = solve_problem(p);
  const std::string json = results_json(p, r);
  EXPECT_NE(json.find("\"sizes\""), std::string::npos);
  EXPECT_NE(json.find("\"unit\": \"m\""), std::string::npos) << json.substr(0, 3000);
  EXPECT_NE(json.find("\"bound_audit\""), std::string::npos);
  const std::string html = report_html(p, r);
  // The sizes and the audit before the results; the file itself last, folded.
  EXPECT_LT(html.find("id=\"sizes\""), html.find("id=\"results\""));
  EXPECT_LT(html.find("id=\"audit\""), html.find("id=\"results\""));
  EXPECT_LT(html.find("id=\"stats\""), html.find("<details id=\"problem\">"));
  EXPECT_NE(html.find("Box diameter of x (m)"), std::string::npos);
  EXPECT_NE(html.find("Box diameter of y"), std::string::npos);
}

TEST(VarSizes, UnitMustBeAString) {
  problem_test::expect_error("[time]\ndomain = [0, 1]\ndelta = 0.5\n[var.x]\nkind = \"tube\"\nunit = 3\n",
                             "expected a unit for the reports");
}

TEST(BoundAudit, TheTruthAgainstEachStatedBound) {
  const std::string eval = R"(
[[constraint]]
kind = "eval"
data = "obs"
y = "x"
time = "t"
expr = "x - z + [-0.5, 0.5]"
[[constraint]]
kind = "eval"
data = "obs"
y = "x"
time = "t"
expr = "x - z*a + [-0.5, 0.5]"
)";
  const Problem p = problem_test::parse(tables() + kProblem + eval);
  const std::vector<AuditLine> a = audit_problem(p);
  ASSERT_EQ(a.size(), 4u);
  // The value [0, t]: worst at t = 1, truth 0.9 against [0, 1]: 0.4 of 0.5.
  EXPECT_EQ(a[0].name, "[var.x] value of x");
  EXPECT_EQ(a[0].unit, "m");
  EXPECT_NEAR(a[0].used, 0.4, 1e-12);
  EXPECT_DOUBLE_EQ(a[0].allowed, 0.5);
  EXPECT_NE(a[0].how.find("t = 1"), std::string::npos) << a[0].how;
  // The 'at' [0.5, 1.5] at t = 1: 0.1 of 0.5.
  EXPECT_EQ(a[1].name, "[var.x] x at t = 1");
  EXPECT_NEAR(a[1].used, 0.1, 1e-12);
  EXPECT_DOUBLE_EQ(a[1].allowed, 0.5);
  EXPECT_NEAR(audit_percent(a[1]), 20, 1e-9);
  // The row: 0.9 - 1 + [-0.5, 0.5] = [-0.6, 0.4]: 0.1 of 0.5, named by its line.
  EXPECT_EQ(a[2].name, "constraint 2 (eval) on 'obs'");
  EXPECT_NEAR(a[2].used, 0.1, 1e-12);
  EXPECT_NEAR(a[2].allowed, 0.5, 1e-12);
  EXPECT_NE(a[2].how.find("obs line 2"), std::string::npos) << a[2].how;
  // a has no truth: not measurable, and the line says why.
  EXPECT_TRUE(std::isnan(a[3].used));
  EXPECT_NE(a[3].how.find("reads 'a'"), std::string::npos) << a[3].how;
  EXPECT_NE(audit_text(a[0]).find("max 0.4 m of 0.5 allowed (80 %"), std::string::npos) << audit_text(a[0]);
}

TEST(BoundAudit, AViolatedBoundIsMarked) {
  const AuditLine l{"turn rate", "rad/s", 2, 3, "measured"};
  EXPECT_DOUBLE_EQ(audit_percent(l), 150);
  EXPECT_NE(audit_text(l).find("<-- VIOLATED"), std::string::npos);
  const std::string no_truth = "[time]\ndomain = [0, 1]\ndelta = 0.5\n[var.x]\nkind = \"tube\"\n[[constraint]]\nkind = "
                               "\"expr\"\nexpr = \"x - 1\"\n";
  EXPECT_TRUE(audit_problem(problem_test::parse(no_truth)).empty());  // no truth, no audit
}

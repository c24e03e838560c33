// The initial tubes of a problem file are those of Tube(td, f) for the
// bounds' expressions, bit for bit, whether the bound depends on t or not
// (a bound without t is evaluated once, not at every slice and gate), and
// the tubes whose slices come from a table are those of their rows.
#include <gtest/gtest.h>

#include "problem_text.h"
#include "sillage/expr/function.h"
#include "sillage/problem/build_network.h"

using namespace sillage;

namespace {

void expect_same(const Tube& a, const Tube& b) {
  ASSERT_EQ(a.nb_slices(), b.nb_slices());
  for (std::size_t k = 0; k <= a.nb_slices(); ++k) {
    ASSERT_EQ(a.gate(k), b.gate(k)) << "gate " << k;
    if (k < a.nb_slices()) {
      ASSERT_EQ(a.slice(k), b.slice(k)) << "slice " << k;
    }
  }
}

}  // namespace

TEST(BuildBounds, SameTubesAsTubeOfTheExpression) {
  const std::vector<std::string> bounds{"[-10, 10]", "pi/2 + [-1, 1]/100", "sqrt(t - 2)", "max(0, [-1, 2])*tan(0.1)",
                                        "cos(t) + [-0.01, 0.01]", "tan(t/10)", "[0, 1]*t", "exp(-t)*[1, 2]"};
  std::string text = "[time]\ndomain = [0, 3]\ndelta = 0.01\n";
  for (std::size_t i = 0; i < bounds.size(); ++i)
    text.append("[var.x").append(std::to_string(i)).append("]\nkind = \"tube\"\nvalue = \"").append(bounds[i]).append("\"\n");
  text.append("[[constraint]]\nkind = \"expr\"\nexpr = \"x0 - x1\"\n");
  const Problem p = problem_test::parse(text);
  const BuiltProblem b = build_network(p, 0.01);
  for (std::size_t i = 0; i < bounds.size(); ++i) {
    SCOPED_TRACE(bounds[i]);
    expect_same((*b.vars[i].tubes)[0], Tube(b.td, Function({"t"}, bounds[i])));
  }
  EXPECT_TRUE((*b.var("x2").tubes)[0].codomain().is_unbounded());  // undefined before t = 2: the whole line there, as Tube(td, f)
}

// slices = {data, value}: slice k is its row's value (each row evaluated once
// even when added time points split its period), gate k the hull of its two slices.
TEST(BuildBounds, SlicesFromATableRowByRow) {
  const std::string text =
      "[time]\npoints = { data = \"truth\", column = \"t\" }\n"
      "[data.truth]\nfile = \"data/robot_truth.csv\"\n"
      "[data.periods]\nfile = \"../../tests/cpp/problem/fuzz_corpus/robot_periods.csv\"\n"
      "[var.s]\nkind = \"tube\"\nvalue = \"[-100, 100]\"\nslices = { data = \"periods\", value = \"speed + dt*[-1, 1]\" }\n"
      "at = [{ t = 10.125, value = \"[-50, 50]\" }]\n"  // a double: a time point
      "[[constraint]]\nkind = \"expr\"\nexpr = \"s - s\"\n";
  const Problem p = problem_test::parse(text);
  const BuiltProblem b = build_network(p, 1.0);
  const Tube& s = (*b.var("s").tubes)[0];
  ASSERT_EQ(s.nb_slices(), p.time.points.size());  // 10.125 splits the period [10, 10.25]
  const CsvTable& periods = p.table("periods")->table;
  for (std::size_t k = 0; k < s.nb_slices(); ++k) {
    const double t = s.tdomain()->t(k);
    std::size_t row = 0;
    while (row + 1 < periods.nb_rows() && p.time.points[row + 1] <= t) ++row;
    const double v = periods.row(row)[0], dt = p.time.points[row + 1] - p.time.points[row];
    ASSERT_TRUE(s.slice(k).contains(v)) << k;
    ASSERT_LE(s.slice(k).diam(), 2 * dt + 1e-9) << k;
    const Interval hull = (k > 0 ? s.slice(k - 1) : s.slice(k)) | s.slice(k);
    ASSERT_EQ(s.gate(k), hull) << k;
  }
  EXPECT_EQ(s.slice(40), s.slice(41));  // the two halves of the split period: one row
}

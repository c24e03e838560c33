// A time written in a problem file is a decimal, not its nearest double: a
// value stated at t = 1000000000.1 (an 'at') or at a table's stamp (gates =
// {data, value}) holds there, and the tube at the time point nearest to it is
// that value moved by the derivative over the rounding gap. Exact decimals
// (0, 2.5) stay gates.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "problem_text.h"
#include "sillage/problem/build_network.h"
#include "sillage/problem/report_html.h"
#include "sillage/problem/solve_problem.h"

using namespace sillage;
using problem_test::parse;

namespace {

// Whether the gate holds v within e, both in long double (v's own error is far below e).
bool holds(const Interval& gate, long double v, long double e) {
  return !gate.is_empty() && static_cast<long double>(gate.lb()) <= v - e && v + e <= static_cast<long double>(gate.ub());
}

std::string table_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()) + ".csv");
  std::ofstream(path) << text;
  return path.string();
}

}  // namespace

// The case: x' = 1000, x(1000000000.1) = 100. The double nearest to
// 1000000000.1 is 2.38e-8 above it, so x there is 100.0000238, not [100, 100].
TEST(TimesAsWritten, AnAtBetweenTwoDoublesHoldsAtTheDecimal) {
  const Problem p = parse(
      "[time]\ndomain = [1000000000, 1000000001]\ndelta = 0.25\n"
      "[var.x]\nkind = \"tube\"\nat = [{ t = 1000000000.1, value = 100 }]\n"
      "[var.v]\nkind = \"tube\"\nvalue = 1000\n"
      "[[constraint]]\nkind = \"deriv\"\nx = \"x\"\nv = \"v\"\n");
  const GateSpec& g = p.var("x")->at.at(0);
  EXPECT_LT(g.t_lo, g.t_hi);  // not a double: enclosed
  EXPECT_LE(g.t_lo, g.t);
  EXPECT_LE(g.t, g.t_hi);
  const SolveResult r = solve_problem(p);
  ASSERT_FALSE(r.empty) << r.why_empty;
  const Tube& x = (*r.built.var("x").tubes)[0];
  const TDomain& td = *x.tdomain();
  for (std::size_t k = 0; k <= td.nb_slices(); ++k) {  // x(t) = 100 + 1000 (t - 1000000000.1), at every gate
    const long double t = static_cast<long double>(td.t(k) - 1000000000.0) - 0.1L;  // the difference is exact
    EXPECT_TRUE(holds(x.gate(k), 100 + 1000 * t, 1e-9L)) << "gate " << k << " at " << td.t(k) << " = " << x.gate(k);
  }
  EXPECT_GT(x.gate(0).diam(), 0);  // the rounding gap is in it
  EXPECT_LT(x.gate(0).diam(), 1e-3);
}

// An exact decimal stays a gate, a time point of the domain, as before.
TEST(TimesAsWritten, AnExactTimeIsAGate) {
  const Problem p = parse(
      "[time]\ndomain = [0, 4]\ndelta = 1\n"
      "[var.x]\nkind = \"tube\"\nat = [{ t = 2.5, value = 1 }, { t = 1_000e-3, value = 2 }]\n"
      "[[constraint]]\nkind = \"expr\"\nexpr = \"x - [0, 3]\"\n");
  EXPECT_EQ(p.var("x")->at.at(0).t_lo, 2.5);
  EXPECT_EQ(p.var("x")->at.at(0).t_hi, 2.5);
  EXPECT_EQ(p.var("x")->at.at(1).t_lo, 1.0);
  EXPECT_EQ(p.var("x")->at.at(1).t_hi, 1.0);
  const BuiltProblem b = build_network(p, 1);
  const Tube& x = (*b.var("x").tubes)[0];
  EXPECT_EQ(x.gate(static_cast<std::size_t>(b.td->time_index(2.5))), Interval(1));
  EXPECT_EQ(x.gate(1), Interval(2));
  EXPECT_EQ(b.value_nodes.size(), 0u);
}

// Consistent exact values at decimal stamps (x = 1e9 t at t = 0.1, 0.2, ...):
// with the values put at the stamps' doubles, no trajectory of slope 1e9
// joined them (no solution); at the stamps as written, one does.
TEST(TimesAsWritten, GatesAtDecimalStampsAreConsistent) {
  const std::string stamps = table_file("decimal_stamps", "t,pos\n0.1,100000000\n0.2,200000000\n0.3,300000000\n0.7,700000000\n");
  const Problem p = parse("[time]\npoints = { data = \"s\", column = \"t\" }\n[data.s]\nfile = \"" + stamps +
                          "\"\n[var.x]\nkind = \"tube\"\ngates = { data = \"s\", value = \"pos\" }\n"
                          "[var.v]\nkind = \"tube\"\nvalue = 1e9\n"
                          "[[constraint]]\nkind = \"deriv\"\nx = \"x\"\nv = \"v\"\n");
  const SolveResult r = solve_problem(p);
  ASSERT_FALSE(r.empty) << r.why_empty;
  const Tube& x = (*r.built.var("x").tubes)[0];
  const TDomain& td = *x.tdomain();
  for (std::size_t k = 0; k <= td.nb_slices(); ++k) {
    const long double truth = 1e9L * static_cast<long double>(td.t(k));
    EXPECT_TRUE(holds(x.gate(k), truth, 1e-10L)) << "gate " << k << " = " << x.gate(k);
    EXPECT_LT(x.gate(k).diam(), 1e-6);  // the gap times the slope: ulps of 0.1 times 1e9
  }
  std::filesystem::remove(stamps);
}

// A value at a time between two doubles, on a tube with no derivative, says
// nothing of the gate next to it (that could hold any value): no solution is
// lost, and the problem is not declared inconsistent.
TEST(TimesAsWritten, WithoutADerivativeNothingIsLost) {
  const SolveResult r = problem_test::solve_text(
      "[time]\ndomain = [0, 1]\ndelta = 0.5\n"
      "[var.x]\nkind = \"tube\"\nvalue = \"[-1, 1]\"\nat = [{ t = 0.1, value = \"[0.5, 0.6]\" }]\n"
      "[var.y]\nkind = \"tube\"\n"
      "[[constraint]]\nkind = \"expr\"\nexpr = \"x - y\"\n");
  ASSERT_FALSE(r.empty) << r.why_empty;
  const Tube& x = (*r.built.var("x").tubes)[0];
  for (std::size_t k = 0; k <= x.nb_slices(); ++k) EXPECT_EQ(x.gate(k), Interval(-1, 1)) << "gate " << k;
  EXPECT_EQ(r.built.value_nodes.size(), 1u);
}

// A value at a decimal time that contradicts the tube is a no solution that
// names the value and its place in the file.
TEST(TimesAsWritten, AnInconsistentValueIsNamed) {
  const SolveResult r = problem_test::solve_text(
      "[time]\ndomain = [0, 1]\ndelta = 0.5\n"
      "[var.x]\nkind = \"tube\"\nvalue = \"[-1, 1]\"\nat = [{ t = 0.1, value = 5 }]\n"
      "[var.v]\nkind = \"tube\"\nvalue = \"[-1, 1]\"\n"
      "[[constraint]]\nkind = \"deriv\"\nx = \"x\"\nv = \"v\"\n");
  ASSERT_TRUE(r.empty);
  EXPECT_NE(r.why_empty.find("x at t = 0.1"), std::string::npos) << r.why_empty;
  EXPECT_NE(r.why_empty.find("test.toml:7:7"), std::string::npos) << r.why_empty;
}

// A bound with no value ("1/0", "sqrt(-1)") is a mistake of the file, said
// at its place, not a problem without solution.
TEST(TimesAsWritten, AnEmptyBoundIsABadInput) {
  problem_test::expect_error("[time]\ndomain = [0, 1]\ndelta = 0.5\n[var.x]\nkind = \"tube\"\n"
                             "at = [{ t = 0, value = \"1/0\" }]\n[[constraint]]\nkind = \"expr\"\nexpr = \"x\"\n",
                             "test.toml:6:25: found the bound \"1/0\", which is empty (undefined), expected a constant expression");
  problem_test::expect_error("[time]\ndomain = [0, 1]\ndelta = 0.5\n[var.a]\nkind = \"interval\"\nvalue = \"sqrt(-1)\"\n"
                             "[[constraint]]\nkind = \"expr\"\nexpr = \"a\"\n",
                             "found the bound \"sqrt(-1)\", which is empty (undefined)");
  problem_test::expect_error("[time]\ndomain = [0, 1]\ndelta = 0.5\n[var.x]\nkind = \"tube\"\nvalue = \"sqrt(t - 2)\"\n"
                             "[[constraint]]\nkind = \"expr\"\nexpr = \"x\"\n",
                             "found the bound \"sqrt(t - 2)\", which is empty (undefined at every t of the domain)");
}

// The results table at a time as written: x' = 1, x(1000000000) = -0.0999,
// so x(1000000000.1) = 0.0001 exactly; the time point nearest to it is
// 2.4e-8 s later (x = 0.000100024 there, the old cell). The cell is the tube
// over the doubles around the decimal, through x', printed outward.
TEST(TimesAsWritten, TheResultsTableAtATimeAsWritten) {
  const Problem p = parse(
      "[time]\ndomain = [1000000000, 1000000001]\ndelta = 0.25\n"
      "[var.x]\nkind = \"tube\"\nat = [{ t = 1000000000, value = -0.0999 }]\n"
      "[var.v]\nkind = \"tube\"\nvalue = 1\n"
      "[[constraint]]\nkind = \"deriv\"\nx = \"x\"\nv = \"v\"\n"
      "[output]\ntimes = [1000000000.1]\n");
  const OutputTime& t = p.output.times.at(0);
  EXPECT_LT(t.lo, t.hi);
  const SolveResult r = solve_problem(p);
  ASSERT_FALSE(r.empty) << r.why_empty;
  const std::string html = report_html(p, r);
  const std::size_t row = html.find("<tr><td>x</td><td>", html.find("id=\"results\""));
  ASSERT_NE(row, std::string::npos);
  const std::size_t open = html.find('[', row), comma = html.find(',', open), close = html.find(']', comma);
  const double lb = std::stod(html.substr(open + 1, comma - open - 1)), ub = std::stod(html.substr(comma + 1, close - comma - 1));
  EXPECT_LE(lb, 0.0001) << html.substr(row, close - row);
  EXPECT_GE(ub, 0.0001) << html.substr(row, close - row);
  EXPECT_LT(ub - lb, 1e-6);
}

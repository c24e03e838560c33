// The keys of an eval constraint beyond one stamped tube: several tubes at one
// time (y, v arrays), an unknown time (no time column), a time interval from
// two columns, rows kept by 'where', gates at the times; and [network] ratio.
// What the loader reads, its errors at their place, and what the network does
// with them.
#include <gtest/gtest.h>

#include "problem_text.h"
#include "sillage/problem/check_summary.h"
#include "sillage/problem/eval_rows.h"
#include "sillage/problem/report_html.h"
#include "sillage/problem/solve_problem.h"

using namespace sillage;
using problem_test::expect_error;
using problem_test::parse;

namespace {

// beacon_ranges.csv: t, b, r (nine rows, b in {2, -1}).
const std::string kHead = "[time]\ndomain = [0, 20]\ndelta = 0.05\n[data.ranges]\nfile = \"data/beacon_ranges.csv\"\n"
                          "[var.x]\nkind = \"tube\"\nvalue = \"[-10, 10]\"\n"
                          "[var.v]\nkind = \"tube\"\nvalue = \"cos(t) + [-0.01, 0.01]\"\n"
                          "[[constraint]]\nkind = \"deriv\"\nx = \"x\"\nv = \"v\"\n";  // 15 lines

std::string eval(const std::string& keys) {
  return kHead + "[[constraint]]\nkind = \"eval\"\ndata = \"ranges\"\n" + keys + "expr = \"abs(x - b) - r\"\n";
}

}  // namespace

TEST(LoadEval, ReadsTheNewKeys) {
  const Problem p = parse(eval("y = [\"x\"]\nv = [\"v\"]\ntime = [\"t\", \"t\"]\ntime_error = 0.01\nwhere = { b = 2 }\n"
                               "gates = true\nerrors = { r = 0.001 }\n") + "[network]\nratio = 0\n");
  const ConstraintSpec& c = p.constraints[1];
  EXPECT_EQ(c.ys, std::vector<std::string>{"x"});
  EXPECT_EQ(c.vs, std::vector<std::string>{"v"});
  EXPECT_EQ(c.time_columns, (std::vector<std::string>{"t", "t"}));
  EXPECT_EQ(c.where.at("b"), std::make_pair(2.0, 2.0));
  EXPECT_TRUE(c.gates);
  ASSERT_TRUE(p.network.ratio);
  EXPECT_EQ(*p.network.ratio, 0.0);
}

// The label names both time columns; sillage check says how many rows each
// eval uses, and that one whose 'where' keeps none states nothing.
TEST(LoadEval, LabelAndRowsUsed) {
  const Problem p = parse(eval("y = \"x\"\ntime = [\"t\", \"t\"]\nwhere = { b = 2 }\n"));
  EXPECT_NE(p.constraints[1].label.find("at x([t, t]) for every row of 'ranges' kept by 'where'"), std::string::npos)
      << p.constraints[1].label;
  const std::string kept = check_summary(p);
  EXPECT_NE(kept.find("5 of the 9 rows of 'ranges' used\n"), std::string::npos) << kept;
  const std::string none = check_summary(parse(eval("y = \"x\"\ntime = \"t\"\nwhere = { b = 7 }\n")));
  EXPECT_NE(none.find("0 of the 9 rows of 'ranges' used: none, this constraint states nothing"), std::string::npos)
      << none;
}

TEST(LoadEval, ErrorsAtTheirPlace) {
  expect_error(eval("y = \"x\"\ntime = [\"t\", \"b\", \"r\"]\n"),
               "test.toml:20:8: found an array of 3 element(s), expected a time column, or two columns [lb, ub]");
  expect_error(eval("y = [\"x\", \"v\"]\nv = \"v\"\ntime = \"t\"\n"),
               "test.toml:20:5: found 1 derivative(s), expected 2 (one per tube of y, \"\" for none)");
  expect_error(eval("y = \"x\"\ntime = \"t\"\nwhere = { beacon = 2 }\n"),
               "test.toml:21:11: found the column 'beacon' missing from table 'ranges', expected one of its columns: t, b, r");
  expect_error(eval("y = \"x\"\ntime = \"t\"\nerrors = { rr = 0.1 }\n"),
               "test.toml:21:12: found the column 'rr' missing from table 'ranges', expected one of its columns: t, b, r");
  expect_error(eval("y = \"x\"\ntime = \"t\"\ngates = 1\n"), "test.toml:21:9: found an integer 1, expected true or false");
  expect_error(eval("y = \"x\"\ntime_error = 0.1\n"), "test.toml:20:14: found a time error without a time column");
  expect_error(eval("y = [\"x\", \"x\"]\ntime = \"t\"\n"), "found 'x' twice, expected distinct tubes in y");
  expect_error(eval("y = []\ntime = \"t\"\n"), "test.toml:19:5: found an empty array");
  expect_error(eval("y = \"x\"\ntime = \"t\"\n") + "[network]\nratio = 1\n", "found ratio = 1, expected a ratio in [0, 1)");
}

TEST(LoadEval, WhereKeepsTheRowsAndGatesSampleTheTimes) {
  const auto all = build_network(parse(eval("y = \"x\"\nv = \"v\"\ntime = \"t\"\ntime_error = 0.01\n")), 0.05);
  const auto two = build_network(parse(eval("y = \"x\"\nv = \"v\"\ntime = \"t\"\ntime_error = 0.01\nwhere = { b = 2 }\n")), 0.05);
  // The deriv, then the rows (y with its derivative, the observation on y and the row's values):
  // one CtcEvalList holding a fix per row, each a time and a value.
  EXPECT_EQ(all.cn->nb_ctc(), 2u);
  EXPECT_EQ(all.extra_domains, 9u * 2);
  const CsvTable table = CsvTable::read(problem_test::problems_dir() + "/data/beacon_ranges.csv");
  std::size_t rows_b2 = 0;
  for (std::size_t i = 0; i < table.nb_rows(); ++i) rows_b2 += table.row(i)[table.column("b")] == 2;
  EXPECT_EQ(two.cn->nb_ctc(), 2u);
  EXPECT_EQ(two.extra_domains, 2 * rows_b2);
  EXPECT_GT(rows_b2, 0u);
  EXPECT_LT(rows_b2, 9u);
  EXPECT_EQ(all.td->nb_slices(), 400u);
  const auto gated = build_network(parse(eval("y = \"x\"\nv = \"v\"\ntime = \"t\"\ntime_error = 0.01\ngates = true\n")), 0.05);
  EXPECT_GT(gated.td->nb_slices(), 400u);
  const double t0 = table.row(0)[table.column("t")];
  bool lower_is_a_gate = false;  // t - 0.01, enclosed outward: a time point just below
  for (std::size_t k = 0; k <= gated.td->nb_slices(); ++k)
    lower_is_a_gate |= gated.td->t(k) <= t0 - 0.01 && gated.td->t(k) > t0 - 0.01 - 1e-12;
  EXPECT_TRUE(lower_is_a_gate);
}

// Without a time column the time is unknown: the evaluations contract it.
// x = sin(t) + 1 ranges, two tubes at one time: x and a copy u = x.
TEST(LoadEval, UnknownTimeSharedByTwoTubes) {
  const Problem p = parse(kHead + "[var.u]\nkind = \"tube\"\n[[constraint]]\nkind = \"expr\"\nexpr = \"u - x\"\n"
                          "[[constraint]]\nkind = \"eval\"\ndata = \"ranges\"\ny = [\"x\", \"u\"]\nv = [\"v\", \"\"]\n"
                          "expr = \"(abs(x - b) - r, u - x)\"\n");
  const SolveResult r = solve_problem(p);
  ASSERT_FALSE(r.empty) << r.why_empty;
  EXPECT_EQ(r.built.cn->nb_ctc(), 2u + 9 * 3);  // per row: two CtcEval, one observation
  EXPECT_EQ(r.built.extra_domains, 9u * (1 + 2 + 2));  // t, two z, the columns b and r
  // The truth stays inside.
  const Tube& x = (*r.built.var("x").tubes)[0];
  for (int i = 0; i <= 20; ++i) EXPECT_TRUE(x(i * 1.0).contains(std::sin(i * 1.0) + 1)) << i;
}

// A CSV cell is its decimal as written: the double read and its neighbours
// enclose it. One row kept (where t = 1.90), its r (0.053700) copied into a
// constant.
TEST(LoadEval, CellsEncloseTheirDecimal) {
  const SolveResult r = solve_problem(parse(kHead + "[var.a]\nkind = \"interval\"\n" +
                                            "[[constraint]]\nkind = \"eval\"\ndata = \"ranges\"\ny = \"x\"\n"
                                            "time = \"t\"\nwhere = { t = 1.90 }\nexpr = \"a - r + 0*x\"\n"));
  ASSERT_FALSE(r.empty) << r.why_empty;
  const Interval decimal = Function({"t"}, "0.053700").eval(IntervalVector{Interval(0)});
  const Interval& a = *r.built.var("a").interval;
  EXPECT_TRUE(decimal.is_subset(a)) << a;
  EXPECT_LT(a.diam(), 1e-16);
}

// A row whose time lies outside [t0, tf] is an error naming the file and the
// row, unless outside = "skip": then it is skipped and counted.
TEST(LoadEval, RowsOutsideTheTimeDomain) {
  auto within_10 = [](std::string text) { return text.replace(text.find("[0, 20]"), 7, "[0, 10]"); };
  expect_error(within_10(eval("y = \"x\"\ntime = \"t\"\n")),
               "test.toml:16:1: found row 5 of 'ranges' (");
  expect_error(within_10(eval("y = \"x\"\ntime = \"t\"\nwhere = { b = 2 }\n")), "found row 6 of 'ranges' (");
  expect_error(within_10(eval("y = \"x\"\ntime = \"t\"\nwhere = { b = 2 }\n")), "beacon_ranges.csv:9) at t = 13.3, outside");
  expect_error(within_10(eval("y = \"x\"\ntime = \"t\"\n")),
               "data/beacon_ranges.csv:8) at t = 11.4, outside the time domain [0, 10], expected rows within [t0, tf] "
               "(outside = \"skip\" skips the others, counted by sillage check)");
  expect_error(eval("y = \"x\"\ntime = \"t\"\noutside = \"drop\"\n"), "test.toml:21:11: found \"drop\", expected \"error\" or \"skip\"");
  const Problem p = parse(within_10(eval("y = \"x\"\ntime = \"t\"\noutside = \"skip\"\n")));
  EXPECT_EQ(p.constraints[1].nb_outside, 4u);  // t = 11.4, 13.3, 15.2, 17.1
  EXPECT_EQ(build_network(p, 0.05).cn->nb_ctc(), 1u + 5 * 2);
  EXPECT_EQ(parse(eval("y = \"x\"\ntime = \"t\"\n")).constraints[1].nb_outside, 0u);
  // Within the time error of the domain: kept (its time is the part inside).
  EXPECT_EQ(parse(within_10(eval("y = \"x\"\ntime = \"t\"\ntime_error = 1.5\nwhere = { b = 2 }\noutside = \"skip\"\n"))).constraints[1].nb_outside, 2u);
}

// The rows of an eval whose observation involves only the tube and the row's
// values are one CtcEvalList node; an observation that also involves another
// variable (here a = 0, which changes nothing) keeps a CtcEval node and an
// observation node per row. The two give the same tube: the same contractors
// to a fixed point (in another order).
TEST(LoadEval, RowsAsOneNodeGiveTheSetsOfANodePerRow) {
  const std::string text = problem_test::read_file(problem_test::problems_dir() + "/line_ranges.toml");
  std::string with_a = text;
  with_a.replace(with_a.find("expr = \"abs(x - b) - r\""), 24, "expr = \"abs(x - b) - r + a\"");
  with_a += "\n[var.a]\nkind = \"interval\"\nvalue = \"0\"\n";
  const SolveResult list = solve_problem(parse(text)), rows = solve_problem(parse(with_a));
  ASSERT_FALSE(list.empty) << list.why_empty;
  ASSERT_FALSE(rows.empty) << rows.why_empty;
  EXPECT_EQ(list.built.cn->nb_ctc(), 2u);
  EXPECT_EQ(rows.built.cn->nb_ctc(), 1u + 2 * 9);
  // sillage check counts the nodes the build makes.
  EXPECT_NE(check_summary(parse(text)).find("network: 2 nodes"), std::string::npos) << check_summary(parse(text));
  EXPECT_NE(check_summary(parse(with_a)).find("network: 19 nodes"), std::string::npos) << check_summary(parse(with_a));
  const Tube &a = (*list.built.var("x").tubes)[0], &b = (*rows.built.var("x").tubes)[0];
  ASSERT_EQ(a.nb_slices(), b.nb_slices());
  double va = 0, vb = 0;
  for (std::size_t k = 0; k <= a.nb_slices(); ++k) va += a.gate(k).diam(), vb += b.gate(k).diam();
  EXPECT_NEAR(va / vb, 1.0, 0.02) << va << " " << vb;
  EXPECT_LT(a.max_thickness(), 1.0);
}

// An emptiness found by a row's observation names that row's domains by the
// table and the CSV line (never "domain 3"), so that the user finds the
// measurement.
TEST(LoadEval, EmptinessNamesTheRow) {
  std::string text = problem_test::read_file(problem_test::problems_dir() + "/line_ranges.toml");
  text.replace(text.find("value = \"[-10, 10]\""), 19, "value = \"[-10, 10]\"\nat = [{ t = 0, value = \"[5, 6]\" }]");
  const SolveResult r = solve_problem(parse(text));
  ASSERT_TRUE(r.empty);
  EXPECT_EQ(r.why_empty.find("domain "), std::string::npos) << r.why_empty;
  EXPECT_NE(r.why_empty.find(" (ranges line "), std::string::npos) << r.why_empty;
}

// The truth check counts a value inside an unbounded tube as a miss: without
// the ranges the line robot's position is never bounded, and "201 of 201
// inside" would be vacuous.
TEST(LoadEval, TruthInAnUnboundedTubeIsNoPass) {
  std::string text = problem_test::read_file(problem_test::problems_dir() + "/line_ranges.toml");
  const Problem with = parse(text);
  const TruthCheck ok = check_truth(with, solve_problem(with).built);
  EXPECT_EQ(ok.samples, 201u);
  EXPECT_EQ(ok.inside, 201u);
  text.replace(text.find("value = \"[-10, 10]\""), 19, "");
  text.erase(text.find("[[constraint]]\nkind = \"eval\""), text.find("[output]") - text.find("[[constraint]]\nkind = \"eval\""));
  const Problem without = parse(text);
  const TruthCheck none = check_truth(without, solve_problem(without).built);
  EXPECT_EQ(none.samples, 201u);
  EXPECT_EQ(none.inside, 0u);
  ASSERT_FALSE(none.first_misses.empty());
  EXPECT_NE(none.first_misses[0].find("in the unbounded"), std::string::npos) << none.first_misses[0];
}

// A row's observation whose contractor empties only one of the row's values
// (a contractor need not empty the whole box) still makes the row's z empty:
// the inconsistency is never lost.
TEST(LoadEval, RowObservationEmptiedByAValueIsEmpty) {
  struct EmptiesTheLast : Ctc {
    EmptiesTheLast() : Ctc(2) {}
    void contract(IntervalVector& x) const override { x[1] = Interval::empty(); }
  };
  const detail::RowObservation row(std::make_shared<EmptiesTheLast>(), std::make_shared<const std::vector<int>>(std::vector<int>{0, -1}),
                                   1, IntervalVector{Interval(3.0)});
  IntervalVector z{Interval(1, 2)};
  row.contract(z);
  EXPECT_TRUE(z.is_empty());
}

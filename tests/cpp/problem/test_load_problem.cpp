// The loader of problem files: what it reads, and an error at the right
// file:line:column, saying what was found and what was expected, for each
// kind of mistake.
#include <gtest/gtest.h>

#include "problem_text.h"

using namespace sillage;
using problem_test::error_of;
using problem_test::parse;

namespace {

const std::string kHead = "[time]\ndomain = [0, 10]\ndelta = 0.5\n";
const std::string kVars = "[var.x]\nkind = \"tube\"\n[var.v]\nkind = \"tube\"\nvalue = \"cos(t) + [-0.1, 0.1]\"\n";
const std::string kDeriv = "[[constraint]]\nkind = \"deriv\"\nx = \"x\"\nv = \"v\"\n";

bool has(const std::string& msg, const std::string& part) { return msg.find(part) != std::string::npos; }

}  // namespace

TEST(LoadProblem, ReadsAMinimalProblem) {
  const Problem p = parse(kHead + kVars + kDeriv);
  EXPECT_EQ(p.time.t0, 0);
  EXPECT_EQ(p.time.tf, 10);
  ASSERT_TRUE(p.time.delta);
  EXPECT_EQ(*p.time.delta, 0.5);
  ASSERT_EQ(p.vars.size(), 2u);
  EXPECT_EQ(p.var("v")->value[0].expr, "cos(t) + [-0.1, 0.1]");
  ASSERT_EQ(p.constraints.size(), 1u);
  EXPECT_EQ(p.constraints[0].kind, ConstraintKind::Deriv);
  EXPECT_EQ(p.hash.size(), 16u);
}

TEST(LoadProblem, NumbersAreKeptAsWritten) {
  const Problem p = parse(kHead + "[var.a]\nkind = \"interval\"\nvalue = 0.1\n" + "[[constraint]]\nkind = \"expr\"\nexpr = \"a - 0.1\"\n");
  EXPECT_EQ(p.var("a")->value[0].expr, "0.1");  // enclosed rigorously later, not the double 0.1
}

TEST(LoadProblem, UnknownKeyIsAnErrorAtItsPlace) {
  const std::string msg = error_of("[time]\ndomain = [0, 10]\ndelta = 0.5\ndelt = 1\n" + kVars + kDeriv);
  EXPECT_TRUE(has(msg, "test.toml:4:1: found the unknown key 'delt' in [time], expected one of: domain, delta")) << msg;
}

TEST(LoadProblem, WrongTypeSaysFoundAndExpected) {
  const std::string msg = error_of("[time]\ndomain = \"0 to 10\"\ndelta = 0.5\n" + kVars + kDeriv);
  EXPECT_TRUE(has(msg, "test.toml:2:10: found a string \"0 to 10\", expected [t0, tf]")) << msg;
}

TEST(LoadProblem, InvalidTomlGivesItsPosition) {
  const std::string msg = error_of("[time\n");
  EXPECT_TRUE(has(msg, "test.toml:1:")) << msg;
  EXPECT_TRUE(has(msg, "invalid TOML")) << msg;
}

TEST(LoadProblem, UnknownVariableInAnExpression) {
  const std::string msg = error_of(kHead + kVars + "[[constraint]]\nkind = \"expr\"\nexpr = \"x - 2*w\"\n");
  // line 11, column 9 is the first character of the string, w is 6 further
  EXPECT_TRUE(has(msg, "test.toml:11:15: found the unknown name 'w'")) << msg;
  EXPECT_TRUE(has(msg, "expected a variable or column (v, x)")) << msg;
}

// t and dt are the time and the slice width in bounds and table values: a
// variable of that name would mean one thing there and another in constraints.
TEST(LoadProblem, TimeNamesAreNotVariableNames) {
  for (const std::string name : {"t", "dt"}) {
    const std::string msg = error_of(kHead + "[var." + name + "]\nkind = \"interval\"\nvalue = \"[100, 101]\"\n" + kVars);
    EXPECT_TRUE(has(msg, "test.toml:4:6: found the variable name '" + name + "', expected a name other than t and dt"))
        << msg;
  }
}

// Where a tube is expected, the variables listed are the tubes only.
TEST(LoadProblem, ExpectedTubesListTheTubes) {
  const std::string consts = "[var.a]\nkind = \"interval\"\n[var.b]\nkind = \"box\"\ndim = 2\n";
  std::string msg = error_of(kHead + consts + kVars + kDeriv + "[output]\nplots = [\"a\"]\n");
  EXPECT_TRUE(has(msg, "found 'a', expected a tube variable (v, x)")) << msg;
  msg = error_of(kHead + consts + kVars + "[[constraint]]\nkind = \"deriv\"\nx = \"x\"\nv = \"a\"\n");
  EXPECT_TRUE(has(msg, "found the interval 'a', expected a tube or tube_vector variable (v, x)")) << msg;
}

TEST(LoadProblem, ComponentIndexOutOfRange) {
  const std::string msg = error_of(kHead + "[var.p]\nkind = \"tube_vector\"\ndim = 2\n" +
                                   "[[constraint]]\nkind = \"expr\"\nexpr = \"p[0] - p[2]\"\n");
  EXPECT_TRUE(has(msg, "test.toml:9:17: found index 2 of 'p', expected an index from 0 to 1")) << msg;
}

TEST(LoadProblem, VectorWithoutIndex) {
  const std::string msg = error_of(kHead + "[var.p]\nkind = \"box\"\ndim = 2\n" +
                                   "[[constraint]]\nkind = \"expr\"\nexpr = \"p - 1\"\n");
  EXPECT_TRUE(has(msg, "found the vector 'p' without an index, expected a component such as p[0]")) << msg;
}

TEST(LoadProblem, DimensionMismatchOfDeriv) {
  const std::string msg = error_of(kHead + "[var.x]\nkind = \"tube_vector\"\ndim = 2\n[var.v]\nkind = \"tube_vector\"\ndim = 3\n" + kDeriv);
  EXPECT_TRUE(has(msg, "test.toml:13:5: found 'v' (tube_vector, dim 3), expected a variable of the kind and dimension of 'x'"))
      << msg;
}

TEST(LoadProblem, BadBoundExpression) {
  const std::string msg = error_of(kHead + "[var.x]\nkind = \"tube\"\nvalue = \"sin(t\"\n" + "[var.v]\nkind = \"tube\"\n" + kDeriv);
  // the bound starts at column 10; the parser wants ')' past its end, its column 6
  EXPECT_TRUE(has(msg, "test.toml:6:15: found the bound \"sin(t\", which needs ')' at its column 6, expected an expression of t"))
      << msg;
}

// The parser reads x__0 for x[0]: its complaints quote the written text and
// point at the written column, never at the rewritten one.
TEST(LoadProblem, RejectedExpressionQuotesTheWrittenText) {
  const std::string vars = "[var.x]\nkind = \"tube_vector\"\ndim = 3\n";
  std::string msg = error_of(kHead + vars + "[[constraint]]\nkind = \"expr\"\nexpr = \"x[2]*coss(x[1]) - x[0]\"\n");
  // line 9, column 9 is the first character of the string, coss is 5 further
  EXPECT_TRUE(has(msg, "test.toml:9:14: found the expression \"x[2]*coss(x[1]) - x[0]\" with unknown identifier 'coss' at "
                       "its column 6, expected a valid expression")) << msg;
  EXPECT_FALSE(has(msg, "x__")) << msg;
  msg = error_of(kHead + vars + "[[constraint]]\nkind = \"expr\"\nexpr = \"x[2]*cos(x[1] - x[0]\"\n");
  EXPECT_TRUE(has(msg, "test.toml:9:29: found the expression \"x[2]*cos(x[1] - x[0]\", which needs ')' at its column 21"))
      << msg;
  msg = error_of(kHead + vars + "[[constraint]]\nkind = \"expr\"\nexpr = \"x[2] + x[1]) - x[0]\"\n");
  EXPECT_TRUE(has(msg, "test.toml:9:20: found the expression \"x[2] + x[1]) - x[0]\", which needs an operator or the end "
                       "at its column 12")) << msg;
}

TEST(LoadProblem, WrongNumberOfBounds) {
  const std::string msg = error_of(kHead + "[var.x]\nkind = \"tube_vector\"\ndim = 2\nvalue = [\"1\"]\n" + "[[constraint]]\nkind = \"expr\"\nexpr = \"x[0]\"\n");
  EXPECT_TRUE(has(msg, "test.toml:7:9: found an array of 1 element(s), expected an array of 2 bounds")) << msg;
}

TEST(LoadProblem, GateOutsideTheDomain) {
  const std::string msg = error_of(kHead + "[var.x]\nkind = \"tube\"\nat = [{t = 11, value = 0}]\n[var.v]\nkind = \"tube\"\n" + kDeriv);
  EXPECT_TRUE(has(msg, "test.toml:6:12: found t = 11 outside the time domain, expected a time in [0, 10]")) << msg;
}

TEST(LoadProblem, MissingDataFileAndColumn) {
  std::string msg = error_of(kHead + "[data.r]\nfile = \"no_such.csv\"\n" + kVars + kDeriv);
  EXPECT_TRUE(has(msg, "test.toml:5:8: found \"no_such.csv\", which names no file (")) << msg;
  EXPECT_TRUE(has(msg, "no_such.csv), expected a CSV file, its path relative to the problem file's folder")) << msg;
  msg = error_of(kHead + "[data.r]\nfile = \"data/beacon_ranges.csv\"\ncolumns = [\"t\", \"nope\"]\n" + kVars + kDeriv);
  EXPECT_TRUE(has(msg, "found the column 'nope' missing from")) << msg;
  EXPECT_TRUE(has(msg, "expected one of: t,")) << msg;
}

TEST(LoadProblem, MissingSectionsAndKinds) {
  EXPECT_TRUE(has(error_of(kVars + kDeriv), "found no key 'time' in the file")) << error_of(kVars + kDeriv);
  EXPECT_TRUE(has(error_of(kHead + kVars), "found no key 'constraint'"));
  const std::string msg = error_of(kHead + kVars + "[[constraint]]\nkind = \"magic\"\n");
  EXPECT_TRUE(has(msg, "test.toml:10:8: found a string \"magic\", expected kind = \"expr\"")) << msg;
}

TEST(LoadProblem, UnreadableFileIsAnError) {
  EXPECT_THROW(load_problem("/no/such/problem.toml"), ProblemError);
  EXPECT_THROW(load_problem(problem_test::problems_dir()), ProblemError);
}

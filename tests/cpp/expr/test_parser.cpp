// Parser: literals enclosed rigorously, precedence, printing, errors.
#include <gtest/gtest.h>
#include <mpfr.h>

#include <random>
#include <string>

#include "sillage/expr/function.h"
#include "sillage/expr/literal.h"
#include "sillage/expr/parser.h"

using namespace sillage;

namespace {

// Exact comparison of a decimal text with a double, by MPFR (exact: enough bits).
int cmp_decimal(const std::string& text, double d) {
  mpfr_t t, e;
  mpfr_inits2(4000, t, e, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_str(t, text.c_str(), 10, MPFR_RNDN);  // 4000 bits: exact enough to compare
  mpfr_set_d(e, d, MPFR_RNDN);
  const int c = mpfr_cmp(t, e);
  mpfr_clears(t, e, static_cast<mpfr_ptr>(nullptr));
  return c;
}

Interval eval1(const std::string& text, std::vector<Interval> x = {}) {
  std::vector<std::string> vars;
  for (std::size_t i = 0; i < x.size(); ++i) vars.push_back(std::string("x").append(std::to_string(i + 1)));
  return Function(vars, text).eval(IntervalVector(x));
}

}  // namespace

TEST(Literal, ExactNumbersAreDegenerate) {
  for (const char* s : {"1", "1.5", "0.5", ".5", "2.", "1e3", "0.125", "3e-1", "0", "0.0e5", "1.5E+2"}) {
    const Interval c = detail::decimal_enclosure(s);
    if (std::string(s) == "3e-1") {
      EXPECT_FALSE(c.is_degenerate()) << s;
    } else {
      EXPECT_TRUE(c.is_degenerate()) << s;
    }
  }
  EXPECT_EQ(detail::decimal_enclosure("1.5E+2"), Interval(150.0));
  EXPECT_EQ(detail::decimal_enclosure(".5"), Interval(0.5));
}

TEST(Literal, InexactNumbersAreEnclosedTightly) {
  const Interval c = detail::decimal_enclosure("0.1");
  EXPECT_EQ(c.ub(), rounding::next_up(c.lb()));
  EXPECT_TRUE(c.contains(0.1));
  EXPECT_GT(cmp_decimal("0.1", c.lb()), 0);
  EXPECT_LT(cmp_decimal("0.1", c.ub()), 0);
}

TEST(Literal, RandomDecimalsAgainstMpfr) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> digit(0, 9), len(1, 25), ex(-330, 310);
  for (int k = 0; k < 3000; ++k) {
    std::string s;
    const int n = len(rng);
    for (int i = 0; i < n; ++i) {
      if (k % 3 == 0 && i == n / 2) s.push_back('.');
      s.push_back(static_cast<char>('0' + digit(rng)));
    }
    if (k % 2 == 0) s.append("e").append(std::to_string(ex(rng)));
    const Interval c = detail::decimal_enclosure(s);
    ASSERT_FALSE(c.is_empty()) << s;
    ASSERT_GE(cmp_decimal(s, c.lb()), 0) << s;
    if (std::isfinite(c.ub())) {
      ASSERT_LE(cmp_decimal(s, c.ub()), 0) << s;
    }
    // Tight: degenerate iff exact, else two consecutive doubles.
    if (c.is_degenerate()) {
      ASSERT_EQ(cmp_decimal(s, c.lb()), 0) << s;
    } else if (std::isfinite(c.ub())) {
      ASSERT_EQ(c.ub(), rounding::next_up(c.lb())) << s;
    }
  }
}

TEST(Literal, OverflowAndUnderflow) {
  const Interval big = detail::decimal_enclosure("1e400");
  EXPECT_EQ(big.lb(), rounding::kMax);
  EXPECT_EQ(big.ub(), rounding::kInf);
  const Interval tiny = detail::decimal_enclosure("1e-400");
  EXPECT_EQ(tiny.lb(), 0.0);
  EXPECT_GT(tiny.ub(), 0.0);
  const Interval sub = detail::decimal_enclosure("3e-310");  // subnormal, not exact
  EXPECT_GT(sub.lb(), 0.0);
  EXPECT_EQ(sub.ub(), rounding::next_up(sub.lb()));
}

TEST(Literal, PrintedBackToTheSameEnclosure) {
  for (const char* s : {"0.1", "1", "2.5", "1e-7", "123456.789", "3.14159"}) {
    const Interval c = detail::decimal_enclosure(s);
    EXPECT_EQ(detail::decimal_enclosure(detail::literal_str(c)), c) << s;
  }
  EXPECT_EQ(detail::literal_str(detail::decimal_enclosure("0.1")), "0.1");
  EXPECT_EQ(detail::literal_str(Interval(-2.5)), "-2.5");
  EXPECT_EQ(detail::literal_str(Interval(1, 2)), "[1, 2]");
  EXPECT_EQ(detail::literal_str(Interval(-rounding::kInf, 2)), "[-inf, 2]");
}

TEST(Parser, ConstantsAreEnclosedInExpressions) {
  const Interval c = eval1("0.1");
  EXPECT_TRUE(c.contains(0.1));
  EXPECT_FALSE(c.is_degenerate());
  const Interval ten = eval1("0.1 * 10");
  EXPECT_TRUE(ten.contains(1.0));
  EXPECT_TRUE(eval1("3 * 0.1").contains(0.30000000000000004));  // the double product of 3 and 0.1
  EXPECT_TRUE(eval1("pi").is_subset(Interval(3.1415926535897931, 3.1415926535897936)));
  EXPECT_EQ(eval1("pi"), Interval::pi());
}

TEST(Parser, IntervalLiterals) {
  EXPECT_EQ(eval1("[1, 2]"), Interval(1, 2));
  EXPECT_EQ(eval1("[-1.5,2e1]"), Interval(-1.5, 20));
  const Interval t = eval1("[0.1, 0.2]");
  EXPECT_LT(t.lb(), 0.1);  // 0.1 (the double) is above the real 0.1
  EXPECT_GT(cmp_decimal("0.1", t.lb()), 0);
  EXPECT_LT(cmp_decimal("0.2", t.ub()), 0);
  EXPECT_EQ(t.ub(), 0.2);  // 0.2 (the double) is above the real 0.2
  EXPECT_TRUE(eval1("[-inf, oo]").is_all_reals());
  EXPECT_EQ(eval1("[-inf, 3]"), Interval(-rounding::kInf, 3));
  EXPECT_TRUE(eval1("[empty]").is_empty());
  EXPECT_EQ(eval1("-[1,2]"), Interval(-2, -1));
}

TEST(Parser, Precedence) {
  const std::vector<Interval> x{Interval(3.0)};
  EXPECT_EQ(eval1("-x1^2", x), Interval(-9.0));
  EXPECT_EQ(eval1("2^3^2"), Interval(512.0));  // right-associative
  EXPECT_EQ(eval1("2^-1"), Interval(0.5));
  EXPECT_EQ(eval1("1 - 2 - 3"), Interval(-4.0));
  EXPECT_EQ(eval1("8 / 4 / 2"), Interval(1.0));
  EXPECT_EQ(eval1("1 + 2 * 3 ^ 2"), Interval(19.0));
  EXPECT_EQ(eval1("(1 + 2) * 3"), Interval(9.0));
  EXPECT_EQ(eval1("-2 * -3"), Interval(6.0));
  EXPECT_EQ(eval1("--x1", x), Interval(3.0));
  EXPECT_EQ(eval1("x1^2", {Interval(-1, 2)}), Interval(0, 4));  // sqr, not x*x
  EXPECT_EQ(eval1("x1*x1", {Interval(-1, 2)}), Interval(-2, 4));
}

TEST(Parser, FunctionsAndArguments) {
  EXPECT_EQ(eval1("sqrt((x1-1)^2 + (x2-2)^2)", {Interval(4.0), Interval(6.0)}), Interval(5.0));
  EXPECT_EQ(eval1("min(x1, 2) + max(x1, 2)", {Interval(5.0)}), Interval(7.0));
  EXPECT_EQ(eval1("root(x1, 3)", {Interval(-8.0)}), Interval(-2.0));
  EXPECT_EQ(eval1("pow(x1, 3)", {Interval(-2.0)}), Interval(-8.0));
  EXPECT_EQ(eval1("abs(x1) * sign(x1)", {Interval(-2.0)}), Interval(-2.0));
  EXPECT_TRUE(eval1("exp(log(x1))", {Interval(2.0)}).contains(2.0));
  EXPECT_TRUE(eval1("atan2(1, 1) * 4").is_superset(Interval::pi()));
  EXPECT_TRUE(eval1("pow(x1, 0.5)", {Interval(4.0)}).contains(2.0));
}

TEST(Parser, VectorFunction) {
  Function f({"x", "y"}, "(x + y, x - y, x * y)");
  EXPECT_EQ(f.image_dim(), 3u);
  const IntervalVector r = f.eval_vector(IntervalVector{Interval(2.0), Interval(3.0)});
  EXPECT_EQ(r, (IntervalVector{Interval(5.0), Interval(-1.0), Interval(6.0)}));
  EXPECT_THROW(f.eval(IntervalVector{Interval(2.0), Interval(3.0)}), DimensionError);
  EXPECT_EQ(Function({"x"}, "(x)").image_dim(), 1u);
}

TEST(Parser, HashConsingSharesNodes) {
  Function f({"x"}, "(x-1)^2 + (x-1)^2");
  EXPECT_EQ(f.tape_size(), 4u);  // 1, x-1, (x-1)^2, +
  ExprVar x("x");
  EXPECT_EQ(sqr(x - 1) + sqr(x - 1), f.exprs()[0]);
  EXPECT_EQ(detail::parse_expr({"x"}, "sin(x)*cos(x)"), sin(x) * cos(x));
}

TEST(Parser, PrintRoundTrips) {
  const std::vector<std::string> texts = {
      "sqrt((x1 - 1)^2 + (x2 - 2)^2)", "-x1^2",      "(-x1)^2",          "x1 - (x2 - 1)", "x1 / (x2 * 3)",
      "(x1 + x2) * (x1 - x2)",         "x1^-2",      "atan2(x2, x1)",    "root(x1, 3)",   "pow(x1, x2)",
      "min(x1, max(x2, 0.1))",         "[1, 2] * x1", "-(x1 + x2)",      "x1 - -2",       "2^x1",
      "exp(-x1^2 / 2) * 0.3",          "(x1, x2 + 1)"};
  for (const std::string& t : texts) {
    Function f({"x1", "x2"}, t);
    Function g({"x1", "x2"}, f.expr_str());
    EXPECT_EQ(f.exprs(), g.exprs()) << t << " printed " << f.expr_str();
  }
  EXPECT_EQ(Function({"x1", "x2"}, "sqrt((x1-1)^2+(x2-2)^2)").str(), "(x1, x2) -> sqrt((x1 - 1)^2 + (x2 - 2)^2)");
  EXPECT_EQ(Function({"x"}, "-x^2").expr_str(), "-x^2");
  EXPECT_EQ(Function({"x"}, "x*0.1").expr_str(), "x * 0.1");
}

namespace {

void expect_parse_error(const std::string& text, const std::string& fragment) {
  try {
    Function f({"x1", "x2"}, text);
    ADD_FAILURE() << "no error for \"" << text << "\"";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << "\"" << text << "\" gave: " << e.what();
  }
}

}  // namespace

TEST(Parser, Errors) {
  expect_parse_error("sqrt((x1-1)^2", "expected ')' at column 14 in \"sqrt((x1-1)^2\"");
  expect_parse_error("x1 + ", "expected an operand at column 6");
  expect_parse_error("x1 * * x2", "expected an operand, got '*' at column 6");
  expect_parse_error("x1 + z", "unknown identifier 'z' at column 6");
  expect_parse_error("foo(x1)", "unknown identifier 'foo' at column 1");
  expect_parse_error("[2,1]", "lower bound above upper bound at column 1");
  expect_parse_error("[inf, inf]", "contains no real number");
  expect_parse_error("[1, nan]", "NaN is not a valid bound at column 5");
  expect_parse_error("NaN + x1", "NaN is not a valid number at column 1");
  expect_parse_error("x1 + 1 )", "expected an operator or the end at column 8");
  expect_parse_error("x1 x2", "expected an operator or the end at column 4");
  expect_parse_error("atan2(x1)", "function 'atan2' takes 2 arguments, got 1 at column 1");
  expect_parse_error("sin(x1, x2)", "function 'sin' takes 1 argument, got 2");
  expect_parse_error("root(x1, 2.5)", "n must be an integer constant");
  expect_parse_error("root(x1, x2)", "n must be an integer constant");
  expect_parse_error("1.2.3", "invalid number literal '1.2.3' at column 1");
  expect_parse_error("2e+", "expected digits of the exponent at column 4");
  expect_parse_error("x1 $ 2", "unexpected character '$' at column 4");
  expect_parse_error("(x1, x2) + 1", "a vector (e1, e2, ...) can only be the whole expression at column 1");
  expect_parse_error("", "expected an operand at column 1");
  expect_parse_error("()", "expected an operand, got ')' at column 2");
  expect_parse_error("[1 2]", "expected ',' at column 4");
  expect_parse_error("sin x1", "expected '(' at column 5");
}

TEST(Parser, BadVariableLists) {
  EXPECT_THROW(Function({"x", "x"}, "x"), Error);
  EXPECT_THROW(Function({"pi"}, "pi"), Error);
  EXPECT_THROW(Function({"sin"}, "1"), Error);
  EXPECT_THROW(Function({"2x"}, "1"), Error);
  EXPECT_THROW(Function({""}, "1"), Error);
  EXPECT_THROW(detail::parse_expr({"x"}, "(x, x)"), ParseError);
  ExprVar x("x"), y("y");
  EXPECT_THROW(Function({x}, x + y), Error);  // y undeclared
}

TEST(Parser, PathologicalTextsRaiseInsteadOfCrashing) {
  const std::string deep = std::string(100000, '(') + "x1" + std::string(100000, ')');
  EXPECT_THROW(Function({"x1"}, deep), ParseError);
  EXPECT_THROW(Function({"x1"}, std::string(100000, '-') + "x1"), ParseError);
  std::string pw = "x1";
  for (int i = 0; i < 100000; ++i) pw += "^x1";
  EXPECT_THROW(Function({"x1"}, pw), ParseError);
  // Moderate nesting is fine.
  EXPECT_EQ(Function({"x1"}, std::string(100, '(') + "x1" + std::string(100, ')')).eval(IntervalVector{Interval(2.0)}),
            Interval(2.0));
}

TEST(Parser, LongFlatExpressions) {
  // 200000 terms: parsing, compiling, printing, differentiating and destroying
  // a long chain must not recurse per term.
  std::string text = "x1";
  for (int i = 1; i < 200000; ++i) text.append(i % 2 ? " + x1 * " : " - ").append(std::to_string(i % 7));
  Function f({"x1"}, text);
  EXPECT_GT(f.tape_size(), 100000u);
  EXPECT_TRUE(f.eval(IntervalVector{Interval(1.0)}).is_degenerate());
  EXPECT_EQ(Function({"x1"}, f.expr_str()).exprs(), f.exprs());
  EXPECT_EQ(f.diff().image_dim(), 1u);
}

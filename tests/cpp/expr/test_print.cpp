// Printing of expressions: shared sub-expressions are named by let-bindings,
// so that the text stays linear in the size of the DAG and reads back into
// the same DAG.
#include <gtest/gtest.h>

#include <sstream>

#include "sillage/expr/diff.h"
#include "sillage/expr/function.h"
#include "sillage/expr/parser.h"

using namespace sillage;

namespace {

// e = x; e = e*e + 1, n times.
Expr tower(const Expr& x, int n) {
  Expr e = x;
  for (int i = 0; i < n; ++i) e = e * e + 1;
  return e;
}

}  // namespace

TEST(Print, TreesPrintAsBefore) {
  ExprVar x("x"), y("y");
  EXPECT_EQ((sqr(x - 1) + sqr(y - 2)).str(), "(x - 1)^2 + (y - 2)^2");
  EXPECT_EQ(((x - 1) * (x - 1)).str(), "(x - 1) * (x - 1)");  // short: inline
  EXPECT_EQ((sin(x) * sin(x) + sin(x)).str(), "sin(x) * sin(x) + sin(x)");
}

// A sign right after an operator is parenthesised ("x - -17.66" reads as a
// typo), and the text still parses back into the same DAG.
TEST(Print, SignsAfterOperatorsAreParenthesised) {
  ExprVar x("x"), y("y");
  const std::vector<std::pair<Expr, std::string>> cases = {
      {x - (-17.5), "x - (-17.5)"}, {x + (-2), "x + (-2)"},     {x * (-2), "x * (-2)"},
      {x / (-y), "x / (-y)"},       {-(-x), "-(-x)"},            {x - -y * 2, "x - (-y * 2)"},
      {-2 - x, "-2 - x"},           {-x * y, "-x * y"},          {sqr(x - (-0.5)), "(x - (-0.5))^2"}};
  for (const auto& [e, text] : cases) {
    EXPECT_EQ(e.str(), text);
    EXPECT_EQ(detail::parse_expr({"x", "y"}, text), e) << text;
  }
}

TEST(Print, SharedNodesAreNamedOnce) {
  ExprVar x("x"), y("y");
  EXPECT_EQ(tower(x, 1).str(), "x * x + 1");
  EXPECT_EQ(tower(x, 2).str(), "let a = x * x + 1 in a * a + 1");
  EXPECT_EQ(tower(x, 3).str(), "let a = x * x + 1; b = a * a + 1 in b * b + 1");
  const Expr s = sqrt(sqr(x) + sqr(y));
  EXPECT_EQ((x / s + y / s).str(), "let a = sqrt(x^2 + y^2) in x / a + y / a");
  // The root itself shared between the outputs of a Function.
  EXPECT_EQ(Function({x, y}, std::vector<Expr>{s, s * 2}).expr_str(), "let a = sqrt(x^2 + y^2) in (a, a * 2)");
}

TEST(Print, NamesAvoidTheVariables) {
  ExprVar a("a"), b("b");
  EXPECT_EQ(tower(a, 3).str(), "let b = a * a + 1; c = b * b + 1 in c * c + 1");
  EXPECT_EQ(tower(a * b, 2).str(), "let c = a * b * (a * b) + 1 in c * c + 1");
  // Variables of the Function that the expression does not use are avoided too.
  ExprVar x("x");
  EXPECT_EQ(Function({ExprVar("a"), x}, tower(x, 2)).expr_str(), "let b = x * x + 1 in b * b + 1");
}

TEST(Print, LetReadsBack) {
  ExprVar x("x");
  for (int n : {2, 3, 10}) {
    const Expr e = tower(x, n);
    EXPECT_EQ(detail::parse_expr({"x"}, e.str()), e) << n;
  }
  EXPECT_EQ(detail::parse_expr({"x"}, "let a = x + 1; b = sin(a) in b * b + a"),
            detail::parse_expr({"x"}, "sin(x + 1) * sin(x + 1) + (x + 1)"));
  EXPECT_THROW(detail::parse_expr({"x"}, "let x = 1 in x"), ParseError);      // a variable
  EXPECT_THROW(detail::parse_expr({"x"}, "let a = 1; a = 2 in a"), ParseError);  // bound twice
  EXPECT_THROW(detail::parse_expr({"x"}, "let sin = 1 in x"), ParseError);    // reserved
  EXPECT_THROW(detail::parse_expr({"x"}, "let a = 1 a"), ParseError);         // no 'in'
  EXPECT_THROW(detail::parse_expr({"x"}, "x + let a = 1 in a"), ParseError);  // only in front
}

TEST(Print, DeepNestsPrintWithinTheParserLimit) {
  // 1000 nested calls (built, not parsed): the 400 innermost are named, so
  // that no part of the text nests deeper than the parser's 500 levels.
  ExprVar x("x");
  for (auto wrap : {+[](const Expr& e) { return sin(e); }, +[](const Expr& e) { return -(e * 2); },
                    +[](const Expr& e) { return 1 - e; }, +[](const Expr& e) { return sqr(e + 1); }}) {
    Expr e = x;
    for (int i = 0; i < 1000; ++i) e = wrap(e);
    const std::string text = e.str();
    EXPECT_EQ(text.substr(0, 4), "let ");
    EXPECT_EQ(detail::parse_expr({"x"}, text), e);
  }
  // Shallow ones are left alone.
  Expr e = x;
  for (int i = 0; i < 400; ++i) e = sin(e);
  EXPECT_EQ(e.str().substr(0, 8), "sin(sin(");
}

TEST(Print, SharedDagsPrintLinearly) {
  // 40 levels: 2^40 leaves as a tree; 40 bindings of about 20 characters here.
  ExprVar x("x");
  const Expr e = tower(x, 40);
  const std::string text = e.str();
  EXPECT_LT(text.size(), 40u * 24);
  EXPECT_EQ(text.substr(0, 35), "let a = x * x + 1; b = a * a + 1; c");
  EXPECT_EQ(detail::parse_expr({"x"}, text), e);
  // The derivative of a deep nest shares sin^k(x) with cos(sin^k(x)).
  Expr s = x;
  for (int i = 0; i < 300; ++i) s = sin(s);
  const std::string d = detail::diff(s, x).str();
  EXPECT_LT(d.size(), 300u * 60);
  EXPECT_EQ(detail::parse_expr({"x"}, d), detail::diff(s, x));
}

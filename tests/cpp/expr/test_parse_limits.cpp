// Parse errors on non-ASCII text (whole characters quoted, columns counted in
// characters, messages valid UTF-8), long texts quoted briefly, and the
// nesting limit of 500 levels, exactly.
#include <gtest/gtest.h>

#include "sillage/error.h"
#include "sillage/expr/function.h"
#include "sillage/expr/parser.h"

using namespace sillage;

namespace {

std::string parse_error(const std::string& text) {
  try {
    detail::parse_expr({"x", "y"}, text);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "no error";
}

std::string nested(const std::string& open, int n, const std::string& close) {
  std::string s;
  for (int i = 0; i < n; ++i) s += open;
  s += "x";
  for (int i = 0; i < n; ++i) s += close;
  return s;
}

}  // namespace

TEST(ParseLimits, NonAsciiCharactersAreQuotedWhole) {
  EXPECT_EQ(parse_error("x + é"), "unexpected character 'é' (U+00E9) at column 5 in \"x + é\"");
  EXPECT_EQ(parse_error("α + x"), "unexpected character 'α' (U+03B1) at column 1 in \"α + x\"");
  // Columns count characters: "é" is one column, two bytes.
  EXPECT_EQ(parse_error("é"), "unexpected character 'é' (U+00E9) at column 1 in \"é\"");
  EXPECT_EQ(parse_error("(é, x) + $"), "unexpected character 'é' (U+00E9) at column 2 in \"(é, x) + $\"");
  EXPECT_EQ(parse_error("x + 😀"), "unexpected character '😀' (U+1F600) at column 5 in \"x + 😀\"");
  EXPECT_EQ(parse_error("x ×"), "unexpected character '×' (U+00D7) at column 3 in \"x ×\"");
  EXPECT_EQ(parse_error("sin(é) +"), "unexpected character 'é' (U+00E9) at column 5 in \"sin(é) +\"");
  // After a non-ASCII character, later columns still count characters.
  EXPECT_EQ(parse_error("x\u00A0"), "unexpected character '\u00A0' (U+00A0) at column 2 in \"x\u00A0\"");
}

TEST(ParseLimits, InvalidUtf8IsReportedAsBytes) {
  // Latin-1 é: a lone byte; the message itself stays valid UTF-8 (U+FFFD).
  EXPECT_EQ(parse_error("x + \xE9"),
            "unexpected byte 0xE9 (the text is not valid UTF-8) at column 5 in \"x + \xEF\xBF\xBD\"");
  EXPECT_EQ(parse_error("x\x01"), "unexpected control character U+0001 at column 2 in \"x\x01\"");
}

TEST(ParseLimits, LongTextsAreQuotedNearTheError) {
  std::string text = "x";
  for (int i = 0; i < 100; ++i) text += " + x";
  text += " $";
  const std::string m = parse_error(text);
  EXPECT_EQ(m, "unexpected character '$' at column 403 near \"...x + x + x + x + x + x + x + x $\"");
  // A long token is quoted up to 60 characters too.
  EXPECT_EQ(parse_error("x + " + std::string(1000, 'z')), "unknown identifier '" + std::string(60, 'z') +
                                                            "...' at column 5 near \"x + " + std::string(56, 'z') +
                                                            "...\"");
}

TEST(ParseLimits, NestingLimitIsExactly500Levels) {
  const IntervalVector x{Interval(2.0), Interval(0.0)};
  for (const auto& [open, close] : std::vector<std::pair<std::string, std::string>>{
           {"(", ")"}, {"sin(", ")"}, {"-", ""}, {"min(1, ", ")"}}) {
    EXPECT_NO_THROW(detail::parse_expr({"x", "y"}, nested(open, 500, close))) << open;
    EXPECT_EQ(parse_error(nested(open, 501, close)).substr(0, 48), "expression nested too deeply (more than 500 leve")
        << open;
  }
  EXPECT_EQ(Function({"x", "y"}, nested("(", 500, ")")).eval(x), Interval(2.0));
  // Exponents: x^x^...^x with 500 carets is 500 levels.
  std::string pw = "x";
  for (int i = 0; i < 500; ++i) pw += "^x";
  EXPECT_NO_THROW(detail::parse_expr({"x", "y"}, pw));
  EXPECT_NE(parse_error(pw + "^x").find("more than 500 levels"), std::string::npos);
}

// Layout of a figure: titles that fit the width (text_width.h) and the legend below the plot.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sillage/figures/figure.h"
#include "sillage/figures/text_width.h"
#include "svg_check.h"

using namespace sillage;
using namespace sillage::test;
using sillage::detail::text_width_px;
using sillage::detail::wrap_text;

namespace {

// The texts of every <text> element of class `cls`.
std::vector<std::string> texts_of(const std::string& svg, const std::string& cls) {
  std::vector<std::string> out;
  for (auto at = svg.find("class=\"" + cls + "\""); at != std::string::npos;
       at = svg.find("class=\"" + cls + "\"", at + 1)) {
    const auto open = svg.find('>', at) + 1;
    out.push_back(svg.substr(open, svg.find("</text>", open) - open));
  }
  return out;
}

}  // namespace

TEST(TextWidth, WrapsWithinTheWidth) {
  EXPECT_TRUE(wrap_text("", 15, 100).empty());
  EXPECT_GT(text_width_px("WWW", 10), text_width_px("iii", 10));
  const std::string title = "plaza1 range-only temporal SLAM: dead reckoning (grey), SLAM (blue), truth (red)";
  const auto lines = wrap_text(title, 15, 300);
  EXPECT_GE(lines.size(), 2u);
  std::string joined;
  for (const auto& l : lines) {
    EXPECT_LE(text_width_px(l, 15), 300) << l;
    joined += (joined.empty() ? "" : " ") + l;
  }
  EXPECT_EQ(joined, title);  // wrapped at spaces, nothing lost
  const auto cut = wrap_text("a_single_word_far_too_long_for_the_line", 15, 80);
  ASSERT_EQ(cut.size(), 1u);
  EXPECT_LE(text_width_px(cut[0], 15), 80);
  EXPECT_NE(cut[0].find("…"), std::string::npos);
}

TEST(FigureLayout, LongTitlesFitAndPushThePlotDown) {
  Figure fig(IntervalVector{Interval(0, 1), Interval(0, 1)}, 300, 200);
  const double top = fig.plot_top();
  fig.set_title("Loops of the plaza1 run on the map: the position tube, the path and every detection, proven or not");
  const std::string svg = fig.svg();
  parse_xml(svg);
  const auto lines = texts_of(svg, "title");
  ASSERT_GE(lines.size(), 2u);
  for (const auto& l : lines) EXPECT_LE(text_width_px(l, 15), fig.svg_width()) << l;
  EXPECT_GT(fig.plot_top(), top);
}

TEST(FigureLayout, LegendFromTwoLabelledStyles) {
  Figure fig(IntervalVector{Interval(0, 1), Interval(0, 1)}, 300, 200);
  fig.draw_box(IntervalVector{Interval(0, 0.5), Interval(0, 0.5)}, Style{"red", "none", 1, 1, "a", "boxes"});
  fig.draw_box(IntervalVector{Interval(0.5, 1), Interval(0, 0.5)}, Style{"red", "none", 1, 1, "a", "boxes"});
  const double h1 = fig.svg_height();
  EXPECT_EQ(fig.legend().size(), 1u);
  EXPECT_EQ(fig.svg().find("class=\"legend\""), std::string::npos);  // one entry: no legend
  fig.draw_polyline({{0, 0}, {1, 1}}, Style{"none", "blue", 1, 1, "b", "line"});
  fig.draw_polyline({{0, 1}, {1, 0}}, Style{"none", "green", 1, 1, "c", ""});  // unlabelled: no entry
  ASSERT_EQ(fig.legend().size(), 2u);
  EXPECT_EQ(fig.legend()[1].mark, LegendMark::Line);
  const std::string svg = fig.svg();
  parse_xml(svg);
  EXPECT_NE(svg.find("class=\"legend\""), std::string::npos);
  EXPECT_NE(svg.find(">line</text>"), std::string::npos);
  EXPECT_GT(fig.svg_height(), h1);  // room made below the plot
}

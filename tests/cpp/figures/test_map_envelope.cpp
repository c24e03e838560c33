// The envelope of a map: the union of the slice boxes covered on a grid, as
// outline loops; the figure draws it with a few boxes, not one shape per slice.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "sillage/figures/map_envelope.h"
#include "svg_check.h"

using namespace sillage;

namespace {

// Two slices: [0, 0.5] × [0, 0.5] and [2.2, 2.7] × [0.2, 0.4], gates inside them.
TubeVector two_boxes() {
  auto td = std::make_shared<TDomain>(0.0, 2.0, 1.0);
  TubeVector x(td, 2);
  x[0].set(Interval(0, 0.5), 0);
  x[1].set(Interval(0, 0.5), 0);
  x[0].set(Interval(2.2, 2.7), 1);
  x[1].set(Interval(0.2, 0.4), 1);
  for (std::size_t k = 0; k <= 2; ++k) {
    x[0].set_gate(k, Interval(k < 2 ? 0.2 : 2.3));
    x[1].set_gate(k, Interval(k < 2 ? 0.2 : 0.3));
  }
  return x;
}

}  // namespace

TEST(MapEnvelope, CoversEachBoxWithTheCellsItTouches) {
  // Cells of 0.5: the first box touches 2 × 2 cells (its upper edges are cell edges), the second 2 × 1.
  const auto loops = map_envelope(two_boxes(), 0, 1, IntervalVector{Interval(0, 4), Interval(0, 1)}, 8);
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_FALSE(loops[0].is_hole);
  EXPECT_FALSE(loops[1].is_hole);
  EXPECT_DOUBLE_EQ(loops[0].length(), 4.0);  // [0, 1] × [0, 1]
  EXPECT_DOUBLE_EQ(loops[1].length(), 3.0);  // [2, 3] × [0, 0.5]
  EXPECT_EQ(loops[1].vertices().front(), (Point2{2, 0}));
}

TEST(MapEnvelope, ABoxBeyondTheWindowIsClipped) {
  TubeVector x = two_boxes();
  x[0].set(Interval(3.5, 10), 1);  // reaches far right of the window
  const auto loops = map_envelope(x, 0, 1, IntervalVector{Interval(0, 4), Interval(0, 1)}, 8);
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_DOUBLE_EQ(loops[1].length(), 2 * 0.5 + 2 * 0.5);  // [3.5, 4] × [0, 0.5]
}

TEST(MapEnvelope, BadArgumentsSayWhat) {
  const TubeVector x = two_boxes();
  EXPECT_THROW(map_envelope(x, 0, 0, IntervalVector{Interval(0, 1), Interval(0, 1)}), DimensionError);
  EXPECT_THROW(map_envelope(x, 0, 1, IntervalVector{Interval(0, 1), Interval(0, 1)}, 0), Error);
  EXPECT_THROW(map_envelope(x, 0, 1, IntervalVector{Interval(), Interval(0, 1)}), Error);
}

TEST(MapEnvelope, TheFigureDrawsTheOutlineAndAFewBoxes) {
  auto td = std::make_shared<TDomain>(0.0, 1000.0, 1.0);
  TubeVector x(td, "(t + [-1, 1], sin(t / 50) * 10 + [-1, 1])");
  const Figure f = map_envelope_figure(x, 0, 1, "map", {}, nullptr, nullptr, 600, nullptr, "x (m)", "y (m)", 5);
  const std::string svg = f.svg();
  sillage::test::parse_xml(svg);  // well-formed
  EXPECT_NE(svg.find("<polygon"), std::string::npos);
  EXPECT_NE(svg.find("envelope of the 1000 slice boxes"), std::string::npos);
  EXPECT_NE(svg.find("a slice box (5 drawn)"), std::string::npos);
  // 1000 slices: a handful of shapes (outline, 5 boxes, 2 gates, legend), not one per slice.
  EXPECT_LT(f.nb_shapes(), 20u);
}

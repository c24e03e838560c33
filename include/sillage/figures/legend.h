#pragma once
// The legend of a figure: one entry per kind of thing drawn, a swatch of its
// style (a box, a line or a dot) and its text, laid out in rows below the
// plot so that it never hides what is drawn.
#include <string>
#include <vector>

#include "sillage/figures/style.h"

namespace sillage {

// What the swatch of a legend entry shows of its style.
enum class LegendMark { Box, Line, Dot };

// One entry of a legend.
struct LegendEntry {
  // The text (a style's label).
  std::string text;
  // The style drawn in the swatch.
  Style style;
  // The swatch's shape.
  LegendMark mark = LegendMark::Box;
};

// Height in pixels of the legend laid out in rows at most max_px wide (0 when empty).
double legend_height(const std::vector<LegendEntry>& entries, double max_px);

// SVG elements of the legend, its top left corner at (x, y), rows at most max_px wide.
std::string legend_svg(const std::vector<LegendEntry>& entries, double x, double y, double max_px);

}  // namespace sillage

#pragma once
// Estimated widths of SVG text, so that figures can wrap titles and lay out
// legends without a font engine. The estimate is from the advance widths of
// DejaVu Sans (the usual sans-serif fallback), rounded up: text estimated to
// fit does fit, with a little room to spare.
#include <string>
#include <vector>

namespace sillage::detail {

// Estimated width in pixels of `text` (UTF-8) at the font size size_px.
double text_width_px(const std::string& text, double size_px);

// `text` broken at spaces into lines whose estimated width is at most
// max_px; a single word wider than that is cut with an ellipsis. An empty
// text gives no line.
std::vector<std::string> wrap_text(const std::string& text, double size_px, double max_px);

}  // namespace sillage::detail

#include "sillage/figures/legend.h"

#include <algorithm>
#include <cstdio>

#include "sillage/figures/figure.h"
#include "sillage/figures/text_width.h"

namespace sillage {

namespace {

constexpr double kFont = 11, kSwatch = 22, kGap = 5, kSpacing = 16, kRow = 17;

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

double entry_width(const LegendEntry& e) { return kSwatch + kGap + detail::text_width_px(e.text, kFont); }

// The (x offset, row) of each entry: entries fill a row until the next would pass max_px.
std::vector<std::pair<double, int>> layout(const std::vector<LegendEntry>& entries, double max_px) {
  std::vector<std::pair<double, int>> at;
  double x = 0;
  int row = 0;
  for (const LegendEntry& e : entries) {
    const double w = entry_width(e);
    if (x > 0 && x + w > max_px) x = 0, ++row;
    at.push_back({x, row});
    x += w + kSpacing;
  }
  return at;
}

// The swatch of an entry: a line, a dot or a small box drawn in its style.
std::string swatch(const LegendEntry& e, double x, double y) {
  const Style& s = e.style;
  const std::string stroke = xml_escape(s.stroke), fill = xml_escape(s.fill);
  const double cy = y + kRow / 2 - 2;
  switch (e.mark) {
    case LegendMark::Line:
      return "<line x1=\"" + fmt(x) + "\" y1=\"" + fmt(cy) + "\" x2=\"" + fmt(x + kSwatch) + "\" y2=\"" + fmt(cy) +
             "\" stroke=\"" + stroke + "\" stroke-width=\"" + fmt(std::clamp(s.stroke_width, 1.0, 4.0)) + "\"/>";
    case LegendMark::Dot:
      return "<circle cx=\"" + fmt(x + kSwatch / 2) + "\" cy=\"" + fmt(cy) + "\" r=\"4.5\" fill=\"" + fill +
             "\" stroke=\"" + stroke + "\" stroke-width=\"" + fmt(std::min(s.stroke_width, 2.0)) + "\"/>";
    case LegendMark::Box: break;
  }
  return "<rect x=\"" + fmt(x + 2) + "\" y=\"" + fmt(cy - 5) + "\" width=\"" + fmt(kSwatch - 4) +
         "\" height=\"10\" fill=\"" + fill + "\" fill-opacity=\"" + fmt(std::clamp(s.opacity, 0.0, 1.0)) +
         "\" stroke=\"" + stroke + "\" stroke-width=\"" + fmt(std::clamp(s.stroke_width, 0.5, 2.0)) + "\"/>";
}

}  // namespace

double legend_height(const std::vector<LegendEntry>& entries, double max_px) {
  if (entries.empty()) return 0;
  return (layout(entries, max_px).back().second + 1) * kRow;
}

std::string legend_svg(const std::vector<LegendEntry>& entries, double x, double y, double max_px) {
  std::string out = "<g class=\"legend\" font-size=\"" + fmt(kFont) + "\">\n";
  const auto at = layout(entries, max_px);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const double ex = x + at[i].first, ey = y + at[i].second * kRow;
    out += swatch(entries[i], ex, ey) + "<text x=\"" + fmt(ex + kSwatch + kGap) + "\" y=\"" + fmt(ey + kRow / 2 + 2) +
           "\">" + xml_escape(entries[i].text) + "</text>\n";
  }
  return out + "</g>\n";
}

}  // namespace sillage

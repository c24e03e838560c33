#include "sillage/figures/figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "sillage/figures/text_width.h"

namespace sillage {

namespace {

// Margins around the plot area; the top one grows with the title's lines.
constexpr double kLeft = 60, kRight = 20, kTop = 36, kBottom = 44;
constexpr double kTitleFont = 15, kTitleLine = 18, kNoteFont = 11, kNoteLine = 14;

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

std::string label(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", std::abs(v) < 1e-12 ? 0.0 : v);
  return buf;
}

// A "nice" tick step (1, 2 or 5 times a power of ten) giving about 6 ticks.
double tick_step(double span) {
  const double raw = span / 6;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double n = raw / mag;
  return (n < 1.5 ? 1 : n < 3 ? 2 : n < 7 ? 5 : 10) * mag;
}

}  // namespace

std::string xml_escape(const std::string& text) {
  std::string r;
  r.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': r += "&amp;"; break;
      case '<': r += "&lt;"; break;
      case '>': r += "&gt;"; break;
      case '"': r += "&quot;"; break;
      case '\'': r += "&apos;"; break;
      default: r += c;
    }
  }
  return r;
}

Figure::Figure(const IntervalVector& view, double width_px, double height_px) {
  if (view.size() != 2) {
    throw DimensionError("Figure: the view must be a 2-D box, got dimension " + std::to_string(view.size()));
  }
  if (view.is_empty() || view.is_unbounded() || view[0].is_degenerate() || view[1].is_degenerate()) {
    throw Error("Figure: the view " + view.str() + " must be bounded with non-zero widths");
  }
  if (!(width_px > 0 && width_px < 1e5) || !(height_px >= 0 && height_px < 1e5)) {
    throw Error("Figure: invalid size " + std::to_string(width_px) + " x " + std::to_string(height_px) + " px");
  }
  vx_ = view[0];
  vy_ = view[1];
  width_ = width_px;
  height_ = height_px > 0 ? height_px : std::clamp(width_px * vy_.diam() / vx_.diam(), 50.0, 4 * width_px);
}

void Figure::set_labels(const std::string& x_label, const std::string& y_label) {
  x_label_ = x_label;
  y_label_ = y_label;
}

void Figure::add_legend(const std::string& text, const Style& style, LegendMark mark) {
  if (text.empty()) return;
  for (const LegendEntry& e : legend_) {
    if (e.text == text) return;
  }
  legend_.push_back({text, style, mark});
}

void Figure::push(std::string shape, const Style& style, LegendMark mark) {
  shapes_.push_back(std::move(shape));
  add_legend(style.label, style, mark);
}

void Figure::set_projection(std::size_t i, std::size_t j) {
  if (i == j) throw Error("Figure::set_projection: the two dimensions must differ (" + std::to_string(i) + ")");
  dim_x_ = i;
  dim_y_ = j;
}

double Figure::px(double x) const { return kLeft + (x - vx_.lb()) / (vx_.ub() - vx_.lb()) * width_; }
double Figure::py(double y) const { return kTop + (vy_.ub() - y) / (vy_.ub() - vy_.lb()) * height_; }

double Figure::svg_width() const { return kLeft + width_ + kRight; }

double Figure::plot_top() const {
  const double lines = kTitleLine * static_cast<double>(detail::wrap_text(title_, kTitleFont, svg_width() - 12).size()) +
                       kNoteLine * static_cast<double>(detail::wrap_text(note_, kNoteFont, svg_width() - 12).size());
  return std::max(kTop, lines + 18);
}

double Figure::svg_height() const {
  const double legend = legend_.size() >= 2 ? legend_height(legend_, width_) + 4 : 0;
  return plot_top() + height_ + kBottom + legend;
}

std::string Figure::style_attributes(const Style& s) const {
  std::string a = " fill=\"" + xml_escape(s.fill) + "\" stroke=\"" + xml_escape(s.stroke) + "\" stroke-width=\"" +
                  fmt(s.stroke_width) + "\"";
  if (s.opacity < 1) a += " fill-opacity=\"" + fmt(std::clamp(s.opacity, 0.0, 1.0)) + "\"";
  if (!s.css_class.empty()) a += " class=\"" + xml_escape(s.css_class) + "\"";
  return a;
}

void Figure::check_point(const Vector& p, const char* where) const {
  if (p.size() <= std::max(dim_x_, dim_y_)) {
    throw DimensionError(std::string("Figure::") + where + ": point of dimension " + std::to_string(p.size()) +
                         " for the projection (" + std::to_string(dim_x_) + ", " + std::to_string(dim_y_) + ")");
  }
  if (!std::isfinite(p[dim_x_]) || !std::isfinite(p[dim_y_])) {
    throw Error(std::string("Figure::") + where + ": the point must be finite");
  }
}

void Figure::draw_box(const IntervalVector& box, const Style& style) {
  if (box.size() <= std::max(dim_x_, dim_y_)) {
    throw DimensionError("Figure::draw_box: box of dimension " + std::to_string(box.size()) +
                         " for the projection (" + std::to_string(dim_x_) + ", " + std::to_string(dim_y_) + ")");
  }
  if (box.is_empty()) return;
  const Interval x = box[dim_x_] & vx_, y = box[dim_y_] & vy_;  // clip to the window
  if (x.is_empty() || y.is_empty()) return;
  push("<rect x=\"" + fmt(px(x.lb())) + "\" y=\"" + fmt(py(y.ub())) + "\" width=\"" +
                    fmt(px(x.ub()) - px(x.lb())) + "\" height=\"" + fmt(py(y.lb()) - py(y.ub())) + "\"" +
                    style_attributes(style) + "/>",
       style, LegendMark::Box);
}

void Figure::draw_boxes(const std::vector<IntervalVector>& boxes, const Style& style) {
  for (const auto& b : boxes) draw_box(b, style);
}

void Figure::draw_ring(const Vector& center, const Interval& radius, const Style& style) {
  check_point(center, "draw_ring");
  if (radius.is_empty() || radius.ub() < 0) return;
  if (radius.is_unbounded()) throw Error("Figure::draw_ring: unbounded radius " + radius.str());
  const double cx = px(center[dim_x_]), cy = py(center[dim_y_]);
  const double sx = width_ / vx_.diam(), sy = height_ / vy_.diam();
  // One ellipse per radius (the scales of the axes may differ); even-odd fill makes the hole.
  auto ellipse = [&](double r) {
    const double rx = r * sx, ry = r * sy;
    return "M " + fmt(cx + rx) + " " + fmt(cy) + " A " + fmt(rx) + " " + fmt(ry) + " 0 1 0 " + fmt(cx - rx) + " " +
           fmt(cy) + " A " + fmt(rx) + " " + fmt(ry) + " 0 1 0 " + fmt(cx + rx) + " " + fmt(cy) + " Z";
  };
  std::string d = ellipse(radius.ub());
  if (radius.lb() > 0) {
    d += ' ';
    d += ellipse(radius.lb());
  }
  push("<path d=\"" + d + "\" fill-rule=\"evenodd\"" + style_attributes(style) + "/>", style, LegendMark::Box);
}

void Figure::draw_point(const Vector& p, double radius_px, const Style& style) {
  check_point(p, "draw_point");
  if (!(radius_px > 0)) throw Error("Figure::draw_point: the radius must be > 0");
  push("<circle cx=\"" + fmt(px(p[dim_x_])) + "\" cy=\"" + fmt(py(p[dim_y_])) + "\" r=\"" + fmt(radius_px) + "\"" +
           style_attributes(style) + "/>",
       style, LegendMark::Dot);
}

void Figure::draw_polyline(const std::vector<Vector>& points, const Style& style, bool closed) {
  if (points.empty()) return;
  std::string pts;
  for (const auto& p : points) {
    check_point(p, "draw_polyline");
    if (!pts.empty()) pts += ' ';
    pts += fmt(px(p[dim_x_]));
    pts += ',';
    pts += fmt(py(p[dim_y_]));
  }
  push(std::string(closed ? "<polygon" : "<polyline") + " points=\"" + pts + "\"" + style_attributes(style) + "/>",
       style, closed ? LegendMark::Box : LegendMark::Line);
}

void Figure::draw_paving(const Paving& paving, bool show_outside) {
  for (std::size_t i = 0; i < paving.nb_nodes(); ++i) {
    if (!paving.is_leaf(i)) continue;
    const PavingTag t = paving.tag(i);
    if (t == PavingTag::Outside && !show_outside) continue;
    draw_box(paving.node_box(i), paving_style(t));
  }
}

void Figure::draw_contour(const std::vector<ContourLoop>& loops, const Style& style) {
  // Contours live in the plane of the figure (x, y), whatever the projection.
  for (const auto& loop : loops) {
    std::string pts;
    for (const auto& v : loop.vertices()) {
      if (!pts.empty()) pts += ' ';
      pts += fmt(px(v.x));
      pts += ',';
      pts += fmt(py(v.y));
    }
    push("<polygon points=\"" + pts + "\"" + style_attributes(style) + "/>", style, LegendMark::Box);
  }
}

void Figure::draw_text(const Vector& p, const std::string& text, double size_px, const std::string& colour) {
  check_point(p, "draw_text");
  shapes_.push_back("<text x=\"" + fmt(px(p[dim_x_])) + "\" y=\"" + fmt(py(p[dim_y_])) + "\" font-size=\"" +
                    fmt(size_px) + "\" fill=\"" + xml_escape(colour) + "\">" + xml_escape(text) + "</text>");
}

std::string Figure::svg() const {
  const double w = svg_width(), h = svg_height(), top = plot_top();
  std::ostringstream os;
  os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
     << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << fmt(w) << "\" height=\"" << fmt(h)
     << "\" viewBox=\"0 0 " << fmt(w) << " " << fmt(h) << "\" font-family=\"sans-serif\">\n"
     << "<defs><clipPath id=\"plot\"><rect x=\"" << fmt(kLeft) << "\" y=\"" << fmt(kTop) << "\" width=\""
     << fmt(width_) << "\" height=\"" << fmt(height_) << "\"/></clipPath></defs>\n"
     << "<rect x=\"0\" y=\"0\" width=\"" << fmt(w) << "\" height=\"" << fmt(h) << "\" fill=\"white\" class=\"background\"/>\n";
  // Title and note lines, centred on the whole width so that they never pass its sides.
  double y = 4;
  for (const std::string& line : detail::wrap_text(title_, kTitleFont, w - 12)) {
    y += kTitleLine;
    os << "<text x=\"" << fmt(w / 2) << "\" y=\"" << fmt(y) << "\" text-anchor=\"middle\" font-size=\"" << fmt(kTitleFont)
       << "\" class=\"title\">" << xml_escape(line) << "</text>\n";
  }
  for (const std::string& line : detail::wrap_text(note_, kNoteFont, w - 12)) {
    y += kNoteLine;
    os << "<text x=\"" << fmt(w / 2) << "\" y=\"" << fmt(y) << "\" text-anchor=\"middle\" font-size=\"" << fmt(kNoteFont)
       << "\" fill=\"#555555\" class=\"note\">" << xml_escape(line) << "</text>\n";
  }
  // The plot is drawn with its top at kTop (px, py) and shifted below the title.
  os << "<g class=\"plot\" transform=\"translate(0 " << fmt(top - kTop) << ")\">\n<g clip-path=\"url(#plot)\">\n";
  for (const auto& s : shapes_) os << s << "\n";
  os << "</g>\n<g class=\"axes\" stroke=\"black\" font-size=\"11\">\n"
     << "<rect x=\"" << fmt(kLeft) << "\" y=\"" << fmt(kTop) << "\" width=\"" << fmt(width_) << "\" height=\""
     << fmt(height_) << "\" fill=\"none\" class=\"frame\"/>\n";
  const double sx = tick_step(vx_.diam()), sy = tick_step(vy_.diam());
  for (double t = std::ceil(vx_.lb() / sx) * sx; t <= vx_.ub() + 1e-9 * sx; t += sx) {
    const double x = px(t), yb = kTop + height_;
    os << "<line x1=\"" << fmt(x) << "\" y1=\"" << fmt(yb) << "\" x2=\"" << fmt(x) << "\" y2=\"" << fmt(yb + 5)
       << "\"/><text x=\"" << fmt(x) << "\" y=\"" << fmt(yb + 17) << "\" text-anchor=\"middle\" stroke=\"none\">"
       << label(t) << "</text>\n";
  }
  for (double t = std::ceil(vy_.lb() / sy) * sy; t <= vy_.ub() + 1e-9 * sy; t += sy) {
    const double yt = py(t);
    os << "<line x1=\"" << fmt(kLeft - 5) << "\" y1=\"" << fmt(yt) << "\" x2=\"" << fmt(kLeft) << "\" y2=\""
       << fmt(yt) << "\"/><text x=\"" << fmt(kLeft - 8) << "\" y=\"" << fmt(yt + 4)
       << "\" text-anchor=\"end\" stroke=\"none\">" << label(t) << "</text>\n";
  }
  if (!x_label_.empty()) {
    os << "<text x=\"" << fmt(kLeft + width_ / 2) << "\" y=\"" << fmt(kTop + height_ + kBottom - 6)
       << "\" text-anchor=\"middle\" stroke=\"none\" class=\"x-label\">" << xml_escape(x_label_) << "</text>\n";
  }
  if (!y_label_.empty()) {
    os << "<text x=\"14\" y=\"" << fmt(kTop + height_ / 2) << "\" text-anchor=\"middle\" stroke=\"none\" "
       << "class=\"y-label\" transform=\"rotate(-90 14 " << fmt(kTop + height_ / 2) << ")\">" << xml_escape(y_label_)
       << "</text>\n";
  }
  os << "</g>\n</g>\n";
  if (legend_.size() >= 2) os << legend_svg(legend_, kLeft, top + height_ + kBottom, width_);
  os << "</svg>\n";
  return os.str();
}

void Figure::save(const std::string& path) const {
  std::ofstream f(path);
  if (!f) throw Error("Figure::save: cannot open '" + path + "' for writing");
  f << svg();
  if (!f) throw Error("Figure::save: cannot write '" + path + "'");
}

}  // namespace sillage

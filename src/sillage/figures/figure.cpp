#include "sillage/figures/figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace sillage {

namespace {

constexpr double kLeft = 60, kRight = 20, kTop = 36, kBottom = 44;

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

void Figure::set_projection(std::size_t i, std::size_t j) {
  if (i == j) throw Error("Figure::set_projection: the two dimensions must differ (" + std::to_string(i) + ")");
  dim_x_ = i;
  dim_y_ = j;
}

double Figure::px(double x) const { return kLeft + (x - vx_.lb()) / (vx_.ub() - vx_.lb()) * width_; }
double Figure::py(double y) const { return kTop + (vy_.ub() - y) / (vy_.ub() - vy_.lb()) * height_; }

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
  shapes_.push_back("<rect x=\"" + fmt(px(x.lb())) + "\" y=\"" + fmt(py(y.ub())) + "\" width=\"" +
                    fmt(px(x.ub()) - px(x.lb())) + "\" height=\"" + fmt(py(y.lb()) - py(y.ub())) + "\"" +
                    style_attributes(style) + "/>");
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
  shapes_.push_back("<path d=\"" + d + "\" fill-rule=\"evenodd\"" + style_attributes(style) + "/>");
}

void Figure::draw_point(const Vector& p, double radius_px, const Style& style) {
  check_point(p, "draw_point");
  if (!(radius_px > 0)) throw Error("Figure::draw_point: the radius must be > 0");
  shapes_.push_back("<circle cx=\"" + fmt(px(p[dim_x_])) + "\" cy=\"" + fmt(py(p[dim_y_])) + "\" r=\"" +
                    fmt(radius_px) + "\"" + style_attributes(style) + "/>");
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
  shapes_.push_back(std::string(closed ? "<polygon" : "<polyline") + " points=\"" + pts + "\"" +
                    style_attributes(style) + "/>");
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
    shapes_.push_back("<polygon points=\"" + pts + "\"" + style_attributes(style) + "/>");
  }
}

void Figure::draw_text(const Vector& p, const std::string& text, double size_px, const std::string& colour) {
  check_point(p, "draw_text");
  shapes_.push_back("<text x=\"" + fmt(px(p[dim_x_])) + "\" y=\"" + fmt(py(p[dim_y_])) + "\" font-size=\"" +
                    fmt(size_px) + "\" fill=\"" + xml_escape(colour) + "\">" + xml_escape(text) + "</text>");
}

std::string Figure::svg() const {
  const double w = kLeft + width_ + kRight, h = kTop + height_ + kBottom;
  std::ostringstream os;
  os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
     << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << fmt(w) << "\" height=\"" << fmt(h)
     << "\" viewBox=\"0 0 " << fmt(w) << " " << fmt(h) << "\" font-family=\"sans-serif\">\n"
     << "<defs><clipPath id=\"plot\"><rect x=\"" << fmt(kLeft) << "\" y=\"" << fmt(kTop) << "\" width=\""
     << fmt(width_) << "\" height=\"" << fmt(height_) << "\"/></clipPath></defs>\n"
     << "<rect x=\"0\" y=\"0\" width=\"" << fmt(w) << "\" height=\"" << fmt(h) << "\" fill=\"white\" class=\"background\"/>\n";
  if (!title_.empty()) {
    os << "<text x=\"" << fmt(kLeft + width_ / 2) << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">"
       << xml_escape(title_) << "</text>\n";
  }
  os << "<g clip-path=\"url(#plot)\">\n";
  for (const auto& s : shapes_) os << s << "\n";
  os << "</g>\n<g class=\"axes\" stroke=\"black\" font-size=\"11\">\n"
     << "<rect x=\"" << fmt(kLeft) << "\" y=\"" << fmt(kTop) << "\" width=\"" << fmt(width_) << "\" height=\""
     << fmt(height_) << "\" fill=\"none\" class=\"frame\"/>\n";
  const double sx = tick_step(vx_.diam()), sy = tick_step(vy_.diam());
  for (double t = std::ceil(vx_.lb() / sx) * sx; t <= vx_.ub() + 1e-9 * sx; t += sx) {
    const double x = px(t), y = kTop + height_;
    os << "<line x1=\"" << fmt(x) << "\" y1=\"" << fmt(y) << "\" x2=\"" << fmt(x) << "\" y2=\"" << fmt(y + 5)
       << "\"/><text x=\"" << fmt(x) << "\" y=\"" << fmt(y + 17) << "\" text-anchor=\"middle\" stroke=\"none\">"
       << label(t) << "</text>\n";
  }
  for (double t = std::ceil(vy_.lb() / sy) * sy; t <= vy_.ub() + 1e-9 * sy; t += sy) {
    const double y = py(t);
    os << "<line x1=\"" << fmt(kLeft - 5) << "\" y1=\"" << fmt(y) << "\" x2=\"" << fmt(kLeft) << "\" y2=\""
       << fmt(y) << "\"/><text x=\"" << fmt(kLeft - 8) << "\" y=\"" << fmt(y + 4)
       << "\" text-anchor=\"end\" stroke=\"none\">" << label(t) << "</text>\n";
  }
  if (!x_label_.empty()) {
    os << "<text x=\"" << fmt(kLeft + width_ / 2) << "\" y=\"" << fmt(h - 6)
       << "\" text-anchor=\"middle\" stroke=\"none\">" << xml_escape(x_label_) << "</text>\n";
  }
  if (!y_label_.empty()) {
    os << "<text x=\"14\" y=\"" << fmt(kTop + height_ / 2) << "\" text-anchor=\"middle\" stroke=\"none\" "
       << "transform=\"rotate(-90 14 " << fmt(kTop + height_ / 2) << ")\">" << xml_escape(y_label_) << "</text>\n";
  }
  os << "</g>\n</svg>\n";
  return os.str();
}

void Figure::save(const std::string& path) const {
  std::ofstream f(path);
  if (!f) throw Error("Figure::save: cannot open '" + path + "' for writing");
  f << svg();
  if (!f) throw Error("Figure::save: cannot write '" + path + "'");
}

}  // namespace sillage

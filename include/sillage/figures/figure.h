#pragma once
// Figure: a small SVG writer in world coordinates. A figure shows the window
// `view` (a 2-D box, or the projection of a box on two chosen dimensions),
// with axes, ticks and a title, and draws boxes, rings (an annulus of radius
// interval [r] around a point, as in thesis Fig. 2.9), points, polylines,
// pavings (thesis colours, see style.h) and contours. Shapes are clipped to
// the window; unbounded boxes are drawn up to its edges. What is drawn with a
// labelled style gets a legend entry (legend.h), shown below the plot when
// there are two or more. Long titles wrap over several lines.
#include <cstddef>
#include <string>
#include <vector>

#include "sillage/figures/legend.h"
#include "sillage/figures/style.h"
#include "sillage/interval/interval_vector.h"
#include "sillage/paving/contour.h"
#include "sillage/paving/paving.h"

namespace sillage {

class Figure {
 public:
  // view: bounded 2-D window with non-zero widths (else Error). The plot area
  // is width_px wide; its height keeps the aspect ratio of the view when
  // height_px is 0 (clamped to [50, 4 * width_px]).
  explicit Figure(const IntervalVector& view, double width_px = 600, double height_px = 0);

  // The title above the plot, wrapped over several lines if wider than the figure.
  void set_title(const std::string& title) { title_ = title; }
  // A note in small grey type below the title: what the reader should know to read the plot
  // (e.g. what lies beyond the window).
  void set_note(const std::string& note) { note_ = note; }
  // Adds a legend entry (none if the text is empty or already listed).
  void add_legend(const std::string& text, const Style& style, LegendMark mark = LegendMark::Box);
  // The legend entries, in drawing order.
  const std::vector<LegendEntry>& legend() const { return legend_; }
  // Axis labels, units included (e.g. 't (s)', 'x (m)').
  void set_labels(const std::string& x_label, const std::string& y_label);
  // Dimensions of the drawn boxes shown on the x and y axes (default 0, 1).
  void set_projection(std::size_t i, std::size_t j);

  // Draws one box.
  void draw_box(const IntervalVector& box, const Style& style = {});
  void draw_boxes(const std::vector<IntervalVector>& boxes, const Style& style = {});
  // Annulus {p : |p - center| in radius}; a disk when lb(radius) <= 0.
  void draw_ring(const Vector& center, const Interval& radius, const Style& style = {});
  // A dot of radius_px pixels at p.
  void draw_point(const Vector& p, double radius_px = 3.0, const Style& style = {"black", "none", 0, 1, ""});
  // A polyline through the points (a polygon if closed).
  void draw_polyline(const std::vector<Vector>& points, const Style& style = {}, bool closed = false);
  // Every leaf of the paving with paving_style (Outside leaves if requested).
  void draw_paving(const Paving& paving, bool show_outside = true);
  // Oriented loops (see contour.h), as polygons in the (x, y) plane of the figure.
  void draw_contour(const std::vector<ContourLoop>& loops, const Style& style = {"none", "black", 1.5, 1, ""});
  // Text at the point p (world coordinates).
  void draw_text(const Vector& p, const std::string& text, double size_px = 12, const std::string& colour = "black");

  // Number of SVG elements drawn so far.
  std::size_t nb_shapes() const { return shapes_.size(); }
  // The SVG document as a string.
  std::string svg() const;
  // Writes svg() to a file; throws Error if it cannot.
  void save(const std::string& path) const;

  // World x -> pixel x of the SVG.
  double px(double x) const;
  // World y -> pixel y within the plot's group, which the SVG shifts down by plot_top() - py(ub(view[1])).
  double py(double y) const;
  // Pixel y in the SVG of the top of the plot area (below the title lines and the note).
  double plot_top() const;
  // Width of the whole SVG, in pixels.
  double svg_width() const;
  // Height of the whole SVG, in pixels: title, note, plot, axis label and legend.
  double svg_height() const;

 private:
  std::string style_attributes(const Style& s) const;
  void push(std::string shape, const Style& style, LegendMark mark);
  void check_point(const Vector& p, const char* where) const;

  Interval vx_, vy_;
  double width_, height_;
  std::size_t dim_x_ = 0, dim_y_ = 1;
  std::string title_, note_, x_label_, y_label_;
  std::vector<LegendEntry> legend_;
  std::vector<std::string> shapes_;  // SVG elements, in drawing order
};

// Escapes &, <, >, " and ' for XML text and attributes.
std::string xml_escape(const std::string& text);

}  // namespace sillage

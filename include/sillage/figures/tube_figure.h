#pragma once
// SVG figures of tubes (thesis Figs. 3.4-3.12), drawn with Figure:
//  - a scalar tube over time: one rectangle [t_k, t_{k+1}] x [x](k) per slice,
//    optional gates, optional true trajectory;
//  - the 2-D projection [x_i](.) x [x_j](.) of a tube vector: one box per
//    slice, the initial and final gates highlighted, optional true path.
// Slices smaller than a pixel are aggregated into their hull (consecutive
// slices, as long as the hull stays within `merge_px` pixels of each slice of
// the group), so 10^5 slices give a few hundred shapes. The drawn shapes
// always cover every slice: the display is rigorous, only coarser. Slices are
// drawn at least min_px pixels thick, so that a thin tube still shows around
// the line of the truth, which is drawn thin and on top. In 2-D, larger boxes
// are drawn first, so that the smaller ones stay visible over them, and the
// gates are translucent: a wide final gate does not hide the tube below it.
#include <cstddef>
#include <string>
#include <vector>

#include "sillage/figures/figure.h"
#include "sillage/figures/thickness_figure.h"
#include "sillage/tube/trajectory.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

// Styles of tube figures and the aggregation tolerance merge_px.
struct TubeStyle {
  // Style of the slice rectangles (its label names the tube in the legend).
  Style slices{"#a9cdf2", "#2a6aa8", 0.4, 1.0, "slice", "tube"};
  // Style of the gates.
  Style gates{"#1f3f66", "none", 0.0, 1.0, "gate", ""};
  // Style of the true trajectory: a thin line, drawn over the tube.
  Style truth{"none", "#d62728", 1.0, 1.0, "truth", "truth"};
  Style initial{"#e1bee7", "#7b1fa2", 1.5, 0.3, "initial", "initial box"};  // gate 0 (2-D figures): purple, not the truth's red
  Style final{"#a5d6a7", "#2e7d32", 1.5, 0.3, "final", "final box"};       // gate N (2-D figures)
  // Style of the landmarks of a map: dots, distinct from the truth's line.
  Style landmarks{"#ffd54f", "#000000", 1.2, 1.0, "landmark", "landmarks"};
  // Radius of the landmark dots, in pixels.
  double landmark_px = 5.0;
  // Least thickness of a drawn slice, in pixels (>= 0; display only: the drawing still covers the slice).
  double min_px = 4.0;
  // Scalar figures: gates as 1-px vertical bars (only if slices are at least
  // 4 px wide on average; else they would just paint the tube).
  bool show_gates = false;
  // Overdraw allowed by the aggregation, in pixels (>= 0; 0 merges only
  // consecutive slices that are identical or share a pixel column).
  double merge_px = 1.0;
};

// Draws the tube in the (t, x) plane of the figure (default projection).
// `truth`, if given, is drawn as a polyline sampled at the pixel resolution
// over its domain within [t_0, t_N]. Returns the number of slice rectangles.
std::size_t draw_tube(Figure& fig, const Tube& x, const TubeStyle& style = {}, const Trajectory* truth = nullptr);

// Draws [x_i](k) x [x_j](k) for every slice as 2-D boxes (x_i horizontally),
// so the figure must keep its default projection (0, 1). Gates 0 and N are
// highlighted (drawn at least 3 px wide so that a point is visible). The true
// path (truth_i(t), truth_j(t)) is drawn if both trajectories are given.
// Returns the number of slice boxes drawn. Error if i or j is out of range or i == j.
std::size_t draw_tube_vector_2d(Figure& fig, const TubeVector& x, std::size_t i, std::size_t j,
                                const TubeStyle& style = {}, const Trajectory* truth_i = nullptr,
                                const Trajectory* truth_j = nullptr);

// A figure over [t_0, t_N] x the tube's codomain (with a margin), the tube
// drawn; the y axis is labelled `name`, the variable and its unit (e.g.
// "v (m/s)"). An unbounded codomain is clipped to a finite window around the
// bounded bounds, and the note says so.
Figure tube_figure(const Tube& x, const std::string& title = "", const TubeStyle& style = {},
                   const Trajectory* truth = nullptr, double width_px = 600, double height_px = 300,
                   const std::string& name = "x");

// The window of a map of x_i x x_j, and a note on it.
struct MapView {
  // The window: bounded, non-degenerate.
  IntervalVector window;
  // What the reader should know (e.g. how far the tube reaches beyond the window); may be empty.
  std::string note;
};

// The window of a map: the tube's finite window (clipped like tube_figure)
// grown to hold the truth (sampled) and the landmarks. When the tube is more
// than `zoom` times wider than the truth and the landmarks along an axis (a
// dead-reckoning tube kilometres wide around a walk of a hundred metres),
// the window frames the truth and the landmarks instead, and the note says
// how far the tube reaches; names label the two components in the note.
MapView map_view(const TubeVector& x, std::size_t i, std::size_t j, const std::string& name_i,
                 const std::string& name_j, const Trajectory* truth_i = nullptr, const Trajectory* truth_j = nullptr,
                 const std::vector<Vector>* landmarks = nullptr, double zoom = 5);

// An empty map of x_i × x_j: the map_view window (aspect ratio kept), the
// title, map_view's note, the axes labelled name_i and name_j (x1, x2...,
// x_{i+1} and x_{j+1}, when empty). tube_vector_figure and
// map_envelope_figure draw on it.
Figure map_frame(const TubeVector& x, std::size_t i, std::size_t j, const std::string& title,
                 const Trajectory* truth_i, const Trajectory* truth_j, double width_px,
                 const std::vector<Vector>* landmarks, const std::string& name_i, const std::string& name_j);

// A figure of the map_view window (aspect ratio kept), with the projection
// drawn by draw_tube_vector_2d and the landmarks (if given, 2-D points) as
// dots on top; a legend names what is drawn. The axes are labelled name_i
// and name_j (the variables and units, e.g. "x (m)"); x1, x2... (x_{i+1},
// x_{j+1}) when empty.
Figure tube_vector_figure(const TubeVector& x, std::size_t i = 0, std::size_t j = 1, const std::string& title = "",
                          const TubeStyle& style = {}, const Trajectory* truth_i = nullptr,
                          const Trajectory* truth_j = nullptr, double width_px = 600,
                          const std::vector<Vector>* landmarks = nullptr, const std::string& name_i = "",
                          const std::string& name_j = "");

// A finite window containing every finite bound of `xs` with a 5 % margin
// (non-degenerate; [-1, 1] if no bound is finite). `clipped` is set when some
// interval is unbounded.
Interval finite_window(const std::vector<Interval>& xs, bool& clipped);

}  // namespace sillage

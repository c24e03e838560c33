#pragma once
// SVG map of a mission and its loops (thesis Figs. 6.12, 6.15): the
// trajectory (the true path as a polyline and/or a 2-D position tube, slice
// boxes), and each detection projected on the map, coloured by status
// (loop_style.h: proven orange, unproven black, partial grey):
//  - as its map box, the hull of the positions p([t1]) ∪ p([t2])
//    (Loop::map_box): guaranteed, but wide after a long drift;
//  - and, when the times of the path are given, as the thesis draws it: the
//    two pieces of the path over [t1] and over [t2], in bold.
#include <cstddef>
#include <string>
#include <vector>

#include "sillage/figures/figure.h"
#include "sillage/figures/loop_style.h"
#include "sillage/loops/path_crossings.h"
#include "sillage/loops/tplane.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

// What the map needs of a detection.
struct MapLoop {
  IntervalVector map_box;  // 2-D; an empty box is not drawn
  LoopStatus status = LoopStatus::Partial;
  IntervalVector t_box = IntervalVector::empty(2);  // [t1] x [t2], for the projections on the path
};

// The detections of the TPlane (their map boxes are set by compute_proofs).
std::vector<MapLoop> map_loops(const TPlane& tplane);

// Drawing options of loops_map_figure.
struct LoopsMapOptions {
  // Draw the partial detections too.
  bool show_partial = true;
  bool boxes = true;        // draw the map boxes
  bool projections = true;  // draw the path over [t1] and [t2] (needs the path times)
  double path_px = 0.5;     // the path polyline keeps a point when it moved this far (pixels) from the last kept
  double crossing_px = 2.5; // radius of the true crossing points
};

struct LoopsMapCounts {
  std::size_t tube_boxes = 0, path_points = 0, loops = 0, projections = 0, crossings = 0;
};

// Draws onto fig (default projection): the position tube (if given), the
// path (if given, points (x, y), at the increasing times path_times if
// given), the loops (partial, unproven, then proven on top: map boxes, then
// projections, one polyline per time interval) and the crossings (their
// points (x, y)). Error if an option is not > 0 or the times are not
// increasing, DimensionError if a point or box is not 2-D or the path and
// its times differ in size.
LoopsMapCounts draw_loops_map(Figure& fig, const std::vector<MapLoop>& loops, const std::vector<Vector>* path = nullptr,
                              const std::vector<double>* path_times = nullptr, const TubeVector* positions = nullptr,
                              const std::vector<PathCrossing>* crossings = nullptr,
                              const LoopsMapOptions& options = {});

// A figure framing the path, the bounded parts of the position tube and the
// loop boxes (5 % margin, aspect ratio kept), axes labelled x_label and
// y_label (the position's names and unit), with a legend.
Figure loops_map_figure(const TPlane& tplane, const std::vector<Vector>* path = nullptr,
                        const std::vector<double>* path_times = nullptr, const TubeVector* positions = nullptr,
                        const std::vector<PathCrossing>* crossings = nullptr, const std::string& title = "",
                        double width_px = 700, const LoopsMapOptions& options = {},
                        const std::string& x_label = "x (m)", const std::string& y_label = "y (m)");
Figure loops_map_figure(const std::vector<MapLoop>& loops, const std::vector<Vector>* path = nullptr,
                        const std::vector<double>* path_times = nullptr, const TubeVector* positions = nullptr,
                        const std::vector<PathCrossing>* crossings = nullptr, const std::string& title = "",
                        double width_px = 700, const LoopsMapOptions& options = {},
                        const std::string& x_label = "x (m)", const std::string& y_label = "y (m)");

}  // namespace sillage

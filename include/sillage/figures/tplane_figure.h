#pragma once
// SVG figure of a t-plane (thesis Figs. 6.3-6.4, 6.13, 6.16-6.17): the
// paving of the loop set 𝕋 (inner green, boundary yellow, outside blue, as
// style.h), each detection Ω_i outlined and filled by its status
// (loop_style.h: proven orange, unproven black, partial grey), the
// diagonal t1 = t2, and optionally the true crossings (t1*, t2*) as points.
//
// A t-plane of a long mission holds components of a few pixels made of
// sub-pixel leaves: leaves smaller than min_leaf_px (both sides) are not
// drawn one by one, the outline of their component covers them (so the
// file stays small); components smaller than marker_px get a disk marker so
// that they show. Zoom by giving a view: then the leaves appear.
#include <cstddef>
#include <string>
#include <vector>

#include "sillage/figures/figure.h"
#include "sillage/figures/loop_style.h"
#include "sillage/loops/path_crossings.h"
#include "sillage/loops/tplane.h"

namespace sillage {

// What the figure needs of a detection (TPlane's Loop, or any union of boxes).
struct DetectionShape {
  std::vector<IntervalVector> boxes;  // 2-D, bounded, disjoint interiors
  LoopStatus status = LoopStatus::Partial;
};

// One shape per detection, then one per proven piece of a split detection.
std::vector<DetectionShape> detection_shapes(const TPlane& tplane);

// Drawing options of tplane_figure.
struct TPlaneFigureOptions {
  double min_leaf_px = 2.0;  // leaves smaller than this on both sides are covered by their component
  double marker_px = 3.0;    // radius of the marker of components smaller than 2 * marker_px
  double crossing_px = 2.0;  // radius of the true-crossing points
  // Draw the diagonal t1 = t2.
  bool show_diagonal = true;
};

struct TPlaneFigureCounts {
  std::size_t leaves = 0, components = 0, markers = 0, crossings = 0;
};

// Draws into fig, whose window is `view` (the projection (t1, t2)): the
// paving's domain in the outside colour, its Inner/Boundary leaves, the
// detections, the diagonal and the crossings that fall in the view.
// Error if view is not a bounded 2-D box or an option is not > 0.
TPlaneFigureCounts draw_tplane(Figure& fig, const IntervalVector& view, const Paving& paving,
                               const std::vector<DetectionShape>& detections,
                               const std::vector<PathCrossing>* crossings = nullptr,
                               const TPlaneFigureOptions& options = {});

// A figure of the whole t-plane (or of `view` if given, e.g. a zoom on a few
// components), axes t1 and t2.
Figure tplane_figure(const TPlane& tplane, const std::vector<PathCrossing>* crossings = nullptr,
                     const std::string& title = "", const IntervalVector* view = nullptr, double width_px = 600,
                     const TPlaneFigureOptions& options = {});

}  // namespace sillage

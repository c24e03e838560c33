#pragma once
// A map of a tube vector as its envelope: thousands of slice boxes
// [x_i](k) × [x_j](k) drawn one by one overlap into a blob where no single box
// reads; the envelope draws their union as one outlined area, with a few boxes
// (evenly spaced in time) over it to show how large one box is. The union is
// covered on a grid of cells (every cell a box touches is in), so the drawn
// area holds every slice box within the window: a display as rigorous as the
// boxes', only coarser (by one cell at most).
#include <cstddef>
#include <string>
#include <vector>

#include "sillage/figures/figure.h"
#include "sillage/figures/tube_figure.h"
#include "sillage/paving/contour.h"

namespace sillage {

// The outline of the union of the slice boxes [x_i](k) × [x_j](k) within `window` (2-D, bounded),
// covered by a grid of `cells` cells across its width (square-ish cells): loops as contour()
// gives them (outer loops, then holes). Empty slices are left out; a box is clipped to the window.
// DimensionError if i or j is out of range or i == j; Error if cells is 0 or the window unbounded.
std::vector<ContourLoop> map_envelope(const TubeVector& x, std::size_t i, std::size_t j,
                                      const IntervalVector& window, std::size_t cells = 300);

// A map (map_view's window, as tube_vector_figure) of the envelope, filled and outlined, with
// `boxes` slice boxes evenly spaced in time drawn over it, the initial and final gates, the truth
// path (if truth_i and truth_j are given) and the landmarks; the axes labelled name_i and name_j.
Figure map_envelope_figure(const TubeVector& x, std::size_t i = 0, std::size_t j = 1, const std::string& title = "",
                           const TubeStyle& style = {}, const Trajectory* truth_i = nullptr,
                           const Trajectory* truth_j = nullptr, double width_px = 600,
                           const std::vector<Vector>* landmarks = nullptr, const std::string& name_i = "",
                           const std::string& name_j = "", std::size_t boxes = 8);

}  // namespace sillage

#pragma once
// Self-crossings of a sampled planar path: the true loops λ* of thesis
// (6.20), counted from a known path (ground truth or a simulated one) to
// check what the t-plane detects and proves.
//
// The path is the polyline through (t_k, x_k, y_k) (times strictly
// increasing). A crossing is a proper intersection of two non-adjacent
// segments, reported with the times at the crossing point on each segment
// (linear interpolation), t1 < t2, and the crossing point. Touching without
// crossing (collinear overlap, a vertex on a segment) is not a crossing.
//
// Which pairs cross is decided exactly: the orientation predicates use a
// floating-point filter with a proven error bound and fall back to an exact
// sum of the products (error-free transformations) when the filter cannot
// tell. Exactness holds when every non-zero coordinate has a magnitude in
// [2^-480, 1e150] (the products' rounding errors are then representable);
// larger values are rejected, tinier non-zero ones may only blur the sign of
// a near-degenerate orientation. The crossing times and points are then
// computed in floating point: a reference for tests and examples, not an
// enclosure.
//
// Cost: O(n + k + c log c) with a uniform grid of cells about as large as
// the median segment, at most ~2 cells per segment (k: segment pairs
// sharing a cell, c: crossings): linear in practice, about 0.1 s for 10^6
// points of a survey path (bench_loops). Many segments in one cell (a path
// that dwells on a spot for thousands of samples) degrade it towards O(m^2)
// in that cell; zero-length segments are skipped.
#include <cstddef>
#include <vector>

namespace sillage {

struct PathCrossing {
  double t1 = 0.0, t2 = 0.0;  // the two passage times, t1 < t2
  double x = 0.0, y = 0.0;    // crossing point
  // The crossing segments: [k, k+1] holds t1 for k = segment1, t2 for
  // k = segment2 (segment1 + 1 < segment2).
  std::size_t segment1 = 0, segment2 = 0;
};

// Crossings ordered by (t1, t2). Error if the sizes differ, a value is not
// finite (or a coordinate exceeds 1e150 in magnitude) or the times are not
// strictly increasing; the message gives the index.
std::vector<PathCrossing> self_crossings(const std::vector<double>& t, const std::vector<double>& x,
                                         const std::vector<double>& y);

}  // namespace sillage

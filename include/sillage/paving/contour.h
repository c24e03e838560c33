#pragma once
// Oriented boundary of a 2-D union of boxes: the input of the topological
// degree test of thesis 6.3 (getContour of Alg. 7, the edges [b]_k of (6.14)).
//
// The boundary of the union is returned as closed loops of oriented edges,
// each edge leaving the union on its LEFT: outer boundaries run
// counter-clockwise, boundaries of holes clockwise. Consecutive collinear
// edges are merged into maximal segments.
//
// The union is a closed set: where two of its boxes meet only at a corner
// (a pinch point), it is connected through that point and its complement is
// not. Loops follow this: at a pinch the loop turns right, into the other
// box, so a component (in the sense of component.h) has exactly one outer
// loop, plus one clockwise loop per hole (bounded part of the complement).
// Such a loop may pass twice through a pinch point (it touches itself, it
// never crosses itself). The degree of thesis Alg. 8 is the sum over loops.
//
// Boxes must be 2-D, bounded, with pairwise disjoint interiors (the leaves of
// a paving). Boxes of zero area are ignored (they have no interior to bound;
// a component joined only through such a box gets one outer loop per part).
// All vertices are box bounds, so the contour is exact (no rounding).
#include <cstddef>
#include <string>
#include <vector>

#include "sillage/budget.h"
#include "sillage/interval/interval_vector.h"

namespace sillage {

struct Point2 {
  double x = 0.0;
  double y = 0.0;
  bool operator==(const Point2& o) const { return x == o.x && y == o.y; }
  bool operator!=(const Point2& o) const { return !(*this == o); }
};

// An oriented, axis-aligned edge from a to b; the enclosed region is on its left.
struct ContourEdge {
  // The start point a and the end point b (x, y).
  Point2 a, b;
  // The edge as a degenerate box [b] (one zero-width component).
  IntervalVector box() const;
  // The Euclidean length of the edge.
  double length() const;
};

// A closed loop: edges[k].b == edges[k+1].a and edges.back().b == edges.front().a.
// It starts at its lexicographically smallest vertex (smallest x, then y).
struct ContourLoop {
  // The oriented edges, in order around the loop.
  std::vector<ContourEdge> edges;
  bool is_hole = false;  // clockwise: the loop bounds a hole of the union
  std::vector<Point2> vertices() const;  // the start points of the edges
  // The perimeter of the loop.
  double length() const;
  std::string str() const;
};

// Loops of the boundary of the union of `boxes`: outer loops first, then
// holes, each group ordered by start vertex. Throws DimensionError for
// non-2-D boxes, Error for unbounded or overlapping boxes. Cancelled once
// `cancel` is (checked every 1024 boxes and edges: 10^5 boxes take tens of
// milliseconds).
std::vector<ContourLoop> contour(const std::vector<IntervalVector>& boxes, const CancelToken& cancel = {});

}  // namespace sillage

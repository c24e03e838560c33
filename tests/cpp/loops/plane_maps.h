#pragma once
// Test helpers for the zero tests of thesis ch. 6: analytic maps of the plane
// as inclusion functions, boxes, and a brute-force winding number computed
// from point values only (an independent reference for the degree).
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <vector>

#include "sillage/loops/plane_function.h"
#include "sillage/paving/contour.h"

namespace sillage::test {

inline IntervalVector box(double a, double b, double c, double d) { return {Interval(a, b), Interval(c, d)}; }

// Squares, tight for intervals (sqr knows x * x >= 0).
inline double sq(double x) { return x * x; }
inline Interval sq(const Interval& x) { return sqr(x); }

// A map written once for doubles and intervals, map(x, y) -> pair {f1, f2}:
// its interval form is an inclusion function of its double form.
template <class F>
PlaneFunction interval_map(F map) {
  return [map](const IntervalVector& t) {
    auto [u, v] = map(t[0], t[1]);
    return IntervalVector{Interval(u), Interval(v)};
  };
}

using PointMap = std::function<std::pair<double, double>(double, double)>;

template <class F>
PointMap point_map(F map) {
  return [map](double x, double y) {
    auto [u, v] = map(x, y);
    return std::pair<double, double>{u, v};
  };
}

// Winding number of g around 0 along the loops, by adaptive sampling of the
// edges: each step turns by less than 0.2 rad (an edge where g nearly
// vanishes is sampled down to 1e-12). Returns a real number, an integer up
// to rounding when the sampling is fine enough.
inline double sampled_winding(const std::vector<ContourLoop>& loops, const PointMap& g) {
  double total = 0;
  std::function<void(double, double, double, double, int)> walk = [&](double x0, double y0, double x1, double y1,
                                                                       int depth) {
    const auto [u0, v0] = g(x0, y0);
    const auto [u1, v1] = g(x1, y1);
    const double turn = std::atan2(u0 * v1 - v0 * u1, u0 * u1 + v0 * v1);
    if (std::abs(turn) > 0.2 && depth < 60) {
      const double xm = 0.5 * (x0 + x1), ym = 0.5 * (y0 + y1);
      walk(x0, y0, xm, ym, depth + 1);
      walk(xm, ym, x1, y1, depth + 1);
    } else {
      total += turn;
    }
  };
  for (const auto& loop : loops) {
    for (const auto& e : loop.edges) {
      const int n = 64;
      for (int i = 0; i < n; ++i) {
        const double s0 = double(i) / n, s1 = double(i + 1) / n;
        walk(e.a.x + s0 * (e.b.x - e.a.x), e.a.y + s0 * (e.b.y - e.a.y), e.a.x + s1 * (e.b.x - e.a.x),
             e.a.y + s1 * (e.b.y - e.a.y), 0);
      }
    }
  }
  return total / (2 * std::numbers::pi);
}

// A random union of cells of an n x n grid over [lo, hi]^2 (at least one cell).
inline std::vector<IntervalVector> random_cells(std::mt19937& rng, int n, double lo, double hi, double keep) {
  std::bernoulli_distribution pick(keep);
  std::vector<IntervalVector> cells;
  const double h = (hi - lo) / n;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      if (pick(rng)) cells.push_back(box(lo + i * h, lo + (i + 1) * h, lo + j * h, lo + (j + 1) * h));
    }
  }
  if (cells.empty()) cells.push_back(box(lo, lo + h, lo, lo + h));
  return cells;
}

// The same loop run backwards (the region on its right: degree negated).
inline ContourLoop reversed(const ContourLoop& loop) {
  ContourLoop r;
  r.is_hole = !loop.is_hole;
  for (auto it = loop.edges.rbegin(); it != loop.edges.rend(); ++it) r.edges.push_back({it->b, it->a});
  return r;
}

// The same loop started at its k-th edge.
inline ContourLoop rotated(const ContourLoop& loop, std::size_t k) {
  ContourLoop r = loop;
  std::rotate(r.edges.begin(), r.edges.begin() + static_cast<std::ptrdiff_t>(k % loop.edges.size()), r.edges.end());
  return r;
}

}  // namespace sillage::test

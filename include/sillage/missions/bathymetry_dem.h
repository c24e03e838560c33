#pragma once
// BathymetryDem: a digital elevation model of the seabed (thesis Fig. 7.20),
// node depths on a regular grid (metres, positive down, below the chart datum),
// the seabed between nodes being their bilinear interpolation. It is an
// inclusion function: every evaluation encloses the exact value, rounding
// included.
//  - operator()(x, y): the bilinear value at a point, outward-rounded;
//  - eval(box): the exact range of the bilinear surface over a box (its
//    extremes over each box ∩ cell rectangle lie at the rectangle's corners:
//    the grid nodes inside the box, the box corners and the crossings of the
//    box edges with the grid lines), in O(perimeter + log) with a min/max
//    pyramid over the nodes;
//  - eval_cells(box): the hull of the nodes of every cell the box touches
//    (looser, O(log) per pyramid block).
// A box (or point) not inside the map gives the whole real line: the seabed
// is unknown there.
#include <cstddef>
#include <string>
#include <vector>

#include "sillage/interval/interval.h"
#include "sillage/interval/interval_vector.h"

namespace sillage {

class BathymetryDem {
 public:
  // Nodes (x0 + i h, y0 + j h), i < nx, j < ny, depth depths[j * nx + i].
  // Error if nx, ny < 2, h <= 0, a value is not finite, the sizes differ, or a
  // node coordinate is not exactly representable (choose h and the origin so,
  // e.g. integers or halves, so that cell indices are exact).
  BathymetryDem(double x0, double y0, double h, std::size_t nx, std::size_t ny, std::vector<double> depths);

  // Number of node columns.
  std::size_t nx() const { return nx_; }
  // Number of node rows.
  std::size_t ny() const { return ny_; }
  // Grid step (m).
  double cell_size() const { return h_; }
  // x of node column 0.
  double x0() const { return x0_; }
  // y of node row 0.
  double y0() const { return y0_; }
  IntervalVector domain() const;  // [x0, x0 + (nx-1) h] x [y0, y0 + (ny-1) h]
  double node(std::size_t i, std::size_t j) const;  // OutOfRangeError outside
  // The node depths, row by row (node (i, j) at j·nx + i); an (ny, nx) array in Python.
  const std::vector<double>& depths() const { return z_; }
  // Smallest node depth.
  double min_depth() const;
  // Largest node depth.
  double max_depth() const;

  // The bilinear depth at (x, y), an enclosing Interval.
  Interval operator()(double x, double y) const;
  // The exact range of the bilinear seabed over a box (x, y), outward-rounded.
  Interval eval(const IntervalVector& box) const;
  // The hull of the nodes of every cell the box touches (looser, cheaper).
  Interval eval_cells(const IntervalVector& box) const;

 private:
  double at(std::size_t i, std::size_t j) const { return z_[j * nx_ + i]; }
  // Min/max of the nodes with i0 <= i <= i1, j0 <= j <= j1 (non-empty range).
  Interval node_range(std::size_t i0, std::size_t i1, std::size_t j0, std::size_t j1) const;
  void range_rec(std::size_t level, std::size_t bi, std::size_t bj, std::size_t i0, std::size_t i1, std::size_t j0,
                 std::size_t j1, double& lo, double& hi) const;
  // Bilinear value at a point known to be in cell (i, j), as an Interval.
  Interval bilinear(std::size_t i, std::size_t j, double x, double y) const;
  // Index of the cell whose x-range holds x (clamped to the last cell).
  std::size_t cell_x(double x) const;
  std::size_t cell_y(double y) const;
  bool inside(const IntervalVector& box, const char* where) const;

  double x0_, y0_, h_;
  std::size_t nx_, ny_;
  std::vector<double> z_;
  // pyramid_[l]: min and max over blocks of 2^l x 2^l nodes, side_[l] blocks a row.
  std::vector<std::vector<double>> pmin_, pmax_;
  std::vector<std::size_t> side_;
};

std::string repr(const BathymetryDem& dem);

}  // namespace sillage

#include "sillage/missions/bathymetry_dem.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sillage/error.h"

namespace sillage {

namespace {
constexpr const char* kWhere = "BathymetryDem";
}

BathymetryDem::BathymetryDem(double x0, double y0, double h, std::size_t nx, std::size_t ny,
                             std::vector<double> depths)
    : x0_(x0), y0_(y0), h_(h), nx_(nx), ny_(ny), z_(std::move(depths)) {
  if (nx < 2 || ny < 2) throw Error(std::string(kWhere) + ": at least 2 x 2 nodes needed, got " +
                                    std::to_string(nx) + " x " + std::to_string(ny));
  if (!(h > 0) || !std::isfinite(h) || !std::isfinite(x0) || !std::isfinite(y0))
    throw Error(std::string(kWhere) + ": the cell size must be > 0 and the origin finite");
  if (z_.size() != nx * ny)
    throw DimensionError(std::string(kWhere) + ": " + std::to_string(nx * ny) + " depths expected (nx * ny), got " +
                         std::to_string(z_.size()));
  for (std::size_t k = 0; k < z_.size(); ++k)
    if (!std::isfinite(z_[k]))
      throw Error(std::string(kWhere) + ": depth of node (" + std::to_string(k % nx) + ", " + std::to_string(k / nx) +
                  ") is not finite");
  // Node coordinates are used as exact numbers below: check that they are.
  for (std::size_t i = 0; i < std::max(nx, ny); ++i) {
    const Interval c = Interval(static_cast<double>(i)) * Interval(h);
    if (!(c.lb() == c.ub()) || (i < nx && (Interval(x0) + c).diam() != 0) || (i < ny && (Interval(y0) + c).diam() != 0))
      throw Error(std::string(kWhere) + ": node coordinate origin + " + std::to_string(i) +
                  " * h is not exactly representable; choose h and the origin as integers or dyadic fractions");
  }
  // Min/max pyramid: level 0 = nodes, each level halves both sides.
  std::size_t wx = nx, wy = ny;
  pmin_.push_back(z_), pmax_.push_back(z_), side_.push_back(wx);
  while (wx > 1 || wy > 1) {
    const std::size_t px = wx, py = wy;
    wx = (wx + 1) / 2, wy = (wy + 1) / 2;
    std::vector<double> mn(wx * wy, INFINITY), mx(wx * wy, -INFINITY);
    const auto& lmn = pmin_.back();
    const auto& lmx = pmax_.back();
    for (std::size_t j = 0; j < py; ++j)
      for (std::size_t i = 0; i < px; ++i) {
        const std::size_t b = (j / 2) * wx + i / 2;
        mn[b] = std::min(mn[b], lmn[j * px + i]);
        mx[b] = std::max(mx[b], lmx[j * px + i]);
      }
    pmin_.push_back(std::move(mn)), pmax_.push_back(std::move(mx)), side_.push_back(wx);
  }
}

IntervalVector BathymetryDem::domain() const {
  return {Interval(x0_, x0_ + static_cast<double>(nx_ - 1) * h_), Interval(y0_, y0_ + static_cast<double>(ny_ - 1) * h_)};
}

double BathymetryDem::node(std::size_t i, std::size_t j) const {
  if (i >= nx_ || j >= ny_)
    throw OutOfRangeError(std::string(kWhere) + ".node: (" + std::to_string(i) + ", " + std::to_string(j) +
                          ") outside the " + std::to_string(nx_) + " x " + std::to_string(ny_) + " grid");
  return at(i, j);
}

double BathymetryDem::min_depth() const { return pmin_.back()[0]; }
double BathymetryDem::max_depth() const { return pmax_.back()[0]; }

void BathymetryDem::range_rec(std::size_t level, std::size_t bi, std::size_t bj, std::size_t i0, std::size_t i1,
                              std::size_t j0, std::size_t j1, double& lo, double& hi) const {
  const std::size_t s = std::size_t(1) << level;
  const std::size_t a0 = bi * s, a1 = std::min(nx_ - 1, a0 + s - 1), c0 = bj * s, c1 = std::min(ny_ - 1, c0 + s - 1);
  if (a0 > i1 || a1 < i0 || c0 > j1 || c1 < j0) return;
  const double mn = pmin_[level][bj * side_[level] + bi], mx = pmax_[level][bj * side_[level] + bi];
  if (mn >= lo && mx <= hi) return;  // nothing to learn here
  if ((a0 >= i0 && a1 <= i1 && c0 >= j0 && c1 <= j1) || level == 0) {
    lo = std::min(lo, mn), hi = std::max(hi, mx);
    return;
  }
  const std::size_t w = side_[level - 1], hgt = pmin_[level - 1].size() / w;
  for (std::size_t dj = 0; dj < 2; ++dj)
    for (std::size_t di = 0; di < 2; ++di)
      if (2 * bi + di < w && 2 * bj + dj < hgt) range_rec(level - 1, 2 * bi + di, 2 * bj + dj, i0, i1, j0, j1, lo, hi);
}

Interval BathymetryDem::node_range(std::size_t i0, std::size_t i1, std::size_t j0, std::size_t j1) const {
  double lo = INFINITY, hi = -INFINITY;
  if ((i1 - i0 + 1) * (j1 - j0 + 1) <= 64) {  // small: a direct scan beats the descent
    for (std::size_t j = j0; j <= j1; ++j)
      for (std::size_t i = i0; i <= i1; ++i) lo = std::min(lo, at(i, j)), hi = std::max(hi, at(i, j));
    return Interval(lo, hi);
  }
  range_rec(pmin_.size() - 1, 0, 0, i0, i1, j0, j1, lo, hi);
  return Interval(lo, hi);
}

std::size_t BathymetryDem::cell_x(double x) const {
  // floor((x - x0)/h) corrected with the exact node coordinates.
  auto i = static_cast<std::ptrdiff_t>(std::floor((x - x0_) / h_));
  const auto last = static_cast<std::ptrdiff_t>(nx_) - 2;
  i = std::clamp<std::ptrdiff_t>(i, 0, last);
  while (i > 0 && x0_ + static_cast<double>(i) * h_ > x) --i;
  while (i < last && x0_ + static_cast<double>(i + 1) * h_ <= x) ++i;
  return static_cast<std::size_t>(i);
}

std::size_t BathymetryDem::cell_y(double y) const {
  auto j = static_cast<std::ptrdiff_t>(std::floor((y - y0_) / h_));
  const auto last = static_cast<std::ptrdiff_t>(ny_) - 2;
  j = std::clamp<std::ptrdiff_t>(j, 0, last);
  while (j > 0 && y0_ + static_cast<double>(j) * h_ > y) --j;
  while (j < last && y0_ + static_cast<double>(j + 1) * h_ <= y) ++j;
  return static_cast<std::size_t>(j);
}

Interval BathymetryDem::bilinear(std::size_t i, std::size_t j, double x, double y) const {
  const double f00 = at(i, j), f10 = at(i + 1, j), f01 = at(i, j + 1), f11 = at(i + 1, j + 1);
  const Interval u = (Interval(x) - Interval(x0_ + static_cast<double>(i) * h_)) / Interval(h_);
  const Interval v = (Interval(y) - Interval(y0_ + static_cast<double>(j) * h_)) / Interval(h_);
  const Interval a = Interval(f00), dx = Interval(f10) - a, dy = Interval(f01) - a;
  const Interval dxy = Interval(f11) - Interval(f10) - Interval(f01) + a;
  // Inside a cell the bilinear surface lies between its corner values.
  const Interval corners(std::min({f00, f10, f01, f11}), std::max({f00, f10, f01, f11}));
  return (a + u * dx + v * dy + u * v * dxy) & corners;
}

bool BathymetryDem::inside(const IntervalVector& box, const char* where) const {
  if (box.size() < 2)
    throw DimensionError(std::string(kWhere) + "." + where + ": a box of at least 2 dimensions (x, y) expected, got " +
                         std::to_string(box.size()));
  const IntervalVector d = domain();
  return box[0].is_subset(d[0]) && box[1].is_subset(d[1]);
}

Interval BathymetryDem::operator()(double x, double y) const {
  if (std::isnan(x) || std::isnan(y)) throw Error(std::string(kWhere) + "(x, y): NaN coordinate");
  const IntervalVector d = domain();
  if (!d[0].contains(x) || !d[1].contains(y)) return Interval();
  return bilinear(cell_x(x), cell_y(y), x, y);
}

Interval BathymetryDem::eval_cells(const IntervalVector& box) const {
  if (!inside(box, "eval_cells")) return box[0].is_empty() || box[1].is_empty() ? Interval::empty() : Interval();
  if (box[0].is_empty() || box[1].is_empty()) return Interval::empty();
  return node_range(cell_x(box[0].lb()), cell_x(box[0].ub()) + 1, cell_y(box[1].lb()), cell_y(box[1].ub()) + 1);
}

Interval BathymetryDem::eval(const IntervalVector& box) const {
  if (!inside(box, "eval")) return box[0].is_empty() || box[1].is_empty() ? Interval::empty() : Interval();
  if (box[0].is_empty() || box[1].is_empty()) return Interval::empty();
  const double xl = box[0].lb(), xu = box[0].ub(), yl = box[1].lb(), yu = box[1].ub();
  // Nodes inside the box: i0..i1, j0..j1 (possibly none).
  const std::size_t cxl = cell_x(xl), cxu = cell_x(xu), cyl = cell_y(yl), cyu = cell_y(yu);
  auto nx_of = [&](std::size_t i) { return x0_ + static_cast<double>(i) * h_; };
  auto ny_of = [&](std::size_t j) { return y0_ + static_cast<double>(j) * h_; };
  const std::size_t i0 = nx_of(cxl) < xl ? cxl + 1 : cxl, i1 = nx_of(cxu + 1) <= xu ? cxu + 1 : cxu;
  const std::size_t j0 = ny_of(cyl) < yl ? cyl + 1 : cyl, j1 = ny_of(cyu + 1) <= yu ? cyu + 1 : cyu;
  Interval r = Interval::empty();
  if (i0 <= i1 && j0 <= j1) r |= node_range(i0, i1, j0, j1);
  // Box corners.
  for (double x : {xl, xu})
    for (double y : {yl, yu}) r |= bilinear(cell_x(x), cell_y(y), x, y);
  // Box edges crossing the grid lines: the surface is linear along a grid line.
  for (double y : {yl, yu}) {
    const std::size_t j = cell_y(y);
    const Interval v = (Interval(y) - Interval(ny_of(j))) / Interval(h_);
    for (std::size_t i = i0; i <= i1 && i < nx_; ++i) {
      const Interval a(at(i, j)), b(at(i, j + 1));
      r |= (a + v * (b - a)) & Interval(std::min(at(i, j), at(i, j + 1)), std::max(at(i, j), at(i, j + 1)));
    }
  }
  for (double x : {xl, xu}) {
    const std::size_t i = cell_x(x);
    const Interval u = (Interval(x) - Interval(nx_of(i))) / Interval(h_);
    for (std::size_t j = j0; j <= j1 && j < ny_; ++j) {
      const Interval a(at(i, j)), b(at(i + 1, j));
      r |= (a + u * (b - a)) & Interval(std::min(at(i, j), at(i + 1, j)), std::max(at(i, j), at(i + 1, j)));
    }
  }
  return r;
}

std::string repr(const BathymetryDem& dem) {
  char buf[256];
  const IntervalVector d = dem.domain();
  std::snprintf(buf, sizeof buf, "BathymetryDem(%zu x %zu nodes, cell %g m, x in [%g, %g], y in [%g, %g], depth in [%.3f, %.3f] m)",
                dem.nx(), dem.ny(), dem.cell_size(), d[0].lb(), d[0].ub(), d[1].lb(), d[1].ub(), dem.min_depth(),
                dem.max_depth());
  return buf;
}

}  // namespace sillage

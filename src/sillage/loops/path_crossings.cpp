#include "sillage/loops/path_crossings.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <tuple>
#include <utility>

#include "sillage/error.h"
#include "sillage/loops/orientation.h"

namespace sillage {

namespace {

constexpr double kMaxCoordinate = 1e150;  // products stay far from overflow

void check_input(const std::vector<double>& t, const std::vector<double>& x, const std::vector<double>& y) {
  if (t.size() != x.size() || t.size() != y.size()) {
    throw DimensionError("self_crossings: t, x, y must have the same size, got " + std::to_string(t.size()) + ", " +
                         std::to_string(x.size()) + ", " + std::to_string(y.size()));
  }
  if (t.size() >= (std::size_t(1) << 31)) {
    throw Error("self_crossings: at most 2^31 - 1 points, got " + std::to_string(t.size()));
  }
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (!std::isfinite(t[k]) || !std::isfinite(x[k]) || !std::isfinite(y[k])) {
      throw Error("self_crossings: point " + std::to_string(k) + " is not finite");
    }
    if (std::fabs(x[k]) > kMaxCoordinate || std::fabs(y[k]) > kMaxCoordinate) {
      throw Error("self_crossings: point " + std::to_string(k) + " has a coordinate beyond 1e150 in magnitude");
    }
    if (k > 0 && !(t[k - 1] < t[k])) {
      throw Error("self_crossings: times must be strictly increasing, t[" + std::to_string(k) + "] = " +
                  number_text(t[k]) + " follows " + number_text(t[k - 1]));
    }
  }
}

// Axis-aligned bounding box of segment [k, k+1]; `falling`: the segment runs
// from (xlo, yhi) to (xhi, ylo), else from (xlo, ylo) to (xhi, yhi).
struct SegmentBox {
  double xlo, xhi, ylo, yhi;
  bool falling;
};

// Segments i < j - 1 cross properly: each one's end points lie strictly on
// both sides of the other's line (exact signs).
bool cross_properly(const std::vector<double>& x, const std::vector<double>& y, std::size_t i, std::size_t j) {
  const double ax = x[i], ay = y[i], bx = x[i + 1], by = y[i + 1];
  const double cx = x[j], cy = y[j], dx = x[j + 1], dy = y[j + 1];
  const int c = detail::orientation_sign(ax, ay, bx, by, cx, cy), d = detail::orientation_sign(ax, ay, bx, by, dx, dy);
  if (c == 0 || d == 0 || c == d) return false;
  const int a = detail::orientation_sign(cx, cy, dx, dy, ax, ay), b = detail::orientation_sign(cx, cy, dx, dy, bx, by);
  return a != 0 && b != 0 && a != b;
}

// Where the proper crossing of segments i and j lies (floating point).
PathCrossing crossing_point(const std::vector<double>& t, const std::vector<double>& x, const std::vector<double>& y,
                            std::size_t i, std::size_t j) {
  // Fraction along each segment from the areas of the triangles on the
  // other segment; long double for a little more accuracy near grazing angles.
  using LD = long double;
  auto area = [&](std::size_t a, std::size_t b, std::size_t c) {
    return (LD(x[b]) - x[a]) * (LD(y[c]) - y[a]) - (LD(y[b]) - y[a]) * (LD(x[c]) - x[a]);
  };
  auto fraction = [](LD p, LD q) {
    const LD f = p / (p - q);  // p and q have opposite exact signs; their rounded values may both vanish
    return f >= 0 && f <= 1 ? f : f > 1 ? LD(1) : f < 0 ? LD(0) : LD(0.5);
  };
  const LD s = fraction(area(j, j + 1, i), area(j, j + 1, i + 1));
  const LD u = fraction(area(i, i + 1, j), area(i, i + 1, j + 1));
  PathCrossing c;
  c.t1 = double(t[i] + s * (LD(t[i + 1]) - t[i]));
  c.t2 = double(t[j] + u * (LD(t[j + 1]) - t[j]));
  c.x = double(x[i] + s * (LD(x[i + 1]) - x[i]));
  c.y = double(y[i] + s * (LD(y[i + 1]) - y[i]));
  c.segment1 = i;
  c.segment2 = j;
  return c;
}

// A uniform grid over the bounding box of the path; each segment is listed
// in every cell its (slightly widened) trace meets, so that two crossing
// segments always share the cell of their crossing point.
class SegmentGrid {
 public:
  SegmentGrid(const std::vector<SegmentBox>& boxes, const std::vector<std::size_t>& segments, double x0, double y0,
              double xspan, double yspan, double cell, double margin)
      : x0_(x0), y0_(y0), cell_(cell), margin_(margin) {
    nx_ = static_cast<std::size_t>(xspan / cell) + 1;
    ny_ = static_cast<std::size_t>(yspan / cell) + 1;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> entries;  // (cell, segment)
    entries.reserve(3 * segments.size());
    for (std::size_t k : segments) {
      visit_cells(boxes[k], [&](std::size_t c) { entries.emplace_back(std::uint32_t(c), std::uint32_t(k)); });
    }
    // Counting sort by cell: offsets_[c] .. offsets_[c+1] index members_.
    offsets_.assign(nx_ * ny_ + 1, 0);
    for (const auto& e : entries) ++offsets_[e.first + 1];
    for (std::size_t c = 0; c < nx_ * ny_; ++c) offsets_[c + 1] += offsets_[c];
    members_.resize(entries.size());
    std::vector<std::size_t> fill(offsets_.begin(), offsets_.end() - 1);
    for (const auto& e : entries) members_[fill[e.first]++] = e.second;
  }

  std::size_t nb_cells() const { return nx_ * ny_; }
  const std::uint32_t* begin(std::size_t c) const { return members_.data() + offsets_[c]; }
  const std::uint32_t* end(std::size_t c) const { return members_.data() + offsets_[c + 1]; }

 private:
  std::size_t column(double x) const { return index(x - x0_, nx_); }
  std::size_t row(double y) const { return index(y - y0_, ny_); }
  std::size_t index(double offset, std::size_t n) const {
    const double k = std::floor(offset / cell_);
    if (!(k > 0)) return 0;
    return std::min(n - 1, static_cast<std::size_t>(k));
  }

  // The cells met by the segment, slab by slab along its longer extent: in a
  // slab, the other coordinate spans at most one cell more than the slope,
  // computed with a margin far above the rounding errors.
  // The range of the minor coordinate of a segment (bounding box [major_lo,
  // major_lo + major_len] x [minor_lo, minor_hi], slope <= 1 in magnitude)
  // over [lo, hi] on its major axis.
  static std::pair<double, double> minor_span(double major_lo, double major_len, double minor_lo, double minor_hi,
                                              bool falling, double lo, double hi) {
    const double len = minor_hi - minor_lo;
    double a = (std::max(lo - major_lo, 0.0) / major_len) * len, b = (std::max(hi - major_lo, 0.0) / major_len) * len;
    a = falling ? minor_hi - a : minor_lo + a;
    b = falling ? minor_hi - b : minor_lo + b;
    double l = std::max(minor_lo, std::min(a, b)), u = std::min(minor_hi, std::max(a, b));
    if (l > u) std::swap(l, u);
    return {l, u};
  }

  template <class F>
  void visit_cells(const SegmentBox& b, F&& f) const {
    const double m = margin_;
    const double w = b.xhi - b.xlo, h = b.yhi - b.ylo;
    if (w >= h) {
      const std::size_t c0 = column(b.xlo - m), c1 = column(b.xhi + m);
      for (std::size_t c = c0; c <= c1; ++c) {
        const double lo = std::max(b.xlo, x0_ + double(c) * cell_), hi = std::min(b.xhi, x0_ + double(c + 1) * cell_);
        double ylo = b.ylo, yhi = b.yhi;
        if (c0 != c1 && w > 0) std::tie(ylo, yhi) = minor_span(b.xlo, w, b.ylo, b.yhi, b.falling, lo, hi);
        for (std::size_t r = row(ylo - m), r1 = row(yhi + m); r <= r1; ++r) f(r * nx_ + c);
      }
    } else {
      const std::size_t r0 = row(b.ylo - m), r1 = row(b.yhi + m);
      for (std::size_t r = r0; r <= r1; ++r) {
        const double lo = std::max(b.ylo, y0_ + double(r) * cell_), hi = std::min(b.yhi, y0_ + double(r + 1) * cell_);
        double xlo = b.xlo, xhi = b.xhi;
        if (r0 != r1) std::tie(xlo, xhi) = minor_span(b.ylo, h, b.xlo, b.xhi, b.falling, lo, hi);
        for (std::size_t c = column(xlo - m), c1 = column(xhi + m); c <= c1; ++c) f(r * nx_ + c);
      }
    }
  }

  double x0_, y0_, cell_, margin_;
  std::size_t nx_ = 1, ny_ = 1;
  std::vector<std::size_t> offsets_;
  std::vector<std::uint32_t> members_;
};

}  // namespace

std::vector<PathCrossing> self_crossings(const std::vector<double>& t, const std::vector<double>& x,
                                         const std::vector<double>& y) {
  check_input(t, x, y);
  const std::size_t n = t.size();
  if (n < 4) return {};  // two non-adjacent segments need four points

  // Segments of non-zero length (a point-like segment crosses nothing properly).
  std::vector<SegmentBox> boxes(n - 1);
  std::vector<std::size_t> segments;
  std::vector<double> lengths;
  segments.reserve(n - 1);
  lengths.reserve(n - 1);
  double xmin = x[0], xmax = x[0], ymin = y[0], ymax = y[0], scale = 0;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const bool falling = (x[k] < x[k + 1]) != (y[k] < y[k + 1]) && x[k] != x[k + 1] && y[k] != y[k + 1];
    boxes[k] = {std::min(x[k], x[k + 1]), std::max(x[k], x[k + 1]), std::min(y[k], y[k + 1]),
                std::max(y[k], y[k + 1]), falling};
    xmin = std::min(xmin, boxes[k].xlo), xmax = std::max(xmax, boxes[k].xhi);
    ymin = std::min(ymin, boxes[k].ylo), ymax = std::max(ymax, boxes[k].yhi);
    if (x[k] != x[k + 1] || y[k] != y[k + 1]) {
      segments.push_back(k);
      lengths.push_back(std::max(boxes[k].xhi - boxes[k].xlo, boxes[k].yhi - boxes[k].ylo));
    }
  }
  if (segments.size() < 2) return {};
  scale = std::max({std::fabs(xmin), std::fabs(xmax), std::fabs(ymin), std::fabs(ymax)});
  const double xspan = xmax - xmin, yspan = ymax - ymin;

  // Cells about the median segment length, but no more than ~2 per segment.
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  const double max_cells = 2.0 * double(segments.size()) + 16.0;
  double cell = std::max(lengths[lengths.size() / 2], std::max(xspan, yspan) / max_cells);
  cell = std::max(cell, std::sqrt(xspan * yspan / max_cells));
  if (!(cell > 0)) cell = 1.0;
  // Widening of the traces: 1 % of a cell, far above the rounding errors of
  // coordinates of magnitude `scale`.
  const double margin = 0.01 * cell + 16 * std::numeric_limits<double>::epsilon() * scale;
  const SegmentGrid grid(boxes, segments, xmin, ymin, xspan, yspan, cell, margin);

  // Candidate pairs per cell, swept by increasing xlo; each crossing pair is
  // found in every cell both segments share, hence the sort and unique.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  std::vector<std::uint32_t> members;
  for (std::size_t c = 0; c < grid.nb_cells(); ++c) {
    if (grid.end(c) - grid.begin(c) < 2) continue;
    members.assign(grid.begin(c), grid.end(c));
    std::sort(members.begin(), members.end(), [&](std::uint32_t a, std::uint32_t b) {
      return boxes[a].xlo < boxes[b].xlo || (boxes[a].xlo == boxes[b].xlo && a < b);
    });
    for (std::size_t a = 0; a < members.size(); ++a) {
      const SegmentBox& ba = boxes[members[a]];
      for (std::size_t b = a + 1; b < members.size() && boxes[members[b]].xlo <= ba.xhi; ++b) {
        const SegmentBox& bb = boxes[members[b]];
        if (bb.ylo > ba.yhi || ba.ylo > bb.yhi) continue;
        const std::uint32_t i = std::min(members[a], members[b]), j = std::max(members[a], members[b]);
        if (j - i < 2) continue;  // adjacent segments share a vertex: never a proper crossing
        if (cross_properly(x, y, i, j)) pairs.emplace_back(i, j);
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());

  std::vector<PathCrossing> crossings;
  crossings.reserve(pairs.size());
  for (const auto& [i, j] : pairs) crossings.push_back(crossing_point(t, x, y, i, j));
  std::sort(crossings.begin(), crossings.end(), [](const PathCrossing& a, const PathCrossing& b) {
    return a.t1 < b.t1 || (a.t1 == b.t1 && (a.t2 < b.t2 || (a.t2 == b.t2 && a.segment1 < b.segment1)));
  });
  return crossings;
}

}  // namespace sillage

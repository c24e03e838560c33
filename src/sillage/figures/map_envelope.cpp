#include "sillage/figures/map_envelope.h"

#include <algorithm>
#include <cmath>

#include "sillage/error.h"

namespace sillage {

namespace {

void check_components(const TubeVector& x, std::size_t i, std::size_t j, const char* where) {
  if (i >= x.size() || j >= x.size() || i == j)
    throw DimensionError(std::string(where) + ": components (" + std::to_string(i) + ", " + std::to_string(j) +
                         ") of a tube vector of size " + std::to_string(x.size()) +
                         " (they must be distinct and in range)");
}

// The cells [lo, hi] (inclusive) of a grid from `origin` with cells of `size` that x touches
// within n cells; false if none.
bool cell_range(const Interval& x, double origin, double size, std::size_t n, std::size_t& lo, std::size_t& hi) {
  const double a = std::floor((x.lb() - origin) / size), b = std::floor((x.ub() - origin) / size);
  if (b < 0 || a >= static_cast<double>(n)) return false;
  lo = a < 0 ? 0 : static_cast<std::size_t>(a);
  hi = b >= static_cast<double>(n) ? n - 1 : static_cast<std::size_t>(b);
  return true;
}

}  // namespace

std::vector<ContourLoop> map_envelope(const TubeVector& x, std::size_t i, std::size_t j, const IntervalVector& window,
                                      std::size_t cells) {
  check_components(x, i, j, "map_envelope");
  if (cells == 0) throw Error("map_envelope: cells must be >= 1");
  if (window.size() != 2 || window.is_empty() || window.is_unbounded() || window[0].diam() <= 0 || window[1].diam() <= 0)
    throw Error("map_envelope: the window must be a bounded 2-D box of positive size, got " + window.str());
  const double cw = window[0].diam() / static_cast<double>(cells);
  // Square cells, unless the window is far taller than wide (at most 4 cells rows per column).
  const std::size_t nx = cells, ny = std::clamp<std::size_t>(
                                        static_cast<std::size_t>(std::ceil(window[1].diam() / cw)), 1, 4 * cells);
  const double ch = window[1].diam() / static_cast<double>(ny);
  const double x0 = window[0].lb(), y0 = window[1].lb();
  std::vector<char> in(nx * ny, 0);
  auto mark = [&](const Interval& a, const Interval& b) {
    if (a.is_empty() || b.is_empty()) return;
    std::size_t ia, ib, ja, jb;
    if (!cell_range(a, x0, cw, nx, ia, ib) || !cell_range(b, y0, ch, ny, ja, jb)) return;
    for (std::size_t r = ja; r <= jb; ++r) std::fill(in.begin() + r * nx + ia, in.begin() + r * nx + ib + 1, 1);
  };
  const auto xi = x[i].slices(), xj = x[j].slices();
  for (std::size_t k = 0; k < xi.size(); ++k) mark(xi[k], xj[k]);
  for (std::size_t k = 0; k <= x.nb_slices(); ++k) mark(x[i].gate(k), x[j].gate(k));
  // One box per run of marked cells in a row: disjoint interiors, as contour() needs.
  std::vector<IntervalVector> runs;
  for (std::size_t r = 0; r < ny; ++r) {
    for (std::size_t c = 0; c < nx;) {
      if (!in[r * nx + c]) {
        ++c;
        continue;
      }
      const std::size_t start = c;
      while (c < nx && in[r * nx + c]) ++c;
      runs.push_back(IntervalVector{Interval(x0 + static_cast<double>(start) * cw, x0 + static_cast<double>(c) * cw),
                                    Interval(y0 + static_cast<double>(r) * ch, y0 + static_cast<double>(r + 1) * ch)});
    }
  }
  return contour(runs);
}

Figure map_envelope_figure(const TubeVector& x, std::size_t i, std::size_t j, const std::string& title,
                           const TubeStyle& style, const Trajectory* truth_i, const Trajectory* truth_j,
                           double width_px, const std::vector<Vector>* landmarks, const std::string& name_i,
                           const std::string& name_j, std::size_t boxes) {
  check_components(x, i, j, "map_envelope_figure");
  Figure fig = map_frame(x, i, j, title, truth_i, truth_j, width_px, landmarks, name_i, name_j);
  // Cells of about 2 px: the outline follows the boxes to within a couple of pixels.
  const std::size_t cells = std::max<std::size_t>(1, static_cast<std::size_t>(width_px / 2));
  std::vector<ContourLoop> outer, holes;
  const IntervalVector window = map_view(x, i, j, name_i, name_j, truth_i, truth_j, landmarks).window;  // the frame's
  for (ContourLoop& l : map_envelope(x, i, j, window, cells)) (l.is_hole ? holes : outer).push_back(std::move(l));
  Style envelope = style.slices;
  envelope.label = "envelope of the " + std::to_string(x.nb_slices()) + " slice boxes";
  fig.draw_contour(outer, envelope);
  Style hole{"white", style.slices.stroke, style.slices.stroke_width, 1.0, "hole", ""};
  fig.draw_contour(holes, hole);
  // A few slice boxes, evenly spaced in time: how large one box is.
  const std::size_t n = x.nb_slices();
  Style box{"none", style.gates.fill, 1.0, 1.0, "box", boxes > 0 ? "a slice box (" + std::to_string(boxes) + " drawn)" : ""};
  for (std::size_t m = 0; m < boxes && n > 0; ++m) {
    const std::size_t k = boxes == 1 ? n / 2 : m * (n - 1) / (boxes - 1);
    fig.draw_box(IntervalVector{x[i].slice(k), x[j].slice(k)}, box);
  }
  for (const auto& [k, st] : {std::pair{std::size_t{0}, &style.initial}, std::pair{n, &style.final}})
    fig.draw_box(IntervalVector{x[i].gate(k), x[j].gate(k)}, *st);
  if (truth_i != nullptr && truth_j != nullptr) {  // sampled at 2000 points of its domain within [t0, tf]
    const Interval dom = truth_i->domain() & truth_j->domain() & x.tdomain()->t0_tf();
    std::vector<Vector> path;
    for (std::size_t s = 0; !dom.is_empty() && s <= 2000; ++s) {
      const double t = s == 2000 ? dom.ub() : dom.lb() + dom.diam() * static_cast<double>(s) / 2000;
      const Interval a = (*truth_i)(t), b = (*truth_j)(t);
      if (!a.is_empty() && !b.is_empty() && a.is_bounded() && b.is_bounded()) path.push_back(Vector{a.mid(), b.mid()});
    }
    fig.draw_polyline(path, style.truth);
  }
  if (landmarks != nullptr && style.landmark_px > 0)
    for (const Vector& p : *landmarks) fig.draw_point(p, style.landmark_px, style.landmarks);
  return fig;
}

}  // namespace sillage

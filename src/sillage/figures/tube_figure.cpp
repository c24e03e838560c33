#include "sillage/figures/tube_figure.h"

#include <algorithm>
#include <cmath>

#include "sillage/error.h"

namespace sillage {

namespace {

// Pixels per world unit along each axis (the mapping of Figure is affine).
double scale_x(const Figure& f) { return std::abs(f.px(1) - f.px(0)); }
double scale_y(const Figure& f) { return std::abs(f.py(1) - f.py(0)); }

void check_style(const TubeStyle& s, const char* where) {
  if (!(s.merge_px >= 0) || !std::isfinite(s.merge_px)) {
    throw Error(std::string(where) + ": merge_px must be finite and >= 0, got " + std::to_string(s.merge_px));
  }
}

// Grows a degenerate or tiny interval to `min_px` pixels so that it shows;
// the result still contains x (display only).
Interval at_least(const Interval& x, double min_px, double scale) {
  if (x.is_empty() || x.is_unbounded()) return x;
  const double want = min_px / scale, d = x.diam();
  return d >= want ? x : x.inflate((want - d) / 2);
}

// Polyline(s) through the finite points; an unbounded or empty value cuts it.
template <class PointAt>
void draw_sampled(Figure& fig, const Interval& dom, std::size_t n, const Style& style, PointAt point_at) {
  std::vector<Vector> piece;
  for (std::size_t s = 0; s <= n; ++s) {
    const double t = s == n ? dom.ub() : dom.lb() + (dom.ub() - dom.lb()) * static_cast<double>(s) / n;
    Vector p;
    if (point_at(t, p)) {
      piece.push_back(std::move(p));
    } else {
      if (piece.size() > 1) fig.draw_polyline(piece, style);
      piece.clear();
    }
  }
  if (piece.size() > 1) fig.draw_polyline(piece, style);
}

bool finite_value(const Interval& v, double& out) {
  if (v.is_empty() || v.is_unbounded()) return false;
  out = v.mid();
  return std::isfinite(out);
}

}  // namespace

Interval finite_window(const std::vector<Interval>& xs, bool& clipped) {
  clipped = false;
  double lo = rounding::kInf, hi = -rounding::kInf;
  for (const auto& x : xs) {
    if (x.is_empty()) continue;
    if (x.is_unbounded()) clipped = true;
    for (double b : {x.lb(), x.ub()}) {
      if (std::isfinite(b)) {
        lo = std::min(lo, b);
        hi = std::max(hi, b);
      }
    }
  }
  if (lo > hi) return {-1, 1};
  if (lo == hi) return {lo - std::max(1.0, std::abs(lo) * 0.1), hi + std::max(1.0, std::abs(hi) * 0.1)};
  // A wider margin when clipped, so that the unbounded parts visibly reach the edge.
  double m = (clipped ? 0.25 : 0.05) * (hi / 2 - lo / 2) * 2;
  if (!std::isfinite(m) || !std::isfinite(lo - m) || !std::isfinite(hi + m)) m = 0;
  return {lo - m, hi + m};
}

std::size_t draw_tube(Figure& fig, const Tube& x, const TubeStyle& style, const Trajectory* truth) {
  check_style(style, "draw_tube");
  const TDomain& td = *x.tdomain();
  const auto sl = x.slices();
  const std::size_t n = sl.size(), before = fig.nb_shapes();
  const double tol_y = style.merge_px / scale_y(fig);
  Style dense = style.slices;
  dense.stroke = dense.fill;

  // Slices: a group grows while it spans at most one pixel column, or while
  // its hull stays within merge_px pixels of each of its slices (so a thin
  // slice is never hidden in a thick neighbour, nor an empty one).
  for (std::size_t k = 0; k < n;) {
    const std::size_t start = k;
    const double x0 = fig.px(td.t(start));
    Interval h = sl[k], core = sl[k].inflate(tol_y);
    for (++k; k < n; ++k) {
      const Interval h2 = h | sl[k], core2 = core & sl[k].inflate(tol_y);
      if (fig.px(td.t(k + 1)) - x0 > 1.0 && !h2.is_subset(core2)) break;
      h = h2;
      core = core2;
    }
    // Narrow rectangles: outlines would darken the tube, so stroke with the fill colour.
    const bool narrow = fig.px(td.t(k)) - x0 < 3.0 && style.slices.fill != "none";
    fig.draw_box(IntervalVector{Interval(td.t(start), td.t(k)), h}, narrow ? dense : style.slices);
  }
  const std::size_t drawn = fig.nb_shapes() - before;

  // Gates: one 1-px bar per pixel column, the hull of the gates in it; not
  // when slices are under 4 px wide on average (the bars would paint the tube).
  const double mean_px = (fig.px(td.tf()) - fig.px(td.t0())) / static_cast<double>(n);
  if (style.show_gates && mean_px >= 4.0) {
    const auto gs = x.gates();
    const double hw = 0.5 / scale_x(fig);
    for (std::size_t k = 0; k < gs.size();) {
      const std::size_t start = k;
      const double col = std::floor(fig.px(td.t(k)));
      Interval h = gs[k];
      for (++k; k < gs.size() && std::floor(fig.px(td.t(k))) == col; ++k) h |= gs[k];
      fig.draw_box(IntervalVector{Interval(td.t(start) - hw, td.t(k - 1) + hw), h}, style.gates);
    }
  }

  if (truth != nullptr) {
    const Interval dom = truth->domain() & td.t0_tf();
    if (!dom.is_empty() && !dom.is_degenerate()) {
      const double w = fig.px(dom.ub()) - fig.px(dom.lb());
      const auto samples = static_cast<std::size_t>(std::clamp(std::ceil(w), 2.0, 20000.0));
      draw_sampled(fig, dom, samples, style.truth, [&](double t, Vector& p) {
        double v;
        if (!finite_value((*truth)(t), v)) return false;
        p = {t, v};
        return true;
      });
    }
  }
  return drawn;
}

std::size_t draw_tube_vector_2d(Figure& fig, const TubeVector& x, std::size_t i, std::size_t j,
                                const TubeStyle& style, const Trajectory* truth_i, const Trajectory* truth_j) {
  check_style(style, "draw_tube_vector_2d");
  if (i >= x.size() || j >= x.size() || i == j) {
    throw DimensionError("draw_tube_vector_2d: components (" + std::to_string(i) + ", " + std::to_string(j) +
                         ") of a tube vector of size " + std::to_string(x.size()) +
                         " (they must be distinct and in range)");
  }
  const auto xi = x[i].slices(), xj = x[j].slices();
  const std::size_t n = xi.size(), before = fig.nb_shapes();
  const double sx = scale_x(fig), sy = scale_y(fig);
  const double tol_x = style.merge_px / sx, tol_y = style.merge_px / sy;
  auto empty_at = [&](std::size_t k) { return xi[k].is_empty() || xj[k].is_empty(); };

  // Consecutive slice boxes merge while their hull stays within merge_px
  // pixels of each of them (so tiny boxes along a path merge); empty slices
  // (some component empty) end a group and are not drawn.
  for (std::size_t k = 0; k < n;) {
    if (empty_at(k)) {
      ++k;
      continue;
    }
    Interval hx = xi[k], hy = xj[k], core_x = hx.inflate(tol_x), core_y = hy.inflate(tol_y);
    for (++k; k < n && !empty_at(k); ++k) {
      const Interval hx2 = hx | xi[k], hy2 = hy | xj[k];
      const Interval cx2 = core_x & xi[k].inflate(tol_x), cy2 = core_y & xj[k].inflate(tol_y);
      if (!hx2.is_subset(cx2) || !hy2.is_subset(cy2)) break;
      hx = hx2;
      hy = hy2;
      core_x = cx2;
      core_y = cy2;
    }
    fig.draw_box(IntervalVector{hx, hy}, style.slices);
  }
  const std::size_t drawn = fig.nb_shapes() - before;

  if (truth_i != nullptr && truth_j != nullptr) {
    const Interval dom = truth_i->domain() & truth_j->domain() & x.tdomain()->t0_tf();
    if (!dom.is_empty() && !dom.is_degenerate()) {
      draw_sampled(fig, dom, 2000, style.truth, [&](double t, Vector& p) {
        double a, b;
        if (!finite_value((*truth_i)(t), a) || !finite_value((*truth_j)(t), b)) return false;
        p = {a, b};
        return true;
      });
    }
  }
  // Gates 0 and N on top, at least 3 px wide so that a point shows.
  const std::size_t last = x.nb_slices();
  for (const auto& [k, st] : {std::pair{std::size_t{0}, &style.initial}, std::pair{last, &style.final}}) {
    fig.draw_box(IntervalVector{at_least(x[i].gate(k), 3, sx), at_least(x[j].gate(k), 3, sy)}, *st);
  }
  return drawn;
}

Figure tube_figure(const Tube& x, const std::string& title, const TubeStyle& style, const Trajectory* truth,
                   double width_px, double height_px) {
  std::vector<Interval> all(x.slices().begin(), x.slices().end());
  all.insert(all.end(), x.gates().begin(), x.gates().end());
  bool clipped = false;
  const Interval wy = finite_window(all, clipped);
  Figure fig(IntervalVector{x.tdomain()->t0_tf(), wy}, width_px, height_px);
  fig.set_title(clipped ? title + " (unbounded: clipped to " + wy.str() + ")" : title);
  fig.set_labels("t (s)", "x");
  draw_tube(fig, x, style, truth);
  return fig;
}

Figure tube_vector_figure(const TubeVector& x, std::size_t i, std::size_t j, const std::string& title,
                          const TubeStyle& style, const Trajectory* truth_i, const Trajectory* truth_j,
                          double width_px) {
  if (i >= x.size() || j >= x.size() || i == j) {
    throw DimensionError("tube_vector_figure: components (" + std::to_string(i) + ", " + std::to_string(j) +
                         ") of a tube vector of size " + std::to_string(x.size()));
  }
  bool ci = false, cj = false;
  auto all = [&](const Tube& c) {
    std::vector<Interval> v(c.slices().begin(), c.slices().end());
    v.insert(v.end(), c.gates().begin(), c.gates().end());
    return v;
  };
  const Interval wx = finite_window(all(x[i]), ci), wy = finite_window(all(x[j]), cj);
  Figure fig(IntervalVector{wx, wy}, width_px);
  fig.set_title(ci || cj ? title + " (unbounded: clipped to " + wx.str() + " x " + wy.str() + ")" : title);
  // Built with append: `"x" + std::to_string(..)` trips a GCC 12 -Wrestrict false positive.
  std::string lx = "x", ly = "x";
  lx.append(std::to_string(i + 1));
  ly.append(std::to_string(j + 1));
  fig.set_labels(lx, ly);
  draw_tube_vector_2d(fig, x, i, j, style, truth_i, truth_j);
  return fig;
}

}  // namespace sillage

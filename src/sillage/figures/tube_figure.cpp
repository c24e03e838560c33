#include "sillage/figures/tube_figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sillage/error.h"

namespace sillage {

namespace {

// Pixels per world unit along each axis (the mapping of Figure is affine).
double scale_x(const Figure& f) { return std::abs(f.px(1) - f.px(0)); }
double scale_y(const Figure& f) { return std::abs(f.py(1) - f.py(0)); }

void check_style(const TubeStyle& s, const char* where) {
  for (const auto& [name, v] : {std::pair{"merge_px", s.merge_px}, std::pair{"min_px", s.min_px},
                                std::pair{"landmark_px", s.landmark_px}}) {
    if (!(v >= 0) || !std::isfinite(v)) {
      throw Error(std::string(where) + ": " + name + " must be finite and >= 0, got " + std::to_string(v));
    }
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
    fig.draw_box(IntervalVector{Interval(td.t(start), td.t(k)), at_least(h, style.min_px, scale_y(fig))},
                 narrow ? dense : style.slices);
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
  std::vector<IntervalVector> groups;
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
    groups.push_back(IntervalVector{at_least(hx, style.min_px, sx), at_least(hy, style.min_px, sy)});
  }
  // Larger boxes first: the smaller ones (the start of a drift, a narrowing) stay visible over them.
  auto area = [](const IntervalVector& b) { return b.is_unbounded() ? rounding::kInf : b[0].diam() * b[1].diam(); };
  std::stable_sort(groups.begin(), groups.end(),
                   [&](const IntervalVector& a, const IntervalVector& b) { return area(a) > area(b); });
  for (const IntervalVector& g : groups) fig.draw_box(g, style.slices);
  const std::size_t drawn = fig.nb_shapes() - before;

  // Gates 0 and N, translucent and at least 3 px wide so that a point shows.
  const std::size_t last = x.nb_slices();
  for (const auto& [k, st] : {std::pair{std::size_t{0}, &style.initial}, std::pair{last, &style.final}}) {
    fig.draw_box(IntervalVector{at_least(x[i].gate(k), 3, sx), at_least(x[j].gate(k), 3, sy)}, *st);
  }
  // The truth last, thin, over the tube and its gates.
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
  return drawn;
}

Figure tube_figure(const Tube& x, const std::string& title, const TubeStyle& style, const Trajectory* truth,
                   double width_px, double height_px, const std::string& name) {
  std::vector<Interval> all(x.slices().begin(), x.slices().end());
  all.insert(all.end(), x.gates().begin(), x.gates().end());
  bool clipped = false;
  const Interval wy = finite_window(all, clipped);
  Figure fig(IntervalVector{x.tdomain()->t0_tf(), wy}, width_px, height_px);
  fig.set_title(title);
  if (clipped) fig.set_note("Unbounded: clipped to " + wy.str());
  fig.set_labels("t (s)", name);
  draw_tube(fig, x, style, truth);
  return fig;
}

namespace {

// All the slices and gates of a tube.
std::vector<Interval> slices_and_gates(const Tube& c) {
  std::vector<Interval> v(c.slices().begin(), c.slices().end());
  v.insert(v.end(), c.gates().begin(), c.gates().end());
  return v;
}

// The hull of the finite points (truth samples, landmarks) along x_i and x_j.
IntervalVector key_hull(const TubeVector& x, const Trajectory* truth_i, const Trajectory* truth_j,
                        const std::vector<Vector>* landmarks) {
  IntervalVector h(2, Interval::empty());
  auto add = [&](double a, double b) {
    if (std::isfinite(a) && std::isfinite(b)) h |= IntervalVector{Interval(a), Interval(b)};
  };
  if (truth_i != nullptr && truth_j != nullptr) {
    const Interval dom = truth_i->domain() & truth_j->domain() & x.tdomain()->t0_tf();
    if (!dom.is_empty()) {
      for (std::size_t s = 0; s <= 2000; ++s) {
        const double t = s == 2000 ? dom.ub() : dom.lb() + dom.diam() * static_cast<double>(s) / 2000;
        double a, b;
        if (finite_value((*truth_i)(t), a) && finite_value((*truth_j)(t), b)) add(a, b);
      }
    }
  }
  if (landmarks != nullptr) {
    for (const Vector& p : *landmarks) {
      if (p.size() != 2) throw DimensionError("map_view: landmarks must be 2-D points, got dimension " + std::to_string(p.size()));
      add(p[0], p[1]);
    }
  }
  return h;
}

std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

// Built with append: `"[" + std::string` trips a GCC 12 -Wrestrict false positive.
std::string range_text(const Interval& x) {
  return std::string("[").append(short_number(x.lb())).append(", ").append(short_number(x.ub())).append("]");
}

}  // namespace

MapView map_view(const TubeVector& x, std::size_t i, std::size_t j, const std::string& name_i,
                 const std::string& name_j, const Trajectory* truth_i, const Trajectory* truth_j,
                 const std::vector<Vector>* landmarks, double zoom) {
  if (i >= x.size() || j >= x.size() || i == j) {
    throw DimensionError("map_view: components (" + std::to_string(i) + ", " + std::to_string(j) +
                         ") of a tube vector of size " + std::to_string(x.size()));
  }
  if (!(zoom >= 1) || !std::isfinite(zoom)) throw Error("map_view: zoom must be finite and >= 1, got " + number_text(zoom));
  bool ci = false, cj = false;
  const Interval wx = finite_window(slices_and_gates(x[i]), ci), wy = finite_window(slices_and_gates(x[j]), cj);
  MapView v{IntervalVector{wx, wy}, ""};
  if (ci || cj) v.note = "Unbounded: clipped to " + range_text(wx) + " × " + range_text(wy);
  const IntervalVector key = key_hull(x, truth_i, truth_j, landmarks);
  if (key.is_empty()) return v;
  bool unused = false;  // the same margins as the tube's window
  const IntervalVector framed{finite_window({key[0]}, unused), finite_window({key[1]}, unused)};
  if (wx.diam() > zoom * framed[0].diam() || wy.diam() > zoom * framed[1].diam()) {
    const IntervalVector tube{x[i].codomain(), x[j].codomain()};
    v.window = framed;
    const bool truth = truth_i != nullptr && truth_j != nullptr, marks = landmarks != nullptr && !landmarks->empty();
    v.note = std::string("Framed on ") + (truth && marks ? "the truth and the landmarks" : truth ? "the truth" : "the landmarks") +
             "; the tube reaches " + name_i + " in " + range_text(tube[0]) + ", " + name_j + " in " + range_text(tube[1]);
  } else {
    v.window = v.window | framed;
  }
  return v;
}

Figure map_frame(const TubeVector& x, std::size_t i, std::size_t j, const std::string& title,
                 const Trajectory* truth_i, const Trajectory* truth_j, double width_px,
                 const std::vector<Vector>* landmarks, const std::string& name_i, const std::string& name_j) {
  // Built with append: `"x" + std::to_string(..)` trips a GCC 12 -Wrestrict false positive.
  std::string ni = name_i, nj = name_j;
  if (ni.empty()) ni.append("x").append(std::to_string(i + 1));
  if (nj.empty()) nj.append("x").append(std::to_string(j + 1));
  const MapView view = map_view(x, i, j, ni, nj, truth_i, truth_j, landmarks);
  Figure fig(view.window, width_px);
  fig.set_title(title);
  fig.set_note(view.note);
  fig.set_labels(ni, nj);
  return fig;
}

Figure tube_vector_figure(const TubeVector& x, std::size_t i, std::size_t j, const std::string& title,
                          const TubeStyle& style, const Trajectory* truth_i, const Trajectory* truth_j,
                          double width_px, const std::vector<Vector>* landmarks, const std::string& name_i,
                          const std::string& name_j) {
  check_style(style, "tube_vector_figure");
  Figure fig = map_frame(x, i, j, title, truth_i, truth_j, width_px, landmarks, name_i, name_j);
  draw_tube_vector_2d(fig, x, i, j, style, truth_i, truth_j);
  if (landmarks != nullptr && style.landmark_px > 0) {
    for (const Vector& p : *landmarks) fig.draw_point(p, style.landmark_px, style.landmarks);
  }
  return fig;
}

}  // namespace sillage

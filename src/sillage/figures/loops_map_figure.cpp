#include "sillage/figures/loops_map_figure.h"

#include <algorithm>
#include <cmath>

#include "sillage/error.h"
#include "sillage/figures/tube_figure.h"

namespace sillage {

namespace {

void check_options(const LoopsMapOptions& o) {
  for (double v : {o.path_px, o.crossing_px}) {
    if (!(v > 0) || !std::isfinite(v)) {
      throw Error("draw_loops_map: the pixel sizes of the options must be finite and > 0, got " + number_text(v));
    }
  }
}

void check_path(const std::vector<Vector>* path, const std::vector<double>* times) {
  if (path) {
    for (std::size_t k = 0; k < path->size(); ++k) {
      if ((*path)[k].size() != 2) {
        throw DimensionError("draw_loops_map: path point " + std::to_string(k) + " has dimension " +
                             std::to_string((*path)[k].size()));
      }
    }
  }
  if (!times) return;
  if (!path || path->size() != times->size()) {
    throw DimensionError("draw_loops_map: the path times need a path of the same size");
  }
  for (std::size_t k = 1; k < times->size(); ++k) {
    if (!((*times)[k - 1] < (*times)[k])) {
      throw Error("draw_loops_map: the path times must be increasing, at index " + std::to_string(k));
    }
  }
}

// Display-only thinning of points[first, last): drops points closer than
// min_px to the last kept one; the ends are always kept.
std::vector<Vector> thinned(const Figure& fig, const std::vector<Vector>& points, std::size_t first, std::size_t last,
                            double min_px) {
  const double sx = std::abs(fig.px(1) - fig.px(0)), sy = std::abs(fig.py(1) - fig.py(0));
  std::vector<Vector> kept;
  for (std::size_t k = first; k < last; ++k) {
    const Vector& p = points[k];
    if (!kept.empty() && k + 1 < last &&
        std::hypot((p[0] - kept.back()[0]) * sx, (p[1] - kept.back()[1]) * sy) < min_px) {
      continue;
    }
    kept.push_back(p);
  }
  return kept;
}

}  // namespace

std::vector<MapLoop> map_loops(const TPlane& tplane) {
  std::vector<MapLoop> loops;
  loops.reserve(tplane.nb_detections());
  for (const Loop& l : tplane.detections()) loops.push_back({l.map_box(), loop_status(l), l.t_box()});
  return loops;
}

LoopsMapCounts draw_loops_map(Figure& fig, const std::vector<MapLoop>& loops, const std::vector<Vector>* path,
                              const std::vector<double>* path_times, const TubeVector* positions,
                              const std::vector<PathCrossing>* crossings, const LoopsMapOptions& options) {
  check_options(options);
  check_path(path, path_times);
  for (const MapLoop& l : loops) {
    if (l.map_box.size() != 2 || l.t_box.size() != 2) {
      throw DimensionError("draw_loops_map: map boxes and t-boxes must be 2-D");
    }
  }
  LoopsMapCounts counts;
  if (positions) {
    TubeStyle ts;
    ts.slices = {"#dfe9f5", "#9fbcdc", 0.3, 1.0, "position", "position tube"};
    ts.merge_px = 3.0;  // a background: coarser groups of slices, still covering every slice
    counts.tube_boxes = draw_tube_vector_2d(fig, *positions, 0, 1, ts);
  }
  if (path && !path->empty()) {
    const std::vector<Vector> kept = thinned(fig, *path, 0, path->size(), options.path_px);
    fig.draw_polyline(kept, {"none", "#1f4e8c", 0.8, 1.0, "path", "path"});
    counts.path_points = kept.size();
  }
  for (LoopStatus status : {LoopStatus::Partial, LoopStatus::Unproven, LoopStatus::Proven}) {
    if (status == LoopStatus::Partial && !options.show_partial) continue;
    Style style = loop_style(status);
    style.opacity = 0.2;  // map boxes overlap a lot: keep the path visible through them
    style.label = "map box, " + to_string(status) + " loop";
    for (const MapLoop& l : loops) {
      if (l.status != status) continue;
      if (options.boxes && !l.map_box.is_empty()) {
        fig.draw_box(l.map_box, style);
        ++counts.loops;
      }
      if (!options.projections || !path_times || l.t_box.is_empty()) continue;
      const Style bold{"none", style.stroke == "#000000" ? "#000000" : style.fill, 2.5, 1.0,
                       style.css_class + "-projection", "path over [t1] and [t2], " + to_string(status) + " loop"};
      for (const Interval& t : {l.t_box[0], l.t_box[1]}) {
        // The samples inside [t] (the path is drawn at its sampling: the
        // projection is a piece of the drawn path).
        const auto lo = std::lower_bound(path_times->begin(), path_times->end(), t.lb());
        const auto hi = std::upper_bound(path_times->begin(), path_times->end(), t.ub());
        if (hi - lo < 2) continue;
        fig.draw_polyline(thinned(fig, *path, std::size_t(lo - path_times->begin()),
                                  std::size_t(hi - path_times->begin()), options.path_px),
                          bold);
        ++counts.projections;
      }
    }
  }
  if (crossings) {
    for (const PathCrossing& c : *crossings) {
      fig.draw_point({c.x, c.y}, options.crossing_px, {"#d62728", "#ffffff", 0.5, 1, "crossing", "true crossings"});
      ++counts.crossings;
    }
  }
  return counts;
}

Figure loops_map_figure(const std::vector<MapLoop>& loops, const std::vector<Vector>* path,
                        const std::vector<double>* path_times, const TubeVector* positions,
                        const std::vector<PathCrossing>* crossings, const std::string& title, double width_px,
                        const LoopsMapOptions& options, const std::string& x_label, const std::string& y_label) {
  std::vector<Interval> xs, ys;
  if (path) {
    for (const Vector& p : *path) {
      if (p.size() == 2) xs.emplace_back(p[0]), ys.emplace_back(p[1]);
    }
  }
  if (positions) {
    const IntervalVector c = positions->codomain();
    xs.push_back(c[0]), ys.push_back(c[1]);
  }
  if (options.boxes) {
    for (const MapLoop& l : loops) {
      if (l.map_box.size() == 2 && !l.map_box.is_empty()) xs.push_back(l.map_box[0]), ys.push_back(l.map_box[1]);
    }
  }
  bool clipped_x = false, clipped_y = false;
  const Interval wx = finite_window(xs, clipped_x), wy = finite_window(ys, clipped_y);
  Figure fig(IntervalVector{wx, wy}, width_px);
  fig.set_title(title);
  fig.set_labels(x_label, y_label);
  draw_loops_map(fig, loops, path, path_times, positions, crossings, options);
  return fig;
}

Figure loops_map_figure(const TPlane& tplane, const std::vector<Vector>* path, const std::vector<double>* path_times,
                        const TubeVector* positions, const std::vector<PathCrossing>* crossings,
                        const std::string& title, double width_px, const LoopsMapOptions& options,
                        const std::string& x_label, const std::string& y_label) {
  return loops_map_figure(map_loops(tplane), path, path_times, positions, crossings, title, width_px, options, x_label,
                          y_label);
}

}  // namespace sillage

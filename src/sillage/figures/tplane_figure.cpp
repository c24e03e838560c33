#include "sillage/figures/tplane_figure.h"

#include <algorithm>
#include <cmath>

#include "sillage/error.h"
#include "sillage/paving/contour.h"

namespace sillage {

namespace {

void check_view(const IntervalVector& view, const char* where) {
  if (view.size() != 2 || view.is_empty() || view.is_unbounded() || view[0].is_degenerate() ||
      view[1].is_degenerate()) {
    throw Error(std::string(where) + ": the view must be a bounded 2-D box with non-zero widths, got " + view.str());
  }
}

void check_options(const TPlaneFigureOptions& o) {
  for (double v : {o.min_leaf_px, o.marker_px, o.crossing_px}) {
    if (!(v > 0) || !std::isfinite(v)) {
      throw Error("draw_tplane: the pixel sizes of the options must be finite and > 0, got " + number_text(v));
    }
  }
}

// The paving colours, named as in the Python legend (plot_loops.TPLANE_LEGEND).
Style labelled(PavingTag tag) {
  Style s = paving_style(tag);
  s.label = tag == PavingTag::Inner ? "inner" : tag == PavingTag::Boundary ? "boundary" : "outside (no loop)";
  return s;
}

Style labelled(LoopStatus status) {
  Style s = loop_style(status);
  s.label = status == LoopStatus::Proven     ? "proven loop"
            : status == LoopStatus::Unproven ? "detection (no proof)"
                                             : "partial detection";
  return s;
}

IntervalVector hull_of(const std::vector<IntervalVector>& boxes) {
  IntervalVector h(2, Interval::empty());
  for (const auto& b : boxes) h |= b;
  return h;
}

}  // namespace

std::vector<DetectionShape> detection_shapes(const TPlane& tplane) {
  std::vector<DetectionShape> shapes;
  shapes.reserve(tplane.nb_detections());
  for (const Loop& l : tplane.detections()) {
    shapes.push_back({l.boxes(), loop_status(l)});
    // The proven pieces of a split detection, drawn over it (component_split.h).
    for (const Loop& p : l.pieces()) {
      if (p.proven()) shapes.push_back({p.boxes(), LoopStatus::Proven});
    }
  }
  return shapes;
}

TPlaneFigureCounts draw_tplane(Figure& fig, const IntervalVector& view, const Paving& paving,
                               const std::vector<DetectionShape>& detections,
                               const std::vector<PathCrossing>* crossings, const TPlaneFigureOptions& options) {
  check_view(view, "draw_tplane");
  check_options(options);
  TPlaneFigureCounts counts;
  const double sx = std::abs(fig.px(1) - fig.px(0)), sy = std::abs(fig.py(1) - fig.py(0));  // px per second
  auto big_enough = [&](const IntervalVector& b, double px) {
    return b[0].diam() * sx >= px || b[1].diam() * sy >= px;
  };

  if (!paving.is_empty()) {
    // The domain in the outside colour, then the leaves of the outer
    // approximation: together they show every leaf with its tag.
    fig.draw_box(paving.domain(), labelled(PavingTag::Outside));
    for (PavingTag tag : {PavingTag::Inner, PavingTag::Boundary}) {
      for (std::size_t i : paving.leaf_indices(tag)) {
        const IntervalVector b = paving.node_box(i);
        if (!b.intersects(view) || !big_enough(b, options.min_leaf_px)) continue;
        fig.draw_box(b, labelled(tag));
        ++counts.leaves;
      }
    }
  }
  if (options.show_diagonal) {
    const double lo = std::max(view[0].lb(), view[1].lb()), hi = std::min(view[0].ub(), view[1].ub());
    if (lo < hi) fig.draw_polyline({{lo, lo}, {hi, hi}}, {"none", "#555555", 0.8, 1.0, "diagonal", "t1 = t2"});
  }
  // Partial ones first, proven ones last: the proofs stay on top.
  for (LoopStatus status : {LoopStatus::Partial, LoopStatus::Unproven, LoopStatus::Proven}) {
    const Style style = labelled(status);
    for (const DetectionShape& d : detections) {
      if (d.status != status || d.boxes.empty()) continue;
      const IntervalVector hull = hull_of(d.boxes);
      if (hull.is_empty() || !hull.intersects(view)) continue;
      fig.draw_contour(contour(d.boxes), style);
      ++counts.components;
      if (!big_enough(hull, 2 * options.marker_px)) {
        const Vector centre = hull.mid();
        if (view.contains(centre)) {
          fig.draw_point(centre, options.marker_px, {style.fill, "none", 0, 1, style.css_class + "-marker"});
          ++counts.markers;
        }
      }
    }
  }
  if (crossings) {
    for (const PathCrossing& c : *crossings) {
      if (!view.contains({c.t1, c.t2})) continue;
      fig.draw_point({c.t1, c.t2}, options.crossing_px, {"#1565c0", "#ffffff", 0.5, 1, "crossing", "true crossings"});
      ++counts.crossings;
    }
  }
  return counts;
}

Figure tplane_figure(const TPlane& tplane, const std::vector<PathCrossing>* crossings, const std::string& title,
                     const IntervalVector* view, double width_px, const TPlaneFigureOptions& options) {
  const IntervalVector window = view ? *view : tplane.domain();
  check_view(window, "tplane_figure");
  Figure fig(window, width_px);
  fig.set_title(title);
  fig.set_labels("t1 (s)", "t2 (s)");
  draw_tplane(fig, window, tplane.paving(), detection_shapes(tplane), crossings, options);
  return fig;
}

}  // namespace sillage

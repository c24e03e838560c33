#include "sillage/missions/slam_figures.h"

#include <algorithm>
#include <cmath>

#include "sillage/error.h"
#include "sillage/figures/thickness_figure.h"
#include "sillage/figures/tube_figure.h"
#include "sillage/missions/bathymetry_tubes.h"

namespace sillage {

namespace {

// The step curve of values over td, one step per pixel column of fig (upper envelope).
std::vector<Vector> envelope(const Figure& fig, const TDomain& td, const std::vector<double>& values, double hi) {
  std::vector<Vector> pts;
  const std::size_t n = td.nb_slices();
  for (std::size_t k = 0; k < n;) {
    const std::size_t start = k;
    const double x0 = fig.px(td.t(start));
    double v = values[k];
    for (++k; k < n && fig.px(td.t(k + 1)) - x0 <= 1.0; ++k) v = std::max(v, values[k]);
    v = std::min(v, hi);
    pts.push_back({td.t(start), v});
    pts.push_back({td.t(k), v});
  }
  return pts;
}

}  // namespace

Figure slam_thickness_figure(const std::vector<ThicknessCurve>& curves, const std::string& title, double width_px,
                             double height_px) {
  if (curves.empty()) throw Error("slam_thickness_figure: no curve");
  const auto td = curves.front().p.tdomain();
  std::vector<std::vector<double>> values;
  double hi = 0;
  for (const ThicknessCurve& c : curves) {
    if (c.p.size() < 2 || c.p.tdomain() != td)
      throw DimensionError("slam_thickness_figure: curve '" + c.label + "' must have 2+ components on the first's TDomain");
    values.push_back(thickness_values(c.p.subvector(0, 1), ThicknessMeasure::Diagonal));
    for (double v : values.back())
      if (std::isfinite(v)) hi = std::max(hi, v);
  }
  if (hi == 0) hi = 1;
  hi *= 1.08;
  Figure fig(IntervalVector{td->t0_tf(), Interval(0, hi)}, width_px, height_px);
  fig.set_title(title);
  fig.set_labels("t (s)", "d(t) (m)");
  // Curves within a pixel of each other everywhere hide one another: one
  // legend entry names them all, so that every name finds its curve.
  const double px_per_m = std::abs(fig.py(1) - fig.py(0));
  auto coincide = [&](const std::vector<double>& a, const std::vector<double>& b) {
    for (std::size_t k = 0; k < a.size(); ++k) {
      const bool fa = std::isfinite(a[k]), fb = std::isfinite(b[k]);
      if (fa != fb || (fa && std::abs(a[k] - b[k]) * px_per_m > 1.0)) return false;
    }
    return true;
  };
  std::vector<std::size_t> group(curves.size());
  for (std::size_t i = 0; i < curves.size(); ++i) {
    group[i] = i;
    for (std::size_t g = 0; g < i; ++g) {
      if (group[g] == g && coincide(values[g], values[i])) {
        group[i] = g;
        break;
      }
    }
    fig.draw_polyline(envelope(fig, *td, values[i], hi), Style{"none", curves[i].colour, 1.5, 1.0, "thickness"});
  }
  for (std::size_t g = 0; g < curves.size(); ++g) {
    if (group[g] != g) continue;
    std::string text = curves[g].label;
    std::size_t top = g, members = 1;
    for (std::size_t i = g + 1; i < curves.size(); ++i) {
      if (group[i] == g) text += " = " + curves[i].label, top = i, ++members;
    }
    if (members > 1) text += " (the curves coincide)";
    fig.add_legend(text, Style{"none", curves[top].colour, 1.5, 1.0, "thickness"}, LegendMark::Line);
  }
  // Legends show from two entries: one coinciding group says so in the note.
  if (fig.legend().size() == 1 && curves.size() > 1) fig.set_note(fig.legend().front().text);
  return fig;
}

Figure slam_map_figure(const BathymetryMission& m, const TubeVector& dead_reckoning, const TubeVector& slam,
                       const std::vector<IntervalVector>& tf_boxes, const std::string& title, double width_px) {
  if (dead_reckoning.size() < 2 || slam.size() < 2)
    throw DimensionError("slam_map_figure: the tubes need 2+ components (east, north)");
  const TrajectoryVector truth = bathymetry_truth(m);
  TubeStyle grey;
  grey.slices = {"#d9d9d9", "#b0b0b0", 0.3, 1.0, "dead-reckoning", "dead reckoning"};
  grey.truth = {"none", "#1f3f66", 1.0, 1.0, "truth", "truth"};
  const MapView view = map_view(dead_reckoning, 0, 1, "east (m)", "north (m)", &truth[0], &truth[1]);
  Figure fig(view.window, width_px);
  fig.set_title(title);
  fig.set_note(view.note);
  fig.set_labels("east (m)", "north (m)");
  draw_tube_vector_2d(fig, dead_reckoning, 0, 1, grey);
  TubeStyle blue;
  blue.slices = {"#9ecae1", "#4a90c2", 0.3, 1.0, "slam", "SLAM"};
  blue.truth = grey.truth;
  // The boxes [p](t_f) as outlines, below the truth.
  for (std::size_t i = 0; i < tf_boxes.size(); ++i) {
    const double w = i == 0 ? 2.0 : 1.0;
    fig.draw_box(tf_boxes[i].subvector(0, 1), Style{"none", i == 0 ? "#555555" : "#d62728", w, 1.0, "p-tf",
                                                    i == 0 ? "[p](t_f), dead reckoning" : "[p](t_f), SLAM iterations"});
  }
  if (!slam.is_empty()) draw_tube_vector_2d(fig, slam, 0, 1, blue, &truth[0], &truth[1]);
  return fig;
}

}  // namespace sillage

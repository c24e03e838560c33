#include "sillage/missions/bathymetry_figures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sillage/error.h"
#include "sillage/figures/tube_figure.h"
#include "sillage/missions/bathymetry_tubes.h"

namespace sillage {

std::string depth_colour(double depth, double lo, double hi) {
  const double s = hi > lo ? std::clamp((depth - lo) / (hi - lo), 0.0, 1.0) : 0.5;
  // From sand (#f2e6b3) through teal to deep blue (#0b2a5b).
  const double r0 = 242, g0 = 230, b0 = 179, r1 = 72, g1 = 158, b1 = 170, r2 = 11, g2 = 42, b2 = 91;
  double r, g, b;
  if (s < 0.5) {
    const double a = s / 0.5;
    r = r0 + a * (r1 - r0), g = g0 + a * (g1 - g0), b = b0 + a * (b1 - b0);
  } else {
    const double a = (s - 0.5) / 0.5;
    r = r1 + a * (r2 - r1), g = g1 + a * (g2 - g1), b = b1 + a * (b2 - b1);
  }
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", static_cast<int>(std::lround(r)), static_cast<int>(std::lround(g)),
                static_cast<int>(std::lround(b)));
  return buf;
}

Figure bathymetry_dem_figure(const BathymetryDem& dem, const std::vector<double>& x, const std::vector<double>& y,
                             const std::string& title, double block, double width_px) {
  if (!(block > 0)) throw Error("bathymetry_dem_figure: block must be > 0");
  if (x.size() != y.size()) throw DimensionError("bathymetry_dem_figure: x and y must have the same size");
  const IntervalVector d = dem.domain();
  Figure fig(d, width_px);
  fig.set_title(title);
  fig.set_labels("east (m)", "north (m)");
  const double lo = dem.min_depth(), hi = dem.max_depth();
  const auto nb = static_cast<std::size_t>(std::max(1.0, std::round(block / dem.cell_size())));
  for (std::size_t j = 0; j + 1 < dem.ny(); j += nb)
    for (std::size_t i = 0; i + 1 < dem.nx(); i += nb) {
      const std::size_t i1 = std::min(dem.nx() - 1, i + nb), j1 = std::min(dem.ny() - 1, j + nb);
      double s = 0;
      for (std::size_t b = j; b <= j1; ++b)
        for (std::size_t a = i; a <= i1; ++a) s += dem.node(a, b);
      const double mean = s / static_cast<double>((i1 - i + 1) * (j1 - j + 1));
      const std::string c = depth_colour(mean, lo, hi);
      const double h = dem.cell_size();
      fig.draw_box({Interval(dem.x0() + i * h, dem.x0() + i1 * h), Interval(dem.y0() + j * h, dem.y0() + j1 * h)},
                   {c, c, 0.3, 1.0, "dem"});
    }
  std::vector<Vector> path;
  const std::size_t step = std::max<std::size_t>(1, x.size() / 4000);
  for (std::size_t k = 0; k < x.size(); k += step) path.push_back({x[k], y[k]});
  if (!path.empty()) fig.draw_polyline(path, {"none", "white", 1.2, 1.0, "path"});
  // Depth scale: the shallowest and deepest values, as text.
  char buf[96];
  std::snprintf(buf, sizeof buf, "depth %.1f m (light) to %.1f m (dark)", lo, hi);
  fig.draw_text({d[0].lb() + 5, d[1].lb() + 8}, buf, 11, "black");
  return fig;
}

Figure bathymetry_map_figure(const BathymetryMission& m, const TubeVector& p, const std::string& title,
                             double width_px) {
  const TrajectoryVector truth = bathymetry_truth(m);
  TubeStyle style;
  style.slices = {"#c8c8c8", "#9a9a9a", 0.3, 1.0, "dead-reckoning", "dead reckoning"};
  style.truth = {"none", "#1f3f66", 1.0, 1.0, "truth", "truth"};
  return tube_vector_figure(p, 0, 1, title, style, &truth[0], &truth[1], width_px, nullptr, "east (m)", "north (m)");
}

Figure bathymetry_observation_figure(const BathymetryMission& m, const Tube& z, const std::string& title,
                                     double width_px) {
  const Trajectory zt = bathymetry_truth_observation(m);
  return tube_figure(z, title, {}, &zt, width_px, 300, "z (m)");
}

}  // namespace sillage

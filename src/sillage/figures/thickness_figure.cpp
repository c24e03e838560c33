#include "sillage/figures/thickness_figure.h"

#include <algorithm>
#include <cmath>

#include "sillage/error.h"

namespace sillage {

std::vector<double> thickness_values(const Tube& x) {
  std::vector<double> d(x.nb_slices());
  for (std::size_t k = 0; k < d.size(); ++k) d[k] = x.thickness(k);
  return d;
}

std::vector<double> thickness_values(const TubeVector& x, ThicknessMeasure m) {
  std::vector<double> d(x.nb_slices(), 0.0);
  std::vector<bool> empty(d.size(), false);
  for (std::size_t c = 0; c < x.size(); ++c) {
    const auto sl = x[c].slices();
    for (std::size_t k = 0; k < d.size(); ++k) {
      if (sl[k].is_empty()) {
        empty[k] = true;  // an empty component makes the whole slice box empty
        continue;
      }
      const double w = sl[k].diam();
      d[k] = m == ThicknessMeasure::MaxDiameter ? std::max(d[k], w) : d[k] + w * w;
    }
  }
  for (std::size_t k = 0; k < d.size(); ++k) {
    if (empty[k]) d[k] = 0;
    else if (m == ThicknessMeasure::Diagonal) d[k] = std::sqrt(d[k]);
  }
  return d;
}

Figure step_figure(const TDomain& td, const std::vector<double>& values, const std::string& title, double width_px,
                   double height_px) {
  const std::size_t n = td.nb_slices();
  if (values.size() != n) {
    throw DimensionError("step_figure: " + std::to_string(values.size()) + " values for " + std::to_string(n) +
                         " slices");
  }
  double lo = 0, hi = 0;
  bool clipped = false;
  for (double v : values) {
    if (std::isnan(v)) throw Error("step_figure: NaN value");
    if (std::isinf(v)) {
      clipped = true;
      continue;
    }
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (hi == lo) hi = lo + 1;
  hi += 0.05 * (hi - lo);
  Figure fig(IntervalVector{td.t0_tf(), Interval(lo, hi)}, width_px, height_px);
  fig.set_title(clipped ? title + " (infinite values clipped)" : title);
  fig.set_labels("t (s)", "d(t)");

  // One step per pixel column: the max of the slices it covers (upper
  // envelope), consecutive equal steps merged.
  std::vector<Vector> pts;
  for (std::size_t k = 0; k < n;) {
    const std::size_t start = k;
    const double x0 = fig.px(td.t(start));
    double v = values[k];
    for (++k; k < n && fig.px(td.t(k + 1)) - x0 <= 1.0; ++k) v = std::max(v, values[k]);
    v = std::clamp(v, lo, hi);
    if (!pts.empty() && pts.back()[1] == v) {
      pts.back()[0] = td.t(k);
    } else {
      pts.push_back({td.t(start), v});
      pts.push_back({td.t(k), v});
    }
  }
  fig.draw_polyline(pts, Style{"none", "#2a6aa8", 1.5, 1.0, "thickness"});
  return fig;
}

Figure thickness_figure(const Tube& x, const std::string& title, double width_px, double height_px) {
  return step_figure(*x.tdomain(), thickness_values(x), title, width_px, height_px);
}

Figure thickness_figure(const TubeVector& x, ThicknessMeasure m, const std::string& title, double width_px,
                        double height_px) {
  return step_figure(*x.tdomain(), thickness_values(x, m), title, width_px, height_px);
}

}  // namespace sillage

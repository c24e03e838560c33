#include "sillage/problem/refined_points.h"

#include <algorithm>
#include <cmath>

namespace sillage::detail {

std::vector<double> refined_points(const BuiltProblem& b, double q) {
  if (!(q >= 0 && q <= 1)) throw Error("refined_points: a quantile in [0, 1] expected, found " + number_text(q));
  const TDomain& td = *b.td;
  const std::size_t n = td.nb_slices();
  std::vector<double> thick(n, 0.0);
  for (const VarDomain& v : b.vars) {
    if (!v.tubes) continue;
    for (std::size_t i = 0; i < v.tubes->size(); ++i) {
      const Tube& x = (*v.tubes)[i];
      if (!std::isfinite(x.volume())) continue;
      // The slice's excess over its gates: what splitting it can remove (the
      // thickness the gates carry, accumulated drift, is there at any δ).
      for (std::size_t k = 0; k < n; ++k)
        thick[k] += std::max(0.0, x.slice(k).diam() - std::max(x.gate(k).diam(), x.gate(k + 1).diam()));
    }
  }
  std::vector<double> sorted = thick;
  const auto at = sorted.begin() + static_cast<std::ptrdiff_t>(std::floor(q * static_cast<double>(n - 1)));
  std::nth_element(sorted.begin(), at, sorted.end());
  const double threshold = *at;
  const bool uniform = std::none_of(thick.begin(), thick.end(), [&](double x) { return x > threshold; });
  std::vector<double> points;
  for (std::size_t k = 0; k < n; ++k) {
    points.push_back(td.t(k));
    const double mid = td.t(k) + (td.t(k + 1) - td.t(k)) / 2;
    if ((uniform || thick[k] > threshold) && mid > td.t(k) && mid < td.t(k + 1)) points.push_back(mid);
  }
  points.push_back(td.t(n));
  return points;
}

}  // namespace sillage::detail

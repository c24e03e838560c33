#include "sillage/slam/observation.h"

#include <cmath>
#include <string>
#include <vector>

#include "sillage/error.h"
#include "sillage/interval/elementary.h"

namespace sillage {

namespace {

void check(const TideModel& m, const char* where) {
  if (!(m.duration > 0) || !std::isfinite(m.duration) || !std::isfinite(m.range) || !std::isfinite(m.t_low)) {
    throw Error(std::string(where) + ": the tide's duration must be positive and its parameters finite");
  }
  if (!m.error.contains(0.0)) {
    throw Error(std::string(where) + ": the tide model's error " + m.error.str() + " must contain 0");
  }
}

}  // namespace

Tube tide_tube(const std::shared_ptr<TDomain>& td, const TideModel& tide) {
  check(tide, "tide_tube(tdomain, tide)");
  std::vector<Interval> slices(td->nb_slices()), gates(td->nb_slices() + 1);
  for (std::size_t k = 0; k < slices.size(); ++k) slices[k] = tide(td->slice_domain(k));
  for (std::size_t k = 0; k < gates.size(); ++k) gates[k] = tide(Interval(td->t(k)));
  return Tube(td, slices, gates);
}

Tube bathymetric_observation(const Tube& z_alt, const Tube& z_depth, const TideModel& tide) {
  const char* where = "bathymetric_observation(z_alt, z_depth, tide)";
  if (z_alt.tdomain() != z_depth.tdomain()) {
    throw DimensionError(std::string(where) + ": z_alt and z_depth must share one TDomain");
  }
  check(tide, where);
  Tube z = z_alt;
  z += z_depth;
  z += tide_tube(z_alt.tdomain(), tide);
  return z;
}

}  // namespace sillage

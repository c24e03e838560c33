#include "sillage/slam/bathymetry_tide.h"

#include <cmath>
#include <cstdio>

#include "sillage/error.h"
#include "sillage/interval/elementary.h"

namespace sillage {

Interval TideModel::height(const Interval& t) const {
  if (!(duration > 0) || !std::isfinite(range) || !std::isfinite(t_low))
    throw Error("TideModel.height: duration > 0 and a finite range and t_low expected");
  const Interval phase = Interval::half_pi() * (t - Interval(t_low)) / Interval(duration);
  return Interval(range) * sqr(sin(phase));
}

Interval TideModel::operator()(const Interval& t) const {
  if (!error.contains(0.0)) throw Error("TideModel: the model's error " + error.str() + " must contain 0");
  return height(t) + error;
}

double TideModel::height_value(double t) const {
  const double s = std::sin(1.5707963267948966 * (t - t_low) / duration);
  return range * s * s;
}

std::string repr(const TideModel& m) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "TideModel(range=%g m, duration=%g s, t_low=%g s, error=", m.range, m.duration,
                m.t_low);
  return buf + m.error.str() + ")";
}

}  // namespace sillage

#include "sillage/missions/bathymetry_sensors.h"

#include <cmath>
#include <cstdio>

#include "sillage/error.h"
#include "sillage/interval/elementary.h"

namespace sillage {

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180;

// Upper bound of tan(angle in degrees), rigorous.
Interval tan_deg(double deg) { return tan(Interval(deg) * Interval::pi() / Interval(180)); }
}  // namespace

std::string repr(const BathymetrySensorBounds& b) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "BathymetrySensorBounds(dvl=+-(%g %% + %g m/s), heading=+-%g deg, attitude=+-%g deg, depth=+-%g m, "
                "altitude=+-(%g %% + %g m), tide=+-%g m, beams %g+-%g deg)",
                100 * b.dvl_scale, b.dvl_offset, b.heading, b.attitude, b.depth, 100 * b.altitude_scale,
                b.altitude_offset, b.tide, b.beam_angle, b.beam_spread);
  return buf;
}

std::vector<Vector> dvl_footprint(double x, double y, double yaw, double altitude, const BathymetrySensorBounds& b) {
  if (!(altitude >= 0) || !std::isfinite(altitude)) throw Error("dvl_footprint: altitude must be finite and >= 0");
  std::vector<Vector> pts;
  pts.reserve(20);
  const double rc = altitude * std::tan(b.beam_angle * kDeg), rin = altitude * std::tan((b.beam_angle - b.beam_spread) * kDeg),
               rout = altitude * std::tan((b.beam_angle + b.beam_spread) * kDeg), da = b.beam_azimuth_spread * kDeg;
  for (int k = 0; k < 4; ++k) {
    const double az = yaw + (45 + 90 * k) * kDeg;
    const double rs[5] = {rc, rin, rout, rc, rc}, as[5] = {az, az, az, az - da, az + da};
    for (int m = 0; m < 5; ++m) pts.push_back({x + rs[m] * std::cos(as[m]), y + rs[m] * std::sin(as[m])});
  }
  return pts;
}

double footprint_depth(const BathymetryDem& dem, double x, double y, double yaw, double altitude,
                       const BathymetrySensorBounds& b) {
  double s = 0;
  const auto pts = dvl_footprint(x, y, yaw, altitude, b);
  for (const auto& p : pts) {
    const Interval d = dem(p[0], p[1]);
    if (!std::isfinite(d.lb()) || !std::isfinite(d.ub()))
      throw Error("footprint_depth: the footprint around (" + std::to_string(x) + ", " + std::to_string(y) +
                  ") leaves the DEM");
    s += d.mid();
  }
  return s / static_cast<double>(pts.size());
}

double footprint_filter_bound(const SeabedClass& c, double cell, double altitude_max, const BathymetrySensorBounds& b) {
  if (!(altitude_max >= 0)) throw Error("footprint_filter_bound: altitude_max must be >= 0");
  // The outermost footprint point: radius a tan(angle + spread) (the azimuth
  // offsets keep the centre radius, smaller).
  const Interval rho = Interval(altitude_max) * tan_deg(b.beam_angle + b.beam_spread);
  const Interval k(c.curvature), h(cell);
  const Interval e = k * sqr(rho) / Interval(2) + k * sqr(h) / Interval(2) + Interval(2) * Interval(c.roughness);
  return e.ub();
}

double nadir_altitude_max(double measured, const SeabedClass& c, double cell, const BathymetrySensorBounds& b) {
  if (!std::isfinite(measured)) throw Error("nadir_altitude_max: the measured altitude is not finite");
  // filter bound = cq a^2 + c0
  const Interval t = tan_deg(b.beam_angle + b.beam_spread);
  const Interval cq = Interval(c.curvature) * sqr(t) / Interval(2);
  const Interval c0 = Interval(c.curvature) * sqr(Interval(cell)) / Interval(2) + Interval(2) * Interval(c.roughness);
  const Interval K = Interval(measured) + Interval(b.altitude_scale) * Interval(std::abs(measured)) +
                     Interval(b.altitude_offset) + c0;
  if (cq.ub() <= 0) return K.ub();
  const Interval disc = Interval(1) - Interval(4) * cq * K;
  if (!(disc.lb() > 0))
    throw Error("nadir_altitude_max: measured altitude " + number_text(measured) +
                " m is too high for the seabed class (the footprint filter bound has no fixed point)");
  // Smaller root (1 - sqrt(disc)) / (2 cq) = 2K / (1 + sqrt(disc)): the second form is stable.
  return (Interval(2) * K / (Interval(1) + sqrt(disc))).ub();
}

}  // namespace sillage

#include "sillage/missions/bathymetry_tubes.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "sillage/error.h"
#include "sillage/interval/elementary.h"
#include "sillage/tube/tube_arithmetic.h"
#include "sillage/tube/tube_integral.h"
#include "sillage/tube/tube_taylor.h"

namespace sillage {

namespace {

// Sample indices of the time points of td, and the fine domain between them.
struct Grid {
  std::vector<std::size_t> idx;  // sample index of each time point of td
  std::shared_ptr<TDomain> fine; // every sample from idx.front() to idx.back()
};

Grid grid_of(const BathymetryMission& m, const std::shared_ptr<TDomain>& td, const char* where) {
  if (!td) throw Error(std::string(where) + ": null TDomain");
  Grid g;
  for (double t : td->times()) {
    const std::ptrdiff_t i = m.sample_index(t);
    if (i < 0)
      throw Error(std::string(where) + ": time point " + std::to_string(t) +
                  " s of the TDomain is not a sample time of the mission; build it with mission.tdomain(dt)");
    g.idx.push_back(static_cast<std::size_t>(i));
  }
  const auto& ts = m.times();
  g.fine = TDomain::create(std::vector<double>(ts.begin() + static_cast<std::ptrdiff_t>(g.idx.front()),
                                               ts.begin() + static_cast<std::ptrdiff_t>(g.idx.back()) + 1));
  return g;
}

// From the fine tube to td: gates kept, slices the hull of the fine slices.
Tube coarsen(const Tube& f, const std::shared_ptr<TDomain>& td, const Grid& g) {
  const std::size_t N = td->nb_slices(), i0 = g.idx.front();
  std::vector<Interval> slices(N), gates(N + 1);
  for (std::size_t k = 0; k <= N; ++k) gates[k] = f.gate(g.idx[k] - i0);
  for (std::size_t k = 0; k < N; ++k) {
    Interval h = Interval::empty();
    for (std::size_t i = g.idx[k]; i < g.idx[k + 1]; ++i) h |= f.slice(i - i0);
    slices[k] = h;
  }
  return Tube(td, slices, gates);
}

TubeVector coarsen(const TubeVector& f, const std::shared_ptr<TDomain>& td, const Grid& g) {
  std::vector<Tube> c;
  for (std::size_t i = 0; i < f.size(); ++i) c.push_back(coarsen(f[i], td, g));
  return TubeVector(std::move(c));
}

// A sampled signal with per-sample bounds e_i and second-derivative bound a:
// gates m_i +- e_i; slices hull(gates) + a h^2/8.
Tube sampled_tube(const std::shared_ptr<TDomain>& fine, std::size_t i0, const std::vector<double>& meas,
                  const std::vector<Interval>& err, double accel2) {
  const std::size_t N = fine->nb_slices();
  std::vector<Interval> gates(N + 1), slices(N);
  for (std::size_t k = 0; k <= N; ++k) gates[k] = Interval(meas[i0 + k]) + err[i0 + k];
  for (std::size_t k = 0; k < N; ++k) {
    const Interval h = fine->slice_width(k);
    const Interval c = Interval(accel2) * sqr(h) / Interval(8);
    slices[k] = (gates[k] | gates[k + 1]) + Interval(-c.ub(), c.ub());
  }
  return Tube(fine, slices, gates);
}

Interval sym(const Interval& e) { return Interval(-e.ub(), e.ub()); }
Interval deg(double d) { return Interval(d) * Interval::pi() / Interval(180); }

// Sensor tubes on the fine domain.
TubeVector fine_sensor_tubes(const BathymetryMission& m, const Grid& g) {
  const auto& b = m.bounds();
  const auto& me = m.measured();
  const std::size_t n = m.nb_samples(), i0 = g.idx.front();
  const Interval a_ang = deg(b.angle_accel);
  std::vector<Interval> e_yaw(n, sym(deg(b.heading))), e_att(n, sym(deg(b.attitude))), e_v(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Interval speed = sqrt(sqr(Interval(me.vx[i])) + sqr(Interval(me.vy[i])) + sqr(Interval(me.vz[i])));
    e_v[i] = sym(Interval(b.dvl_scale) * speed + Interval(b.dvl_offset));
  }
  std::vector<Tube> c;
  c.push_back(sampled_tube(g.fine, i0, me.yaw, e_yaw, a_ang.ub()));
  c.push_back(sampled_tube(g.fine, i0, me.pitch, e_att, a_ang.ub()));
  c.push_back(sampled_tube(g.fine, i0, me.roll, e_att, a_ang.ub()));
  c.push_back(sampled_tube(g.fine, i0, me.vx, e_v, b.velocity_accel2));
  c.push_back(sampled_tube(g.fine, i0, me.vy, e_v, b.velocity_accel2));
  c.push_back(sampled_tube(g.fine, i0, me.vz, e_v, b.velocity_accel2));
  return TubeVector(std::move(c));
}

// w = R(psi, theta, phi) v (4.32), third component as a depth rate (down).
TubeVector fine_velocity(const TubeVector& s) {
  const Tube cp = cos(s[0]), sp = sin(s[0]), ct = cos(s[1]), st = sin(s[1]), cf = cos(s[2]), sf = sin(s[2]);
  const Tube &u = s[3], &v = s[4], &w = s[5];
  Tube w1 = ct * cp * u + (st * cp * sf - cf * sp) * v + (sp * sf + st * cp * cf) * w;
  Tube w2 = ct * sp * u + (cp * cf + st * sp * sf) * v + (st * cf * sp - cp * sf) * w;
  Tube w3 = st * u - ct * sf * v - ct * cf * w;  // depth rate = -(up rate)
  return TubeVector({std::move(w1), std::move(w2), std::move(w3)});
}

}  // namespace

TubeVector bathymetry_sensor_tubes(const BathymetryMission& m, const std::shared_ptr<TDomain>& td) {
  const Grid g = grid_of(m, td, "bathymetry_sensor_tubes");
  return coarsen(fine_sensor_tubes(m, g), td, g);
}

TubeVector bathymetry_velocity_tube(const BathymetryMission& m, const std::shared_ptr<TDomain>& td) {
  const Grid g = grid_of(m, td, "bathymetry_velocity_tube");
  return coarsen(fine_velocity(fine_sensor_tubes(m, g)), td, g);
}

TubeVector bathymetry_dead_reckoning(const BathymetryMission& m, const std::shared_ptr<TDomain>& td,
                                     const IntervalVector& x0) {
  if (x0.size() != 3)
    throw DimensionError("bathymetry_dead_reckoning: x0 must have 3 components (east, north, depth), got " +
                         std::to_string(x0.size()));
  const Grid g = grid_of(m, td, "bathymetry_dead_reckoning");
  const TubeVector w = fine_velocity(fine_sensor_tubes(m, g));
  std::vector<Tube> p;
  for (std::size_t i = 0; i < 2; ++i) p.push_back(coarsen(primitive(w[i], x0[i]), td, g));
  // Depth: the pressure sensor at every sample, the integrated rate in between.
  const std::size_t N = g.fine->nb_slices(), i0 = g.idx.front();
  const Interval e(-m.bounds().depth, m.bounds().depth);
  std::vector<Interval> inc(N), gates(N + 1);
  for (std::size_t k = 0; k < N; ++k) inc[k] = g.fine->slice_width(k) * w[2].slice(k);
  for (std::size_t k = 0; k <= N; ++k) gates[k] = Interval(m.measured().depth[i0 + k]) + e;
  p.push_back(coarsen(primitive_from_increments(w[2], inc, x0[2], gates), td, g));
  return TubeVector(std::move(p));
}

IntervalVector bathymetry_initial_box(const BathymetryMission& m, double horizontal) {
  if (!(horizontal >= 0) || !std::isfinite(horizontal))
    throw Error("bathymetry_initial_box: horizontal must be finite and >= 0");
  const Interval e(-horizontal, horizontal), d(-m.bounds().depth, m.bounds().depth);
  return {Interval(m.x1().front()) + e, Interval(m.x2().front()) + e, Interval(m.measured().depth.front()) + d};
}

double bathymetry_observation_rate_bound(const BathymetryMission& m) {
  // Per axis the bilinear DEM's slope is at most slope + 2 roughness / cell, so
  // its gradient norm at most sqrt(2) times that.
  const SeabedClass& c = m.seabed().bounds;
  const Interval g = sqrt(Interval(2)) * (Interval(c.slope) + Interval(2) * Interval(c.roughness) /
                                                                 Interval(m.dem().cell_size()));
  return (g * Interval(m.bounds().speed_max)).ub();
}

Tube bathymetry_observation_tube(const BathymetryMission& m, const std::shared_ptr<TDomain>& td) {
  const Grid g = grid_of(m, td, "bathymetry_observation_tube");
  const auto& b = m.bounds();
  const auto& me = m.measured();
  const std::size_t i0 = g.idx.front(), N = g.fine->nb_slices();
  const double cell = m.dem().cell_size();
  std::vector<Interval> gates(N + 1), slices(N);
  for (std::size_t k = 0; k <= N; ++k) {
    const std::size_t i = i0 + k;
    const double a = me.altitude[i];
    const double a_max = nadir_altitude_max(a, m.seabed().bounds, cell, b);
    const Interval e = Interval(b.altitude_scale) * Interval(std::abs(a)) + Interval(b.altitude_offset) +
                       Interval(footprint_filter_bound(m.seabed().bounds, cell, a_max, b)) + Interval(b.depth) +
                       Interval(b.tide);
    gates[k] = Interval(a) + Interval(me.depth[i]) - m.tide().height(Interval(m.times()[i])) + sym(e);
  }
  const double L = bathymetry_observation_rate_bound(m);
  for (std::size_t k = 0; k < N; ++k) {
    const Interval r = Interval(L) * g.fine->slice_width(k);
    // Max over the slice of min(a + L tau, b + L (h - tau)) = min(a + Lh, b + Lh, (a + b + Lh) / 2).
    const Interval &ga = gates[k], &gb = gates[k + 1];
    const double up = std::min({(Interval(ga.ub()) + r).ub(), (Interval(gb.ub()) + r).ub(),
                                ((Interval(ga.ub()) + Interval(gb.ub()) + r) / Interval(2)).ub()});
    const double lo = std::max({(Interval(ga.lb()) - r).lb(), (Interval(gb.lb()) - r).lb(),
                                ((Interval(ga.lb()) + Interval(gb.lb()) - r) / Interval(2)).lb()});
    slices[k] = Interval(lo, up);
  }
  return coarsen(Tube(g.fine, slices, gates), td, g);
}

TrajectoryVector bathymetry_truth(const BathymetryMission& m) {
  return TrajectoryVector({Trajectory(m.times(), m.x1()), Trajectory(m.times(), m.x2()),
                           Trajectory(m.times(), m.truth().depth)});
}

Trajectory bathymetry_truth_observation(const BathymetryMission& m) {
  std::vector<double> z(m.nb_samples());
  for (std::size_t i = 0; i < z.size(); ++i) z[i] = m.dem()(m.x1()[i], m.x2()[i]).mid();
  return Trajectory(m.times(), z);
}

}  // namespace sillage

#include "sillage/missions/bathymetry_mission.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sillage/error.h"
#include "sillage/missions/bathymetry_plan.h"
#include "sillage/missions/bathymetry_rng.h"

namespace sillage {

using detail::BathymetryPlan;
using detail::BathymetryRng;

namespace {

constexpr double kPi = 3.14159265358979323846, kDeg = kPi / 180;

double quantize(double x, double q) { return std::round(x / q) * q; }

void check_options(const BathymetryMissionOptions& o) {
  auto positive = [](double v, const char* name) {
    if (!(v > 0) || !std::isfinite(v))
      throw Error(std::string("BathymetryMission: option ") + name + " must be finite and > 0, got " + std::to_string(v));
  };
  positive(o.duration, "duration"), positive(o.step, "step"), positive(o.speed, "speed");
  positive(o.turn_radius, "turn_radius"), positive(o.rail_spacing, "rail_spacing"), positive(o.depth, "depth");
  if (o.rail_spacing >= 2 * o.turn_radius)
    throw Error("BathymetryMission: rail_spacing must be < 2 turn_radius (keyhole turns), got " +
                number_text(o.rail_spacing) + " >= 2 * " + number_text(o.turn_radius));
  if (!(o.tie_line_angle >= 0 && o.tie_line_angle <= 45))
    throw Error("BathymetryMission: tie_line_angle must be in [0, 45] degrees (0: no tie lines), got " +
                std::to_string(o.tie_line_angle));
  if (o.speed * 1.02 > o.bounds.speed_max)
    throw Error("BathymetryMission: speed " + number_text(o.speed) + " too close to the stated speed_max");
}

}  // namespace

BathymetryMission::BathymetryMission(std::uint64_t seed, const BathymetryMissionOptions& options)
    : seed_(seed), options_(options), seabed_((check_options(options), generate_seabed(seed, options.seabed))) {
  const auto& o = options_;
  detail::BathymetryRng rng(seed ^ 0x5eedba7f00dULL);
  const BathymetryPlan plan(o.seabed.size, o.speed, o.turn_radius, o.rail_spacing, o.depth, o.duration, o.transects,
                            o.tie_line_angle * kDeg);
  double ph[10];
  for (double& p : ph) p = rng.uniform(0, 2 * kPi);

  // The continuous truth signals.
  struct State {
    double yaw, pitch, roll, u, v, w;
  };
  auto signals = [&](double t) {
    const double r = plan.yaw_rate(t);
    State s;
    s.u = o.speed * (1 + 0.015 * std::sin(2 * kPi * t / 97 + ph[0]));
    s.v = 0.01 * std::sin(2 * kPi * t / 29 + ph[1]) - 0.3 * r;  // sideslip in turns
    s.w = 0.008 * std::sin(2 * kPi * t / 43 + ph[2]);
    s.yaw = plan.yaw(t) + 0.4 * kDeg * std::sin(2 * kPi * t / 41 + ph[3]) + 0.2 * kDeg * std::sin(2 * kPi * t / 13 + ph[4]);
    s.pitch = plan.depth_rate(t) / o.speed + 0.5 * kDeg * std::sin(2 * kPi * t / 53 + ph[5]);
    s.roll = 0.4 * kDeg * std::sin(2 * kPi * t / 37 + ph[6]) - 0.4 * r;  // banking in turns
    return s;
  };
  // World velocity (7.31) with the Euler matrix (4.32).
  auto world = [](const State& s, double out[3]) {
    const double cp = std::cos(s.yaw), sp = std::sin(s.yaw), ct = std::cos(s.pitch), st = std::sin(s.pitch),
                 cf = std::cos(s.roll), sf = std::sin(s.roll);
    out[0] = ct * cp * s.u + (-cf * sp + st * cp * sf) * s.v + (sp * sf + st * cp * cf) * s.w;
    out[1] = ct * sp * s.u + (cp * cf + st * sp * sf) * s.v + (-cp * sf + st * cf * sp) * s.w;
    out[2] = -st * s.u + ct * sf * s.v + ct * cf * s.w;
  };

  const std::size_t n = static_cast<std::size_t>(std::llround(o.duration / o.step));
  if (std::abs(static_cast<double>(n) * o.step - o.duration) > 1e-9 * o.duration)
    throw Error("BathymetryMission: duration must be a multiple of step");
  times_.resize(n + 1), x1_.resize(n + 1), x2_.resize(n + 1);
  for (auto* v : {&truth_.yaw, &truth_.pitch, &truth_.roll, &truth_.vx, &truth_.vy, &truth_.vz, &truth_.depth,
                  &truth_.altitude, &tide_truth_, &alt_filt_})
    v->resize(n + 1);
  double p[3] = {plan.start_x(), plan.start_y(), -o.depth};
  const double g = std::sqrt(0.6), gw[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9}, gx[3] = {-g, 0, g};
  const double tide_ph = rng.uniform(0, 2 * kPi);
  for (std::size_t i = 0; i <= n; ++i) {
    const double t = static_cast<double>(i) * o.step;
    times_[i] = t;
    const State s = signals(t);
    x1_[i] = p[0], x2_[i] = p[1];
    truth_.yaw[i] = s.yaw, truth_.pitch[i] = s.pitch, truth_.roll[i] = s.roll;
    truth_.vx[i] = s.u, truth_.vy[i] = s.v, truth_.vz[i] = s.w, truth_.depth[i] = -p[2];
    tide_truth_[i] = o.tide.height_value(t) + 0.04 * std::sin(2 * kPi * t / 5000 + tide_ph);
    const Interval seabed = seabed_.dem(p[0], p[1]);
    if (!std::isfinite(seabed.lb()) || !std::isfinite(seabed.ub()))
      throw Error("BathymetryMission: the path leaves the DEM at t = " + number_text(t) + " s");
    truth_.altitude[i] = seabed.mid() + tide_truth_[i] + p[2];
    if (!(truth_.altitude[i] > 0))
      throw Error("BathymetryMission: the seabed (" + std::to_string(seabed.mid()) + " m deep) rises above the vehicle (" +
                  number_text(-p[2]) + " m deep) at t = " + number_text(t) +
                  " s; lower options.depth or options.seabed.relief");
    alt_filt_[i] = footprint_depth(seabed_.dem, p[0], p[1], s.yaw, truth_.altitude[i], o.bounds) + tide_truth_[i] + p[2];
    if (i == n) break;
    double acc[3] = {0, 0, 0}, wv[3];
    for (int q = 0; q < 3; ++q) {
      world(signals(t + o.step / 2 * (1 + gx[q])), wv);
      for (int c = 0; c < 3; ++c) acc[c] += gw[q] * wv[c];
    }
    for (int c = 0; c < 3; ++c) p[c] += o.step / 2 * acc[c];
  }

  // Measurements, one independent stream per sensor.
  detail::BathymetryRng ins = rng.fork(1), dvl = rng.fork(2), prs = rng.fork(3), alt = rng.fork(4);
  const double b_yaw = ins.uniform(-0.02, 0.02) * kDeg, b_pitch = ins.uniform(-0.015, 0.015) * kDeg,
               b_roll = ins.uniform(-0.015, 0.015) * kDeg;
  double dvl_scale[3], dvl_off[3];
  for (int c = 0; c < 3; ++c) dvl_scale[c] = dvl.uniform(-0.0012, 0.0012), dvl_off[c] = dvl.uniform(-0.0003, 0.0003);
  const double b_depth = prs.uniform(-0.01, 0.01), alt_scale = alt.uniform(-0.004, 0.004);
  for (auto* v : {&meas_.yaw, &meas_.pitch, &meas_.roll, &meas_.vx, &meas_.vy, &meas_.vz, &meas_.depth, &meas_.altitude})
    v->resize(n + 1);
  for (std::size_t i = 0; i <= n; ++i) {
    meas_.yaw[i] = quantize(truth_.yaw[i] + b_yaw + ins.uniform(-0.015, 0.015) * kDeg, 1e-5);
    meas_.pitch[i] = quantize(truth_.pitch[i] + b_pitch + ins.uniform(-0.015, 0.015) * kDeg, 1e-5);
    meas_.roll[i] = quantize(truth_.roll[i] + b_roll + ins.uniform(-0.015, 0.015) * kDeg, 1e-5);
    const double v[3] = {truth_.vx[i], truth_.vy[i], truth_.vz[i]};
    double* m[3] = {&meas_.vx[i], &meas_.vy[i], &meas_.vz[i]};
    for (int c = 0; c < 3; ++c)
      *m[c] = quantize(v[c] * (1 + dvl_scale[c]) + dvl_off[c] + dvl.uniform(-0.0003, 0.0003), 1e-4);
    meas_.depth[i] = quantize(truth_.depth[i] + b_depth + prs.uniform(-0.02, 0.02), 0.01);
    meas_.altitude[i] = quantize(alt_filt_[i] * (1 + alt_scale) + alt.uniform(-0.02, 0.02), 0.01);
  }
}

BathymetryMissionOptions bank_mission_options() {
  BathymetryMissionOptions o;
  o.seabed = bank_seabed_options();
  o.transects = true;
  o.bounds.beam_angle = 0;
  o.bounds.beam_spread = 3;
  return o;
}

double BathymetryMission::path_length() const {
  double s = 0;
  for (std::size_t i = 1; i < x1_.size(); ++i) s += std::hypot(x1_[i] - x1_[i - 1], x2_[i] - x2_[i - 1]);
  return s;
}

std::ptrdiff_t BathymetryMission::sample_index(double t) const {
  const auto it = std::lower_bound(times_.begin(), times_.end(), t);
  return it != times_.end() && *it == t ? it - times_.begin() : -1;
}

std::shared_ptr<TDomain> BathymetryMission::tdomain(double dt) const {
  const double m = dt / options_.step;
  const auto k = static_cast<std::size_t>(std::llround(m));
  if (!(dt > 0) || k == 0 || std::abs(m - static_cast<double>(k)) > 1e-9)
    throw Error("BathymetryMission.tdomain: dt must be a positive multiple of the sensor step " +
                number_text(options_.step) + " s, got " + number_text(dt));
  std::vector<double> ts;
  for (std::size_t i = 0; i < times_.size(); i += k) ts.push_back(times_[i]);
  if (ts.back() != times_.back()) ts.push_back(times_.back());
  return TDomain::create(std::move(ts));
}

std::string repr(const BathymetryMission& m) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "BathymetryMission(seed=%llu, %g s at %g s, %zu samples, path %.0f m)",
                static_cast<unsigned long long>(m.seed()), m.options().duration, m.options().step, m.nb_samples(),
                m.path_length());
  return buf;
}

}  // namespace sillage

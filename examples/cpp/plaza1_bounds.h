#pragma once
// The error bounds of the plaza1 examples (plaza1 and loops_plaza1), in one
// table: value, unit, option to override it, and where it comes from. Every
// value is stated from the class of the robot and of its sensors, never read
// off the data file it is applied to (docs/plaza1.md: "The error bounds").
// A robot of the same class drives at most 2 m/s, has a track of about 1 m,
// a low-cost heading (MEMS gyro or wheel odometry), wheel odometry and an RF
// ranging radio, logged by an ordinary PC.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "bound_audit.h"
#include "example_args.h"
#include "plaza1_data.h"

namespace plaza1 {

struct Bounds {
  // The start pose: NaN = the first ground-truth sample (a surveyed start mark).
  double start_x = NAN, start_y = NAN, start_heading = NAN;
  double pos0 = 0.1;        // m
  double heading0 = 0.05;   // rad
  double gyro_bias = 10.5e-3;  // rad/s: |b(t)| at any time, and the turn-on bias b0 (0.3 deg/s class, times 2)
  double gyro_drift = 1e-3; // rad/s: in-run variation |b(t) - b0| (CtcBiasedIncrement)
  double turn_max = 4.0;    // rad/s
  double dist_rel = 0.02;   // odometer scale error
  double dist_over = 0.1;   // m per period counted but not travelled
  double dist_under = 0.01; // m per period travelled but not counted
  double speed_max = 6.0;   // m/s, per time-stamped period
  double range_short = 1.5; // m: measured - true >= -range_short
  double range_long = 10.0; // m: measured - true <= range_long
  double time_err = 0.2;    // s: time stamps of the ranges
  double track = 0.05;      // rad: direction of travel vs heading
  double turn_accel = 20.0; // rad/s^2: the turn inside a period (CtcHeadingWindow)
};

struct BoundSpec {
  const char* option;  // "--name", a number
  const char* name;
  const char* unit;
  double Bounds::*field;
  const char* source;  // where the value comes from, and its margin
};

// The table (docs/plaza1.md prints the same one).
inline const std::vector<BoundSpec>& bound_table() {
  static const std::vector<BoundSpec> t = {
      {"--start-x", "start x", "m", &Bounds::start_x, "default: the first ground-truth sample (a surveyed mark)"},
      {"--start-y", "start y", "m", &Bounds::start_y, "default: the first ground-truth sample"},
      {"--start-heading", "start heading", "rad", &Bounds::start_heading, "default: the first ground-truth sample"},
      {"--start-pos-err", "start position", "m", &Bounds::pos0, "robot set on a surveyed mark by hand"},
      {"--start-heading-err", "start heading", "rad", &Bounds::heading0, "robot aligned by eye on a surveyed line, 3 deg"},
      {"--gyro-turn-on-bias", "gyro turn-on bias", "rad/s", &Bounds::gyro_bias,
       "low-cost MEMS rate gyro, no calibration beyond its power-up null: bias up to 0.3 deg/s (5.2 mrad/s) at any "
       "time, the top of the rate grade (10 to 1000 deg/h; commercial grade 0.1 deg/s), times 2: 0.6 deg/s; "
       "one unknown constant b0 from turn-on (bias repeatability of the class)"},
      {"--gyro-in-run-drift", "gyro in-run drift", "rad/s", &Bounds::gyro_drift,
       "variation of the bias during a 30 min run after turn-on, temperature-compensated MEMS gyro: bias instability "
       "<= 10 deg/h (0.05 mrad/s) + temperature sensitivity <= 0.005 deg/s/degC over a 5 degC change (0.44 mrad/s), "
       "times 2: 1 mrad/s; --gyro-in-run-drift equal to --gyro-turn-on-bias is the bias free at every step"},
      {"--turn-max", "turn rate", "rad/s", &Bounds::turn_max,
       "differential drive, wheels <= 2 m/s, track ~1 m: spinning in place at most 2 * 2 / 1 = 4 rad/s"},
      {"--odo-scale", "odometer scale", "", &Bounds::dist_rel, "wheel radius with tyre load and pressure, +-2 %"},
      {"--odo-over", "odometer over-count", "m/period", &Bounds::dist_over,
       "wheel slip: a wheel spinning at 0.5 m/s for a whole 0.2 s period"},
      {"--odo-under", "odometer under-count", "m/period", &Bounds::dist_under,
       "sliding or pushed with the wheels still: 5 cm/s over 0.2 s"},
      {"--speed-max", "speed per stamped period", "m/s", &Bounds::speed_max,
       "2 m/s robot class; a 0.2 s period may last 0.2 + 2 * 0.2 s of time-stamp jitter: 2 * 3 = 6 m/s"},
      {"--range-short", "range short error", "m", &Bounds::range_short,
       "RF ranging is never short by more than the antenna offsets (robot and beacon, 0.5 m each) and the noise "
       "(0.5 m)"},
      {"--range-long", "range long error", "m", &Bounds::range_long,
       "RF ranging is biased long: uncalibrated radio delay, multipath and non-line-of-sight, up to 10 m in an open "
       "plaza"},
      {"--time-jitter", "time-stamp error", "s", &Bounds::time_err,
       "logging PC (not real-time): reports of a serial radio reach it up to 0.2 s late or early"},
      {"--track-err", "track error", "rad", &Bounds::track,
       "direction of travel vs heading: side slip of a wheeled robot and heading noise, 3 deg"},
      {"--turn-accel", "turn acceleration", "rad/s^2", &Bounds::turn_accel,
       "tyre grip (friction coefficient <= 1): each wheel accelerates at most 9.8 m/s^2, so on a 1 m track the turn "
       "rate changes by at most 2 * 9.8 / 1 = 20 rad/s^2"},
  };
  return t;
}

// The options of the table, for example::program_options().
inline std::vector<std::string> bound_options() {
  std::vector<std::string> r;
  for (const auto& s : bound_table()) r.push_back(std::string(s.option) + "=X");
  return r;
}

// The start of `b` from the first ground-truth sample where not given.
inline Bounds with_start(Bounds b, const example::Plaza1Data& d) {
  if (std::isnan(b.start_x)) b.start_x = d.x[0];
  if (std::isnan(b.start_y)) b.start_y = d.y[0];
  if (std::isnan(b.start_heading)) b.start_heading = d.heading[0];
  return b;
}

// An unknown start: anywhere within 10 m of the beacons' bounding box (the
// area they were set around), any heading.
inline Bounds unknown_start(Bounds b, const example::Plaza1Data& d) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const auto& [id, xy] : d.beacons) {
    x0 = std::min(x0, xy.first), x1 = std::max(x1, xy.first), y0 = std::min(y0, xy.second), y1 = std::max(y1, xy.second);
  }
  b.start_x = (x0 + x1) / 2, b.start_y = (y0 + y1) / 2, b.pos0 = std::max(x1 - x0, y1 - y0) / 2 + 10;
  b.start_heading = 0, b.heading0 = M_PI;
  return b;
}

// The bounds, each overridden by its option; the start defaults to the first
// ground-truth sample (--unknown-start 1: unknown_start).
inline Bounds bounds_from_args(int argc, char** argv, const example::Plaza1Data& d) {
  Bounds b;
  const auto accepted = example::accepted_options(example::program_name(argc > 0 ? argv[0] : nullptr));
  for (const auto& s : bound_table()) {
    if (std::find(accepted.begin(), accepted.end(), std::string(s.option) + "=X") == accepted.end()) {
      throw std::logic_error(std::string("plaza1 bound option ") + s.option + " missing from program_options()");
    }
    b.*s.field = example::option_number(argc, argv, s.option, b.*s.field);
    // Every bound but the start's coordinates is a magnitude: a negative one is a typo, not a model.
    const bool coordinate = s.field == &Bounds::start_x || s.field == &Bounds::start_y || s.field == &Bounds::start_heading;
    if (!coordinate && !(b.*s.field >= 0)) {
      example::usage_error(example::program_name(argc > 0 ? argv[0] : nullptr),
                           std::string("option ") + s.option + " is an error bound (" + s.name + "), expected >= 0, got " +
                               std::to_string(b.*s.field));
    }
  }
  if (example::option_number(argc, argv, "--unknown-start", 0) != 0) b = unknown_start(b, d);
  return with_start(b, d);
}

inline double wrap(double a) { return std::remainder(a, 2 * M_PI); }

// How much of each bound the ground truth used (it changes no bound).
inline std::vector<example::AuditLine> audit(const example::Plaza1Data& d, const Bounds& b) {
  std::vector<example::AuditLine> r;
  const std::size_t n = d.dist.size();
  r.push_back({"start position", "m", b.pos0, std::max(std::abs(d.x[0] - b.start_x), std::abs(d.y[0] - b.start_y)),
               "start vs truth"});
  r.push_back({"start heading", "rad", b.heading0, std::abs(wrap(d.heading[0] - b.start_heading)), "start vs truth"});
  // The gyro: e(t) = odometry heading (summed from the start) - truth = e(t0) + b0 (t - t0) + drift.
  // Turn-on bias: the least-squares slope of e (the truth's b0). In-run drift: the smallest d with
  // |e(t) - e(t0) - b0 (t - t0)| <= heading0 + d (t - t0) (the start error allowed, as for the bias before).
  // e is unwrapped (it changes by far less than pi from one sample to the next): a bias of a few mrad/s
  // adds several turns over a run, which a wrapped e would fold into (-pi, pi].
  std::vector<double> e(n + 1, 0.0);
  double psi = d.heading[0], turn = 0, st = 0, se = 0, stt = 0, ste = 0;
  for (std::size_t k = 0; k <= n; ++k) {
    if (k > 0) psi += d.dpsi_drift[k - 1];
    e[k] = k == 0 ? wrap(psi - d.heading[0]) : e[k - 1] + wrap(psi - d.heading[k] - e[k - 1]);
    const double t = d.t[k] - d.t[0];
    st += t, se += e[k], stt += t * t, ste += t * e[k];
    if (k < n) turn = std::max(turn, std::abs(wrap(d.heading[k + 1] - d.heading[k])) / (d.t[k + 1] - d.t[k]));
  }
  const double m = static_cast<double>(n + 1), b0 = (m * ste - st * se) / (m * stt - st * st);
  double drift = 0;
  for (std::size_t k = 1; k <= n; ++k) {
    const double t = d.t[k] - d.t[0];
    drift = std::max(drift, (std::abs(e[k] - e[0] - b0 * t) - b.heading0) / t);
  }
  r.push_back({"gyro turn-on bias", "rad/s", b.gyro_bias, std::abs(b0),
               "least-squares slope of odometry heading - truth"});
  r.push_back({"gyro in-run drift", "rad/s", b.gyro_drift, drift,
               "(|heading error - slope (t - t0)| - start error) / (t - t0)"});
  r.push_back({"turn rate", "rad/s", b.turn_max, turn, "true heading change per period"});
  double accel = 0;  // change of the mean turn rate between neighbouring periods
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double w0 = wrap(d.heading[k + 1] - d.heading[k]) / (d.t[k + 1] - d.t[k]);
    const double w1 = wrap(d.heading[k + 2] - d.heading[k + 1]) / (d.t[k + 2] - d.t[k + 1]);
    accel = std::max(accel, std::abs(w1 - w0) / ((d.t[k + 2] - d.t[k]) / 2));
  }
  r.push_back({"turn acceleration", "rad/s^2", b.turn_accel, accel,
               "change of the true mean turn rate between neighbouring periods"});
  // The odometer: the straight-line truth step c_k is at most the path length.
  double dist = 0, chord = 0, under = 0, still = 0, speed = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double c = std::hypot(d.x[k + 1] - d.x[k], d.y[k + 1] - d.y[k]);
    dist += d.dist[k], chord += c;
    under = std::max(under, c - d.dist[k] * (1 + b.dist_rel));
    if (c < 0.01) still = std::max(still, d.dist[k] * (1 - b.dist_rel) - c);
    speed = std::max(speed, std::max(c, d.dist[k]) / (d.t[k + 1] - d.t[k]));
  }
  r.push_back({"odometer scale", "", b.dist_rel, std::abs(chord / dist - 1), "whole run, truth steps / odometry"});
  r.push_back({"odometer over-count", "m/period", b.dist_over, still, "periods where the truth moves < 1 cm"});
  r.push_back({"odometer under-count", "m/period", b.dist_under, std::max(under, 0.0),
               "truth step beyond the odometry (a lower bound of the need)"});
  r.push_back({"speed per stamped period", "m/s", b.speed_max, speed, "odometry and truth steps per stamped period"});
  // Ranges against the truth interpolated at the range time stamps.
  double lo = 0, hi = 0;
  for (std::size_t j = 0; j < d.rt.size(); ++j) {
    const auto it = std::upper_bound(d.t.begin(), d.t.end(), d.rt[j]);
    if (it == d.t.begin() || it == d.t.end()) continue;
    const std::size_t k = static_cast<std::size_t>(it - d.t.begin()) - 1;
    const double a = (d.rt[j] - d.t[k]) / (d.t[k + 1] - d.t[k]);
    const double x = d.x[k] + a * (d.x[k + 1] - d.x[k]), y = d.y[k] + a * (d.y[k + 1] - d.y[k]);
    const auto [bx, by] = d.beacons.at(static_cast<int>(d.rid[j]));
    const double e = d.r[j] - std::hypot(x - bx, y - by);
    lo = std::min(lo, e), hi = std::max(hi, e);
  }
  r.push_back({"range short error", "m", b.range_short, -lo, "measured - true, truth at the stamp"});
  r.push_back({"range long error", "m", b.range_long, hi, "measured - true, truth at the stamp"});
  r.push_back({"time-stamp error", "s", b.time_err, NAN, "the truth shares the clock of the data"});
  return r;
}

// Direction of travel of the truth against its own heading: over each
// stretch of at least 1 m from sample k (shorter ones are dominated by the
// position noise of the truth), the direction of the straight line from its
// start to its end against the hull of the headings over the stretch
// (deviation[k], rad; 0 if the stretch is left out). Stretches with a period
// below `reverse_below` (the robot may back up) or above `glitch_above` (a
// time-stamp glitch) are left out; end[k] is the last sample of the stretch.
struct TrackDeviation {
  std::vector<double> deviation;
  std::vector<std::size_t> end;
};

inline TrackDeviation track_deviation(const example::Plaza1Data& d, double reverse_below, double glitch_above) {
  const std::size_t n = d.dist.size();
  TrackDeviation r{std::vector<double>(n + 1, 0.0), std::vector<std::size_t>(n + 1, 0)};
  for (std::size_t k = 0; k < n; ++k) {
    double lo = 0, hi = 0, h = 0;  // headings relative to d.heading[k]
    r.end[k] = k;
    for (std::size_t m = k; m < n; ++m) {
      const double speed = d.dist[m] / (d.t[m + 1] - d.t[m]);
      if (speed < reverse_below || speed > glitch_above) break;
      h += wrap(d.heading[m + 1] - d.heading[m]);
      lo = std::min(lo, h), hi = std::max(hi, h);
      const double dx = d.x[m + 1] - d.x[k], dy = d.y[m + 1] - d.y[k];
      if (std::hypot(dx, dy) < 1.0) continue;
      const double a = wrap(std::atan2(dy, dx) - d.heading[k]);
      r.deviation[k] = std::max({0.0, lo - a, a - hi});
      r.end[k] = m + 1;
      break;
    }
  }
  return r;
}

inline example::AuditLine track_audit(const example::Plaza1Data& d, double track, double reverse_below,
                                      double glitch_above) {
  const TrackDeviation t = track_deviation(d, reverse_below, glitch_above);
  return {"direction of travel vs heading", "rad", track, *std::max_element(t.deviation.begin(), t.deviation.end()),
          "truth over stretches of 1 m at speeds between the reverse and glitch speeds"};
}

}  // namespace plaza1

// Loops on real data: UTIAS MRCLAM dataset 7 (../shared/data/utias-mrclam7,
// read in place). Five small robots wander in a 15 m x 8 m room for 15 min
// and cross their own paths 10 to 49 times. Their only odometry is the
// velocity they were commanded (v, ω at about 65 Hz), not a measurement: the
// bounds must hold the motion the Vicon ground truth shows, and commands say
// little about it. The t-plane (thesis ch. 6) runs on the velocity tube they
// give, and the ground truth checks the bounds and the proofs, as in
// loops_plaza1. docs/loops_real_data.md gives the model, why, and results.
//
// Usage: example_loops_utias [--data DIR] [--robot N] [--out DIR]
// (N in 1..5; all five robots by default).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "example_data.h"
#include "bound_audit.h"
#include "loops_figures.h"
#include "loops_real_data.h"
#include "sillage/io/csv.h"

using namespace sillage;
namespace fs = std::filesystem;

namespace {

// The error model, and why (measured over the five robots, docs/loops_real_data.md).
struct Bounds {
  double dt = 0.1;  // s: slice width
  // Speed ∈ [0, (1 + a) v_lag + b], v_lag the largest command of the last
  // `lag` seconds: the robots follow a speed command with a delay and coast
  // briefly after a stop (up to 0.04 m/s with a zero command); they never back up.
  double lag = 1.0, speed_rel = 0.2, speed_abs = 0.01;
  // Heading ∈ ψ̂ + [-e, e], e = start + rate (t - t0), ψ̂ the integral of the
  // commanded turn rates from the true initial heading. The turn actually
  // made is 0.5 to 1.3 times the command (5 s windows turning over 0.5 rad),
  // |ψ̂ - ψ| reaches 4 rad, and |ψ̂ - ψ| / (t - t0) up to 0.016 rad/s: the
  // bound holds over the five runs with 0.06 rad to spare.
  double heading_start = 0.2, heading_rate = 0.02;
};

struct Robot {
  example::Path truth;           // Vicon, about 100 Hz
  std::vector<double> heading;   // Vicon heading, unwrapped
  std::vector<double> ct, v, w;  // commands, each held until the next
};

Robot load_robot(const fs::path& dir) {
  Robot r;
  const CsvTable gt = CsvTable::read((dir / "ground_truth.csv").string());
  const CsvTable od = CsvTable::read((dir / "odometry.csv").string());
  r.truth = {gt.values("t_s"), gt.values("x_m"), gt.values("y_m")};
  r.heading = gt.values("heading_rad");
  if (gt.nb_rows() < 2) throw Error(gt.source() + ": " + std::to_string(gt.nb_rows()) + " rows, expected at least 2");
  for (std::size_t i = 1; i < r.truth.t.size(); ++i) {
    if (!(r.truth.t[i] > r.truth.t[i - 1])) throw Error(gt.where(i) + ": the times must increase");
  }
  for (std::size_t i = 1; i < r.heading.size(); ++i) {
    r.heading[i] -= 2 * M_PI * std::round((r.heading[i] - r.heading[i - 1]) / (2 * M_PI));
  }
  r.ct = od.values("t_s"), r.v = od.values("v_mps"), r.w = od.values("omega_radps");
  // A few commands share a time stamp (up to 11 per robot): the last one holds.
  std::size_t m = 0;
  for (std::size_t i = 0; i < r.ct.size(); ++i) {
    if (m > 0 && r.ct[i] < r.ct[m - 1]) throw Error(od.where(i) + ": the times decrease");
    if (m > 0 && r.ct[i] == r.ct[m - 1]) --m;
    r.ct[m] = r.ct[i], r.v[m] = r.v[i], r.w[m] = r.w[i], ++m;
  }
  r.ct.resize(m), r.v.resize(m), r.w.resize(m);
  if (r.ct.size() < 2 || r.ct.front() < r.truth.t.front() || r.ct.front() + 1 >= r.truth.t.back()) {
    throw Error("utias: the commands must start within the ground-truth time span (" + dir.string() + ")");
  }
  return r;
}

// Linear interpolation of a sampled value at t (inside the samples).
double interpolate(const std::vector<double>& ts, const std::vector<double>& xs, double t) {
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(ts.begin(), ts.end(), t) - ts.begin());
  if (i == 0) return xs.front();
  if (i == ts.size()) return xs.back();
  return xs[i - 1] + (xs[i] - xs[i - 1]) * (t - ts[i - 1]) / (ts[i] - ts[i - 1]);
}

// The velocity tube; with `audit`, also how much of the heading bound the
// Vicon truth used (bound_audit.h; it changes no bound). The speed bound is
// not audited per slice: the Vicon reference point is off the wheel axis and
// moves while a robot turns on the spot (the 2 cm tolerance of the check).
TubeVector utias_velocity(const Robot& r, const std::shared_ptr<TDomain>& td, const Bounds& b,
                          std::vector<example::AuditLine>* audit = nullptr) {
  double heading_used = 0;
  const std::size_t n = td->nb_slices();
  std::vector<Interval> speed(n), heading(n);
  // ψ̂ is piecewise linear (commands held): over a slice its hull is that of
  // its values at the slice ends and at the command times inside.
  Interval psi(interpolate(r.truth.t, r.heading, r.ct.front()));
  std::size_t j = 0;  // the command active at the current time
  double now = td->t0();
  for (std::size_t k = 0; k < n; ++k) {
    const double end = td->t(k + 1);
    Interval hull = psi;
    while (now < end) {
      const double next = (j + 1 < r.ct.size()) ? std::min(r.ct[j + 1], end) : end;
      psi += Interval(r.w[j]) * (Interval(next) - Interval(now));
      hull |= psi;
      now = next;
      if (j + 1 < r.ct.size() && now >= r.ct[j + 1]) ++j;
    }
    const double e = b.heading_start + b.heading_rate * (end - td->t0());
    heading[k] = hull + Interval(-e, e);
    // The largest command active during [t_k - lag, t_{k+1}].
    const double from = td->t(k) - b.lag;
    std::size_t i = static_cast<std::size_t>(std::upper_bound(r.ct.begin(), r.ct.end(), from) - r.ct.begin());
    i = i > 0 ? i - 1 : 0;
    double vmax = 0;
    for (; i < r.ct.size() && r.ct[i] < end; ++i) vmax = std::max(vmax, r.v[i]);
    speed[k] = Interval(0, (Interval(vmax) * (1 + b.speed_rel) + b.speed_abs).ub());
    if (audit) {
      const double err = std::abs(interpolate(r.truth.t, r.heading, end) - psi.mid()) - b.heading_start;
      heading_used = std::max(heading_used, err / (end - td->t0()));
    }
  }
  if (audit) {
    audit->push_back({"heading drift", "rad/s", b.heading_rate, heading_used,
                      "(|commanded heading - Vicon| - start error) / (t - t0), at the slice ends"});
  }
  return example::velocity_tube(td, speed, heading);
}

// The samples of a path within [t0, tf].
example::Path within(const example::Path& p, double t0, double tf) {
  example::Path r;
  for (std::size_t i = 0; i < p.t.size(); ++i) {
    if (p.t[i] < t0 || p.t[i] > tf) continue;
    r.t.push_back(p.t[i]), r.x.push_back(p.x[i]), r.y.push_back(p.y[i]);
  }
  return r;
}

}  // namespace

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  const std::string robot = example::option_value(argc, argv, "--robot", "0");
  const int only = robot.size() == 1 && robot[0] >= '0' && robot[0] <= '5' ? robot[0] - '0' : -1;
  if (only < 0) {
    std::fprintf(stderr, "loops_utias: --robot must be 1..5 (0: all five), got '%s'\n", robot.c_str());
    return 2;
  }
  std::vector<std::string> files;
  for (int id = 1; id <= 5; ++id) {
    if (only != 0 && id != only) continue;
    for (const char* f : {"ground_truth.csv", "odometry.csv"}) files.push_back("robot" + std::to_string(id) + "/" + f);
  }
  const auto data = example::data_dir(argc, argv, "loops_utias", "utias-mrclam7", files);
  if (!data) return 0;
  const fs::path& dir = *data;
  const Bounds b;
  // Vicon is accurate to about 1 mm; the tolerance also covers its jitter
  // while the robot stands (commands at 0 for more than `lag`). Crossing
  // times: the largest gap between Vicon samples is 0.32 s.
  const double tol_m = 0.02, tol_s = 0.35;
  bool ok = true;
  std::string summary;
  std::vector<std::pair<std::string, std::string>> figures;
  for (int id = 1; id <= 5; ++id) {
    if (only != 0 && id != only) continue;
    const Robot r = load_robot(dir / ("robot" + std::to_string(id)));
    // From the first command to the end of the ground truth (or of the commands).
    const auto td = TDomain::create(r.ct.front(), std::min(r.ct.back(), r.truth.t.back()), b.dt);
    const double eps = (td->tf() - td->t0()) / 2000;
    const example::Path truth = within(r.truth, td->t0(), td->tf());
    // Crossings counted as in the data README: points at least 5 cm apart.
    const example::Path thin = example::thinned(truth, 0.05);
    const auto crossings = self_crossings(thin.t, thin.x, thin.y);
    std::vector<example::AuditLine> audit;
    const TubeVector v = utias_velocity(r, td, b, &audit);
    ok = example::print_audit("loops_utias robot " + std::to_string(id), audit) && ok;
    const auto ic = example::check_integrals(v, truth, example::check_pairs(truth, 100, 5.0, 10), crossings, tol_m);
    const example::LoopRun run = example::run_loops(td, eps, v, crossings, tol_s);
    const sillage::TPlane& tp = run.tplane;
    const example::LoopCheck& lc = run.check;
    char label[200];
    std::snprintf(label, sizeof label, "robot %d: %zu slices, eps = %.3f s, heading unknown (+-pi) after t0 + %.0f s",
                  id, td->nb_slices(), eps, (M_PI - b.heading_start) / b.heading_rate);
    example::print_loops(label, run, ic, tol_m);
    ok = ok && example::passed(lc) && ic.nb_inside_tol == ic.nb_pairs;
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  "robot %d: %zu detections (%zu complete), %zu proofs T, %zu N, %zu/%zu crossings in proofs, %.2f s; ",
                  id, tp.nb_detections(), tp.nb_complete_detections(), tp.nb_proofs(), tp.nb_newton_proofs(),
                  lc.in_proven, lc.nb_crossings, run.seconds);
    summary += buf;
    const double x0 = interpolate(r.truth.t, r.truth.x, td->t0()), y0 = interpolate(r.truth.t, r.truth.y, td->t0());
    example::save_loop_figures(tp, truth, IntervalVector{{x0, x0}, {y0, y0}}, crossings, out,
                               "loops_utias_robot" + std::to_string(id), "UTIAS robot " + std::to_string(id), 2.0,
                               figures);
  }
  example::print_result("loops_utias", summary, ok, figures);
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }

// Loops on real data: CMU "Plaza 1" (../shared/data/plaza1, read in place).
// A robot sweeps a plaza in a lawn-mower pattern and crosses its own path
// about 200 times. From the odometry alone (a distance per 0.2 s period and
// a heading), the t-plane (thesis ch. 6) detects the loops, and the degree
// test T and the Newton test N prove some; the ground truth checks both the
// bounds (integral check) and the proofs (loop check). Two headings:
//   (a) INS: the distributed heading increments, which equal those of the
//       INS/GPS ground truth, i.e. an INS-quality heading, with a small bound;
//   (b) gyro: a realistic drifting heading, with a bound that grows with time
//       (a gyro bias, as in docs/plaza1.md).
// docs/loops_real_data.md gives the error model, why each bound, and results.
//
// Usage: example_loops_plaza1 [--data DIR] [--eps-div N] [--out DIR]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "example_args.h"
#include "loops_figures.h"
#include "loops_real_data.h"
#include "plaza1_data.h"

using namespace sillage;
namespace fs = std::filesystem;

namespace {

// Speed: the odometer distance per period with a scale error and offsets,
// and two rules for what the odometer cannot say.
struct SpeedBounds {
  double dist_rel;    // odometer scale error
  double dist_over;   // m per period counted but not travelled (wheel slip at standstill)
  double dist_under;  // m per period travelled but not counted
  // The odometer distance is unsigned. The robot backs up now and then (by
  // up to 0.5 m at a time in this run, at odometry speeds up to 0.37 m/s
  // outside the glitches below): below this speed it may go either way.
  double reverse_below = 0.5;  // m/s
  // Above this speed (the 99th percentile is 1.67 m/s) a period is a
  // time-stamp glitch (README of the data): its motion is not trusted to
  // follow the heading, any direction is allowed.
  double glitch_above = 2.0;  // m/s
};

// Heading ψ ∈ ψ̂ + [-e(t), e(t)], e(t) = track + start + drift_rate (t - t0),
// over a period: around the hull of ψ̂ at its two ends (the heading is taken
// as monotone within 0.2 s; the margin absorbs the rest).
struct HeadingBounds {
  bool ins;           // the INS-quality increments, or the drifting ones
  double track;       // rad: direction of travel vs heading (skid, INS lever arm, ground-truth noise)
  double start;       // rad: initial heading error
  double drift_rate;  // rad/s: gyro bias
};

struct Model {
  const char* tag;
  const char* name;
  SpeedBounds speed;
  HeadingBounds heading;
};

// docs/loops_real_data.md says why each bound.
const Model kModels[] = {
    // The odometer model of docs/plaza1.md; the ground-truth heading leads the
    // direction of travel by 0.016 rad (median) and their difference is within
    // 0.067 rad on 90 % of the periods.
    {"ins_wide",
     "(a) INS heading +-0.05 rad, odometer d (1 +- 2 %) - 7 cm",
     {0.02, 0.07, 0.001},
     {true, 0.05, 0.0, 0.0}},
    // Tight bounds: the ground truth still agrees with them to within 0.85 m
    // over every pair of times (the integral check says how).
    {"ins_tight",
     "(a) INS heading +-0.01 rad, odometer d (1 +- 0.5 %) - 5 mm",
     {0.005, 0.005, 0.001},
     {true, 0.01, 0.0, 0.0}},
    // The drifting heading: docs/plaza1.md, |drifting - true heading| <=
    // 0.05 + 0.0005 t over the run (the drift is -0.35 mrad/s on average).
    {"gyro",
     "(b) drifting heading +-(0.06 + 0.0005 t) rad, odometer d (1 +- 0.5 %) - 5 mm",
     {0.005, 0.005, 0.001},
     {false, 0.01, 0.05, 5e-4}},
};

TubeVector plaza1_velocity(const example::Plaza1Data& d, const std::shared_ptr<TDomain>& td, const Model& m) {
  const SpeedBounds& sb = m.speed;
  const HeadingBounds& hb = m.heading;
  const std::size_t n = td->nb_slices();
  const std::vector<double>& dpsi = hb.ins ? d.dpsi_ins : d.dpsi_drift;
  std::vector<Interval> speed(n), heading(n);
  Interval psi(d.heading[0]);  // ψ̂(t_k), summed with outward rounding
  for (std::size_t k = 0; k < n; ++k) {
    const Interval dt = td->slice_width(k);
    const Interval next = psi + Interval(dpsi[k]);
    const double e = hb.track + hb.start + hb.drift_rate * (td->t(k + 1) - td->t0());
    const double mean_speed = d.dist[k] / dt.mid();
    const Interval dist =
        (Interval(d.dist[k]) * Interval(1 - sb.dist_rel, 1 + sb.dist_rel) + Interval(-sb.dist_over, sb.dist_under)) &
        Interval(0, INFINITY);
    speed[k] = dist / dt;
    if (mean_speed < sb.reverse_below) speed[k] = Interval(-speed[k].ub(), speed[k].ub());
    heading[k] = (psi | next) + Interval(-e, e);
    if (mean_speed > sb.glitch_above) heading[k] = Interval(-M_PI, M_PI);  // any direction
    psi = next;
  }
  return example::velocity_tube(td, speed, heading);
}

}  // namespace

int main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  const auto data = example::plaza1_from_args(argc, argv, "loops_plaza1");
  if (!data) return 0;
  const example::Plaza1Data& d = *data;
  const auto td = TDomain::create(d.t);
  // eps = (tf - t0) / divisions; --eps-div sets the divisions (2000 by default).
  const std::string div_text = example::option_value(argc, argv, "--eps-div", "2000");
  const double divisions = std::strtod(div_text.c_str(), nullptr);
  if (!(divisions >= 1 && divisions <= 1e6)) {
    std::fprintf(stderr, "loops_plaza1: --eps-div must be a number in [1, 1e6], got '%s'\n", div_text.c_str());
    return 2;
  }
  const double eps = (td->tf() - td->t0()) / divisions;
  // Tolerances for the ground truth (an INS/GPS solution): positions, and
  // the time resolution of its crossings (one sampling period and a bit).
  const double tol_m = 0.85, tol_s = 0.25;
  const example::Path truth{d.t, d.x, d.y};
  // Crossings counted as in the data README: points at least 0.2 m apart
  // (a standing robot's jitter would add crossings of a few millimetres).
  const example::Path thin = example::thinned(truth, 0.2);
  const auto crossings = self_crossings(thin.t, thin.x, thin.y);
  const auto pairs = example::check_pairs(truth, 20, 10.0);
  std::printf("plaza1: %zu slices, eps = %.3f s, %zu true crossings (path thinned to 0.2 m)\n", td->nb_slices(), eps,
              crossings.size());

  bool ok = true;
  std::string summary;
  std::vector<std::pair<std::string, std::string>> figures;
  for (const Model& m : kModels) {
    const TubeVector v = plaza1_velocity(d, td, m);
    const auto ic = example::check_integrals(v, truth, pairs, crossings, tol_m);
    const example::LoopRun run = example::run_loops(td, eps, v, crossings, tol_s);
    const sillage::TPlane& tp = run.tplane;
    const example::LoopCheck& lc = run.check;
    example::print_loops(m.name, run, ic, tol_m);
    ok = ok && example::passed(lc) && ic.nb_inside_tol == ic.nb_pairs;
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  "%s: %zu detections (%zu complete), %zu proofs T, %zu N, %zu/%zu crossings in proofs, %.2f s; ",
                  m.name, tp.nb_detections(), tp.nb_complete_detections(), tp.nb_proofs(), tp.nb_newton_proofs(),
                  lc.in_proven, lc.nb_crossings, run.seconds);
    summary += buf;
    example::save_loop_figures(tp, truth, IntervalVector{{d.x[0], d.x[0]}, {d.y[0], d.y[0]}}, crossings, out,
                               std::string("loops_plaza1_") + m.tag, std::string("plaza1, ") + m.name, 10.0, figures);
  }
  example::print_result("loops_plaza1", summary, ok, figures);
  return ok ? 0 : 1;
}

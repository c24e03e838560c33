// Loops on real data: CMU "Plaza 1" (../shared/data/plaza1, read in place).
// A robot sweeps a plaza in a lawn-mower pattern and crosses its own path
// about 200 times. From the odometry alone (a distance per 0.2 s period and
// a heading), the t-plane (thesis ch. 6) detects the loops, and the degree
// test T and the Newton test N prove some; the ground truth checks both the
// bounds (integral check) and the proofs (loop check). Two headings:
//   (b) gyro: a realistic drifting heading, with a bound that grows with time
//       (a gyro bias, as in docs/plaza1.md): the honest model, stated from
//       the sensor classes; the check (exit status) and the bound audit are its;
//   (a) INS: the distributed heading increments, which equal those of the
//       INS/GPS ground truth: the truth's own heading, not a sensor of the
//       robot. Illustrations of what such a heading and tight bounds would
//       prove, not guarantees: printed, labelled so, never counted.
// docs/loops_real_data.md gives the error model, why each bound, and results.
//
// Usage: example_loops_plaza1 [--data DIR] [--eps-div N] [--out DIR]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "example_args.h"
#include "loops_figures.h"
#include "loops_real_data.h"
#include "plaza1_bounds.h"
#include "plaza1_data.h"

using namespace sillage;
namespace fs = std::filesystem;

namespace {

// Speed: the odometer distance per period with a scale error and offsets
// (plaza1_bounds.h), and two rules for what the odometer cannot say.
struct SpeedBounds {
  double dist_rel;    // odometer scale error
  double dist_over;   // m per period counted but not travelled
  double dist_under;  // m per period travelled but not counted
  // The odometer distance is unsigned, and a robot backs up only slowly:
  // below this speed it may go either way.
  double reverse_below;  // m/s
  // Above the robot's top speed a period is a time-stamp glitch: its motion
  // is not trusted to follow the heading, any direction is allowed.
  double glitch_above;  // m/s
};

// Heading ψ ∈ ψ̂ + [-e(t), e(t)], e(t) = track + start + drift_rate (t - t0),
// over a period: around the hull of ψ̂ at its two ends (the heading is taken
// as monotone within 0.2 s; the margin absorbs the rest).
struct HeadingBounds {
  bool ins;           // the INS-quality increments, or the drifting ones
  double track;       // rad: direction of travel vs heading (side slip, INS heading error)
  double start;       // rad: initial heading error
  double drift_rate;  // rad/s: gyro bias
};

struct Model {
  std::string tag, name;
  bool honest;  // stated from the sensor classes (the check), or an illustration with the truth's heading
  SpeedBounds speed;
  HeadingBounds heading;
};

// The bounds of the loops models beyond plaza1_bounds.h, each an option.
struct LoopsBounds {
  double reverse_below = 0.5;  // m/s: backing up is a slow manoeuvre (a quarter of the 2 m/s top speed)
  double glitch_above = 2.0;   // m/s: the top speed of the robot class
};

// docs/loops_real_data.md says why each bound. The honest model first: it is the check.
std::vector<Model> models(const plaza1::Bounds& b, const LoopsBounds& l) {
  const SpeedBounds table{b.dist_rel, b.dist_over, b.dist_under, l.reverse_below, l.glitch_above};
  char ins[200], gyro[200];
  std::snprintf(ins, sizeof ins, "(a) illustration: the truth's INS heading +-%g rad, odometer d (1 +- %g %%) - %g m",
                b.track, 100 * b.dist_rel, b.dist_over);
  std::snprintf(gyro, sizeof gyro, "(b) drifting heading +-(%g + %g t) rad, odometer d (1 +- %g %%) - %g m",
                b.track + b.heading0, b.gyro_bias, 100 * b.dist_rel, b.dist_over);
  return {
      {"gyro", gyro, true, table, {false, b.track, b.heading0, b.gyro_bias}},
      // (a) uses the heading of the ground truth itself (the INS/GPS), not a
      // sensor of the robot: compared with the tolerance of
      // docs/loops_real_data.md, as the truth's own noise is in the heading.
      {"ins_wide", ins, false, table, {true, b.track, 0.0, 0.0}},
      // Calibrated on this run (read off its ground truth), not stated from
      // the sensors: it shows what tight bounds would prove.
      {"ins_tight",
       "(a) illustration, calibrated on this run: the truth's INS heading +-0.01 rad, odometer d (1 +- 0.5 %) - 5 mm",
       false, {0.005, 0.005, 0.001, l.reverse_below, l.glitch_above}, {true, 0.01, 0.0, 0.0}},
  };
}

TubeVector plaza1_velocity(const example::Plaza1Data& d, const std::shared_ptr<TDomain>& td, const Model& m,
                           double start_heading) {
  const SpeedBounds& sb = m.speed;
  const HeadingBounds& hb = m.heading;
  const std::size_t n = td->nb_slices();
  const std::vector<double>& dpsi = hb.ins ? d.dpsi_ins : d.dpsi_drift;
  std::vector<Interval> speed(n), heading(n);
  Interval psi(start_heading);  // ψ̂(t_k), summed with outward rounding
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

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  const auto data = example::plaza1_from_args(argc, argv, "loops_plaza1");
  if (!data) return 0;
  const example::Plaza1Data& d = *data;
  const plaza1::Bounds b = plaza1::bounds_from_args(argc, argv, d);
  const auto td = TDomain::create(d.t);
  // eps = (tf - t0) / divisions; --eps-div sets the divisions (2000 by default).
  const std::string div_text = example::option_value(argc, argv, "--eps-div", "2000");
  const double divisions = std::strtod(div_text.c_str(), nullptr);
  if (!(divisions >= 1 && divisions <= 1e6)) {
    std::fprintf(stderr, "loops_plaza1: --eps-div must be a number in [1, 1e6], got '%s'\n", div_text.c_str());
    return 2;
  }
  const double eps = (td->tf() - td->t0()) / divisions;
  // Tolerances for the ground truth (an INS/GPS solution): positions (the
  // (a) illustrations only: the honest model holds the truth exactly), and
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

  LoopsBounds lb;
  lb.reverse_below = example::option_number(argc, argv, "--reverse-below", lb.reverse_below);
  lb.glitch_above = example::option_number(argc, argv, "--glitch-above", lb.glitch_above);
  // The audit reports; it changes no bound. It is the audit of the honest model (b), the table's
  // bounds: one that the truth violates voids the guarantee, a failure.
  bool ok = example::print_audit("loops_plaza1, model (b)", plaza1::audit(d, b));
  std::string summary;
  std::vector<std::pair<std::string, std::string>> figures;
  bool illustrations = false;  // their heading line printed
  for (const Model& m : models(b, lb)) {
    if (!m.honest && !illustrations) {
      illustrations = true;
      // The truth against its own heading, which the (a) models use: why they need a tolerance.
      const example::AuditLine t = plaza1::track_audit(d, b.track, lb.reverse_below, lb.glitch_above);
      std::printf("\nillustrations, not guarantees: the (a) models use the heading of the ground truth itself, not a "
                  "sensor of the robot;\ntheir integral check allows the truth's own error (%.2f m) and they do not "
                  "count in the check.\n  the truth's direction of travel vs its own heading: max %.4g rad against "
                  "the (a) bound of %g rad (%s)\n",
                  tol_m, t.used, t.allowed, t.how.c_str());
      summary += "illustrations with the truth's heading, not guarantees: ";
    }
    const TubeVector v = plaza1_velocity(d, td, m, b.start_heading);
    const auto ic = example::check_integrals(v, truth, pairs, crossings, tol_m);
    const example::LoopRun run = example::run_loops(td, eps, v, crossings, tol_s);
    const sillage::TPlane& tp = run.tplane;
    const example::LoopCheck& lc = run.check;
    example::print_loops(m.name, run, ic, tol_m);
    if (m.honest) {  // honest bounds must hold the truth exactly, no tolerance
      ok = ok && example::passed(lc) && ic.nb_inside == ic.nb_pairs;
      if (ic.nb_inside != ic.nb_pairs) std::printf("  <-- INTEGRAL CHECK FAILED (honest bounds: no tolerance)\n");
    } else {
      std::printf("  illustration: truth within %.2f m of the integrals: %s; proofs holding a true crossing: %s "
                  "(not counted)\n",
                  tol_m, ic.nb_inside_tol == ic.nb_pairs ? "yes" : "no", example::passed(lc) ? "yes" : "no");
    }
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  "%s: %zu detections (%zu complete), %zu proofs T, %zu N, %zu/%zu crossings in proofs, %.2f s; ",
                  m.name.c_str(), tp.nb_detections(), tp.nb_complete_detections(), tp.nb_proofs(), tp.nb_newton_proofs(),
                  lc.in_proven, lc.nb_crossings, run.seconds);
    summary += buf;
    example::save_loop_figures(tp, truth, IntervalVector{{d.x[0], d.x[0]}, {d.y[0], d.y[0]}}, crossings, out,
                               std::string("loops_plaza1_") + m.tag, std::string("plaza1, ") + m.name, 10.0, figures);
  }
  example::print_result("loops_plaza1", summary, ok, figures);
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }

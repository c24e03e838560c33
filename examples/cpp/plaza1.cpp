// Real data: CMU "Plaza 1" (../shared/data/plaza1, read in place). A robot
// drives a lawn-mower path in an open plaza; odometry gives a distance and a
// (drifting) heading change per period of about 0.2 s, and a radio measures
// ranges to 4 surveyed beacons, biased long. Two guaranteed estimates:
//   1. dead reckoning from the odometry alone;
//   2. the same plus the 3529 ranges, each at an uncertain time (CtcEval);
//   3. with --q-ranges Q: the ranges q-relaxed, at most Q of them wrong
//      (one CtcQEval in the network), against the strict intersection of 2.
// The odometry ties heading and positions both ways over each period
// (CtcHeading) and over windows of 40 s (CtcHeadingWindow; --heading-window S,
// 0: none), which keeps the heading bounded, even from an unknown start. The
// gyro's bias is one unknown b0 of the run (--gyro-turn-on-bias) plus a small
// in-run drift (--gyro-in-run-drift; CtcBiasedIncrement), printed at the end.
// From an unknown start (--unknown-start 1) the start heading [−π, π] is cut into
// --start-heading-pieces N pieces (default 2), one network each: a piece is proven
// empty or contracted, and the answer is the hull of the non-empty pieces' tubes.
// The stated error bounds (plaza1_bounds.h, each one an option) are the model; the check is that
// every ground-truth sample lies in the position tube. The network is in
// plaza1_network.h (shared with bench/bench_plaza1.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "example_args.h"
#include "example_check.h"
#include "plaza1_network.h"
#include "sillage/figures/thickness_figure.h"
#include "sillage/figures/tube_figure.h"

using namespace sillage;
using example::Plaza1Data;
using plaza1::Bounds;

namespace {

struct Result {
  std::shared_ptr<TubeVector> p;
  ContractStats stats;
  double cpu = 0;
  std::size_t nb_ranges = 0;
  std::shared_ptr<Tube> psi;
  Interval b0;  // the gyro's turn-on bias
  std::vector<plaza1::Piece> pieces;  // one per piece of the start heading
};

// The network once per piece of the start heading (plaza1::solve_pieces), the hull of the
// non-empty ones.
Result solve_timed(const Plaza1Data& d, const Bounds& b, bool with_ranges, int q, double heading_window, int pieces) {
  const double start = static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
  plaza1::PieceSolution sol = plaza1::solve_pieces(d, b, with_ranges, q, heading_window, pieces);
  Result res;
  res.p = sol.hull.p;
  res.stats = sol.hull.stats;
  res.nb_ranges = sol.hull.nb_ranges;
  res.psi = sol.hull.psi;
  res.b0 = *sol.hull.b0;
  res.pieces = std::move(sol.pieces);
  res.cpu = static_cast<double>(std::clock()) / CLOCKS_PER_SEC - start;
  return res;
}

struct TruthCheck {
  std::size_t inside = 0;
  double mean_diam = 0, max_diam = 0;
};

// Ground truth at every time point, and the size of the position boxes: on a
// non-empty, bounded tube only (an empty network proves nothing about it).
TruthCheck check_truth(const Plaza1Data& d, const TubeVector& p) {
  TruthCheck c;
  const std::size_t n = p.nb_slices();
  for (std::size_t k = 0; k <= n; ++k) {
    const IntervalVector g = p.gate(k);
    const bool in = g[0].contains(d.x[k]) && g[1].contains(d.y[k]);
    if (!in && k - c.inside < 5) {  // the first misses, if any: which bound is too tight shows there
      std::printf("  miss k=%zu t=%.3f truth (%.3f, %.3f) box [%.3f, %.3f] x [%.3f, %.3f]\n", k, d.t[k], d.x[k], d.y[k],
                  g[0].lb(), g[0].ub(), g[1].lb(), g[1].ub());
    }
    c.inside += in;
    const double diam = std::max(g[0].diam(), g[1].diam());
    c.mean_diam += diam / static_cast<double>(n + 1);
    c.max_diam = std::max(c.max_diam, diam);
  }
  return c;
}

}  // namespace

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  const auto data = example::plaza1_from_args(argc, argv, "plaza1");
  if (!data) return 0;
  const example::Plaza1Data& d = *data;
  const Bounds b = plaza1::bounds_from_args(argc, argv, d);
  // The audit reports how much of each bound the truth used; it changes nothing. A bound the
  // truth violates voids the guarantee, even if the truth happens to stay inside: a failure.
  bool ok = example::print_audit("plaza1", plaza1::audit(d, b));
  std::string summary;
  std::vector<std::pair<std::string, std::string>> figures;
  const Trajectory tx(d.t, d.x), ty(d.t, d.y);
  // --q-ranges Q (Q >= 0): a third run with at most Q wrong ranges.
  const double q_ranges = example::option_number(argc, argv, "--q-ranges", -1);
  if (q_ranges >= 0 && q_ranges != std::floor(q_ranges)) {
    std::fprintf(stderr, "plaza1: --q-ranges takes a whole number of ranges, got %g\n", q_ranges);
    return 2;
  }
  // --heading-window S: CtcHeadingWindow over windows of S seconds (0: none).
  const double heading_window = example::option_number(argc, argv, "--heading-window", plaza1::kHeadingWindow);
  if (!(heading_window >= 0) || !std::isfinite(heading_window)) {
    std::fprintf(stderr, "plaza1: --heading-window takes a length >= 0 in seconds, got %g\n", heading_window);
    return 2;
  }
  // --start-heading-pieces N: the start heading cut into N pieces, one network each, their hull the
  // answer (default: 2 from an unknown start, any heading; 1 otherwise).
  const bool unknown = example::option_number(argc, argv, "--unknown-start", 0) != 0;
  const double pieces = example::option_number(argc, argv, "--start-heading-pieces", unknown ? 2 : 1);
  if (!(pieces >= 1) || pieces != std::floor(pieces) || pieces > 1000) {
    std::fprintf(stderr, "plaza1: --start-heading-pieces takes a whole number from 1 to 1000, got %g\n", pieces);
    return 2;
  }
  std::vector<int> runs = {-2, -1};  // -2: odometry only, -1: strict ranges, q >= 0: q-relaxed ranges
  if (q_ranges >= 0) runs.push_back(static_cast<int>(q_ranges));
  double strict_mean = NAN, strict_cpu = NAN;
  for (const int run : runs) {
    const bool with_ranges = run != -2;
    const Result r = solve_timed(d, b, with_ranges, run, heading_window, static_cast<int>(pieces));
    const std::size_t n = d.t.size();
    const std::string qlabel = "odometry + ranges, at most " + std::to_string(run) + " wrong";
    const char* label = run >= 0 ? qlabel.c_str() : with_ranges ? "odometry + ranges" : "odometry only";
    std::printf("%s: %zu ranges, %zu rounds, %zu contractor runs, %.2f s CPU, empty = %d\n", label, r.nb_ranges,
                r.stats.iterations, r.stats.contractor_calls, r.cpu, r.stats.empty);
    if (r.pieces.size() > 1) {  // each piece of the start heading: empty (and why) or kept in the hull
      for (const plaza1::Piece& piece : r.pieces) {
        std::printf("  start heading piece [%.4f, %.4f] rad: %s, %zu rounds, %.2f s CPU\n", piece.start.lb(),
                    piece.start.ub(), piece.sol.stats.empty ? example::empty_text(piece.sol.stats).c_str() : "not empty",
                    piece.sol.stats.iterations, piece.cpu);
      }
      if (!r.stats.empty) std::printf("  the tubes below: the hull of the non-empty pieces\n");
    }
    if (run == -1) {
      // GOMNE over the ranges stops at the first q that leaves a trajectory: here q = 0 if the strict network is not empty.
      std::printf("  smallest number of wrong ranges consistent with the data: %s\n", r.stats.empty ? "> 0" : "0");
    }
    // No solution, or an unbounded tube: an answer without truth or box figures, and a failed check.
    // Every piece of the start heading empty: inconsistent, with each piece's explanation.
    if (r.stats.empty && r.pieces.size() > 1) {
      std::string why = "INCONSISTENT: every piece of the start heading is empty";
      for (const plaza1::Piece& piece : r.pieces) {
        char start[80];
        std::snprintf(start, sizeof start, " [%.4f, %.4f] rad: ", piece.start.lb(), piece.start.ub());
        why += start + example::empty_text(piece.sol.stats) + ";";
      }
      std::printf("  INCONSISTENT: every piece of the start heading is empty (each piece says why above)\n");
      summary += std::string(label) + ": " + why + " ";
      ok = false;
      continue;
    }
    if (!example::check_stats(r.stats, label) || !example::enclosure_ok(*r.p)) {
      const std::string why = r.stats.empty ? example::empty_text(r.stats) : "UNBOUNDED: the position tube is unbounded";
      if (!r.stats.empty) std::printf("  %s\n", why.c_str());
      summary += std::string(label) + ": " + why + "; ";
      ok = false;
      continue;
    }
    const TruthCheck c = check_truth(d, *r.p);
    std::printf("  ground truth inside at %zu / %zu time points (%.1f %%); position box diameter mean %.2f m, max %.2f m\n",
                c.inside, n, 100.0 * static_cast<double>(c.inside) / static_cast<double>(n), c.mean_diam, c.max_diam);
    ok = ok && c.inside == n;
    if (run == -1) strict_mean = c.mean_diam, strict_cpu = r.cpu;
    if (run >= 0 && std::isnan(strict_mean)) std::printf("  q-relaxed (q = %d): the strict intersection is empty\n", run);
    if (run >= 0 && !std::isnan(strict_mean)) {
      std::printf("  q-relaxed (q = %d) against the strict intersection: mean box %.2f m vs %.2f m (x %.2f), %.2f s vs %.2f s\n",
                  run, c.mean_diam, strict_mean, c.mean_diam / strict_mean, r.cpu, strict_cpu);
    }
    // Over time: the box diameter, and when the heading is first known to +-0.1 rad.
    std::printf("  position box diameter at t0 +");
    for (const double dt : {0.0, 10.0, 30.0, 60.0, 120.0, 300.0, 600.0, 1200.0}) {
      const std::size_t k = static_cast<std::size_t>(std::lower_bound(d.t.begin(), d.t.end(), d.t[0] + dt) - d.t.begin());
      if (k < n) std::printf(" %.0f s: %.1f m;", dt, r.p->gate(k).max_diam());
    }
    std::printf("\n  heading half-width at t0 +");
    for (const double dt : {0.0, 10.0, 30.0, 60.0, 120.0, 300.0, 600.0, 1200.0}) {
      const std::size_t k = static_cast<std::size_t>(std::lower_bound(d.t.begin(), d.t.end(), d.t[0] + dt) - d.t.begin());
      if (k < n) std::printf(" %.0f s: %.2f rad;", dt, r.psi->gate(k).diam() / 2);
    }
    std::size_t known = 0;
    double first_known = NAN, narrowest = INFINITY;
    for (std::size_t k = 0; k < n; ++k) {
      if (r.psi->gate(k).diam() <= 0.2) ++known, first_known = std::isnan(first_known) ? d.t[k] - d.t[0] : first_known;
      if (d.t[k] >= d.t[0] + 60) narrowest = std::min(narrowest, r.psi->gate(k).diam());
    }
    std::printf("\n  heading known to +-0.1 rad at %zu of %zu time points", known, n);
    if (known > 0) std::printf(", first at t0 + %.1f s", first_known);
    std::printf("; narrowest heading after t0 + 60 s: +-%.2f rad\n", narrowest / 2);
    // The turn-on bias learnt by the network (measured minus true rate); the truth's is the slope of
    // the audit line "gyro turn-on bias".
    std::printf("  gyro turn-on bias b0 in [%.4f, %.4f] mrad/s\n", 1e3 * r.b0.lb(), 1e3 * r.b0.ub());
    char buf[200];
    std::snprintf(buf, sizeof buf, "%s: truth inside %.1f %%, mean/max box diameter %.2f/%.2f m, %.2f s; ", label,
                  100.0 * static_cast<double>(c.inside) / static_cast<double>(n), c.mean_diam, c.max_diam, r.cpu);
    summary += buf;
    const std::string tag = run >= 0 ? "qranges" : with_ranges ? "ranges" : "odometry";
    // The beacons as landmarks: inside the window, dots distinct from the truth's line, in the legend.
    std::vector<Vector> beacons;
    for (const auto& [id, xy] : d.beacons) beacons.push_back(Vector{xy.first, xy.second});
    Figure fig = tube_vector_figure(*r.p, 0, 1, std::string("plaza1: position tube, ") + label, {}, &tx, &ty, 600,
                                    &beacons);
    fig.save((out / ("plaza1_map_" + tag + ".svg")).string());
    figures.push_back({"plaza1_map_" + tag + ".svg", std::string("plaza1 map, ") + label + " (beacons as yellow dots)"});
    thickness_figure(*r.p, ThicknessMeasure::MaxDiameter, std::string("plaza1: position box diameter, ") + label)
        .save((out / ("plaza1_thickness_" + tag + ".svg")).string());
    figures.push_back({"plaza1_thickness_" + tag + ".svg", std::string("plaza1 thickness, ") + label});
  }
  example::print_result("plaza1", summary, ok, figures);
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }

// Real data: CMU "Plaza 1" (../shared/data/plaza1, read in place) as a
// range-only temporal SLAM WITHOUT the beacon positions (issue 13, thesis
// ch. 7). The configuration is the position, p = h(x) = (x, y); the
// observation z(.) is the four ranges, each a tube built from its own
// measurements and widened between them by |z'| <= the robot's speed bound.
// A range is a time-invariant function of the position, whatever the places
// of the beacons, so p(t1) = p(t2) ⇒ z(t1) = z(t2) needs no map at all:
//   1. dead reckoning from the known start: the plaza1 network without the
//      ranges (plaza1_network.h), which gives p and its derivative w = v;
//   2. C_{p⇒z} (CtcPImpliesZ): loops of the t-plane on (p, w) (7.28), proven
//      by the degree test, kept where the four ranges agree, contracted by
//      C_Ω; fast (Alg. 14) to its fixed point, then accurate (Alg. 13).
// The ground truth must lie in [p] at every gate after every iteration
// (checked; a miss, an empty or an unbounded tube is a failure). Every bound
// is the stated one of plaza1_bounds.h; docs/slam.md reports what it gives.
//
// Usage: example_plaza1_slam [--data DIR] [--eps S] [--heading-window S] [bounds] [--out DIR]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "example_args.h"
#include "example_check.h"
#include "plaza1_network.h"
#include "sillage/figures/thickness_figure.h"
#include "sillage/figures/tube_figure.h"
#include "sillage/missions/bathymetry_range_observation.h"
#include "sillage/slam/ctc_p_implies_z.h"

using namespace sillage;

namespace {

// Gates of p holding the ground truth.
std::size_t truth_inside(const TubeVector& p, const example::Plaza1Data& d) {
  std::size_t in = 0;
  for (std::size_t k = 0; k <= p.nb_slices(); ++k) {
    const IntervalVector g = p.gate(k);
    in += g[0].contains(d.x[k]) && g[1].contains(d.y[k]);
  }
  return in;
}

// Mean of the gates' box diameters (the larger side, as plaza1.cpp).
double mean_diameter(const TubeVector& p) {
  double s = 0;
  for (std::size_t k = 0; k <= p.nb_slices(); ++k) s += p.gate(k).max_diam();
  return s / static_cast<double>(p.nb_slices() + 1);
}

}  // namespace

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  const auto data = example::plaza1_from_args(argc, argv, "plaza1_slam");
  if (!data) return 0;
  const example::Plaza1Data& d = *data;
  const plaza1::Bounds b = plaza1::bounds_from_args(argc, argv, d);
  // --eps S: the width of the t-boxes, s. The robot needs 40 s or more to come back
  // to a place (docs/loops_real_data.md), so boxes of seconds resolve every loop.
  const double eps = example::option_number(argc, argv, "--eps", 5.0);
  const double window = example::option_number(argc, argv, "--heading-window", plaza1::kHeadingWindow);
  if (!(eps > 0) || !std::isfinite(eps) || !(window >= 0) || !std::isfinite(window)) {
    std::fprintf(stderr, "plaza1_slam: --eps takes a duration > 0 and --heading-window one >= 0, in seconds\n");
    return 2;
  }
  bool ok = example::print_audit("plaza1_slam", plaza1::audit(d, b));

  // 1. Dead reckoning: the odometry network from the known start.
  auto clock = std::chrono::steady_clock::now();
  const plaza1::Solution dr = plaza1::solve(d, b, false, -1, window);
  const double dr_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
  const TubeVector& dead = *dr.p;
  const TubeVector& w = *dr.v;
  const std::size_t n = dead.nb_slices();
  std::printf("plaza1_slam: %zu slices; dead reckoning %.2f s\n", n, dr_seconds);
  // No solution, or an unbounded tube: an answer without truth or box figures, and a failed check.
  if (!example::check_stats(dr.stats, "dead reckoning") || !example::enclosure_ok(dead)) {
    const std::string why = dr.stats.empty ? example::empty_text(dr.stats) : "UNBOUNDED: the position tube is unbounded";
    if (!dr.stats.empty) std::printf("  dead reckoning: %s\n", why.c_str());
    example::print_result("plaza1_slam", "dead reckoning: " + why, false);
    return 1;
  }
  std::printf("  dead reckoning: truth inside %zu / %zu gates, box diameter mean %.1f m, final %.1f m\n",
              truth_inside(dead, d), n + 1, mean_diameter(dead), dead.gate(n).max_diam());
  ok = ok && truth_inside(dead, d) == n + 1;

  // 2. The observation: the four ranges, beacon positions unused. |z'| <= the stated speed
  // bound (per stamped period, so that the time stamps' jitter is covered as well).
  std::vector<int> ids, rid(d.rid.begin(), d.rid.end());
  for (const auto& [id, xy] : d.beacons) ids.push_back(id);
  const RangeBounds rb{b.range_short, b.range_long, b.time_err, b.speed_max};
  TubeVector z(dead.tdomain(), ids.size());
  std::string inconsistent;  // why the observation has no solution, if it has none
  try {
    z = range_observation_tubes(dead.tdomain(), d.rt, rid, d.r, ids, rb);
    double zw = 0;
    for (std::size_t i = 0; i < z.size(); ++i) {
      for (std::size_t k = 0; k < n; ++k) zw += z[i].slice(k).diam() / static_cast<double>(n * z.size());
    }
    std::printf("  observation: %zu range tubes (%s), mean slice width %.1f m\n", z.size(), repr(rb).c_str(), zw);
  } catch (const Error& e) {  // the ranges contradict each other under these bounds: an answer, not a success
    inconsistent = std::string("observation inconsistent: ") + e.what();
    std::printf("  %s\n", inconsistent.c_str());
    ok = false;
  }

  // 3. C_{p⇒z}, fast then accurate, one iteration at a time: Table 7.2.
  TubeVector p = dead;
  std::vector<SlamRow> rows;
  std::vector<TubeVector> snapshots;
  double cumulated = 0;
  std::printf("\n| it | algorithm | detections | proofs | time | cumulated | contraction of [p](t_f) | mean box | truth |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (const bool fast : {true, false}) {
    const CtcPImpliesZ cpz(eps, fast);
    for (std::size_t it = 0; it < cpz.max_iterations() && ok; ++it) {
      SlamRow r;
      clock = std::chrono::steady_clock::now();
      const bool shrunk = cpz.iterate(p, w, z, r);
      r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
      cumulated += r.seconds;
      r.cumulated_seconds = cumulated;
      r.iteration = rows.size() + 1;
      r.contraction_tf = detail::contraction(dead.gate(n), p.gate(n));
      rows.push_back(r);
      const std::size_t in = p.is_empty() ? 0 : truth_inside(p, d);
      std::printf("| %zu | %s | %zu | %zu | %.2f s | %.2f s | %.1f %% | %.1f m | %zu / %zu |\n", r.iteration,
                  fast ? "fast" : "accurate", r.nb_detections, r.nb_proofs, r.seconds, r.cumulated_seconds,
                  100 * r.contraction_tf, p.is_empty() ? 0.0 : mean_diameter(p), in, n + 1);
      if (!example::enclosure_ok(p) || in != n + 1) {
        std::printf("  <-- FAILED: the truth left [p] (or [p] is empty or unbounded) at iteration %zu\n", r.iteration);
        ok = false;
      }
      if (!shrunk) break;
    }
  }
  if (ok) {
    for (std::size_t k = 0; k <= n; ++k) {
      if (!p.gate(k).is_subset(dead.gate(k))) {
        std::printf("  <-- FAILED: [p] wider than dead reckoning at gate %zu\n", k);
        ok = false;
        break;
      }
    }
  }
  const double mean_dr = mean_diameter(dead), mean_slam = p.is_empty() ? NAN : mean_diameter(p);
  if (inconsistent.empty() && !p.is_empty()) {
    std::printf("\nbox diameter, dead reckoning -> SLAM: mean %.2f -> %.2f m (%.1f %%), final %.2f -> %.2f m\n", mean_dr,
                mean_slam, 100 * (1 - mean_slam / mean_dr), dead.gate(n).max_diam(), p.gate(n).max_diam());
  }

  // The map: dead reckoning (grey), SLAM (blue), truth (red).
  std::vector<std::pair<std::string, std::string>> figures;
  const Trajectory tx(d.t, d.x), ty(d.t, d.y);
  if (!p.is_empty()) {
    // Framed on the truth (dead reckoning alone reaches kilometres away: the note says how far).
    const MapView view = map_view(dead, 0, 1, "x1", "x2", &tx, &ty);
    Figure fig(view.window, 700);
    fig.set_title("plaza1 range-only temporal SLAM: dead reckoning (grey), SLAM (blue), truth");
    fig.set_note(view.note);
    fig.set_labels("x1", "x2");
    TubeStyle grey, blue;
    grey.slices = {"#dddddd", "#999999", 0.4, 1.0, "dead reckoning", "dead reckoning"};
    blue.slices.label = "SLAM";
    draw_tube_vector_2d(fig, dead, 0, 1, grey);
    draw_tube_vector_2d(fig, p, 0, 1, blue, &tx, &ty);
    fig.save((out / "plaza1_slam_map.svg").string());
    figures.push_back({"plaza1_slam_map.svg", "plaza1 temporal SLAM map: DR tube, SLAM tube, truth"});
    thickness_figure(p, ThicknessMeasure::MaxDiameter, "plaza1 temporal SLAM: position box diameter")
        .save((out / "plaza1_slam_thickness.svg").string());
    figures.push_back({"plaza1_slam_thickness.svg", "plaza1 temporal SLAM: box diameter over time"});
  }
  std::size_t proofs = 0;
  for (const SlamRow& r : rows) proofs = std::max(proofs, r.nb_proofs);
  char summary[300];
  std::snprintf(summary, sizeof summary,
                "%zu iterations, at most %zu loop proofs; mean box %.2f m (dead reckoning %.2f m), final %.2f m; %.2f s",
                rows.size(), proofs, mean_slam, mean_dr, p.is_empty() ? NAN : p.gate(n).max_diam(), cumulated);
  // An empty [p] is an answer (no trajectory fits), without box figures.
  const std::string result = !inconsistent.empty() ? inconsistent
                             : p.is_empty() ? "EMPTY after iteration " + std::to_string(rows.size()) +
                                                  " of C_{p=>z} (no solution: the bounds or the data are inconsistent)"
                                            : std::string(summary);
  example::print_result("plaza1_slam", result, ok, figures);
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }

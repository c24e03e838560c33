// The bathymetric temporal SLAM of thesis 7.3.2 (Table 7.2, Fig. 7.16, 7.17,
// 7.20) on the synthetic mission of bathymetry_mission: state x = (east,
// north, depth) with x' = w (7.31), configuration p = h(x) = (x1, x2) (7.25),
// observation z = the seabed depth under the vehicle (7.30). No map: only
// p(t1) = p(t2) => z(t1) = z(t2). Fast (Alg. 14) then accurate (Alg. 13),
// each to its fixed point; the truth is checked inside [p](.) at every gate
// and slice after every iteration, and the run fails loudly otherwise.
//
// --scenario 2 is thesis 7.3.3 (Table 7.3): the start unknown, one accurate
// fix (+-1 m) in the middle of the mission; the SLAM propagates it backward
// and forward, and the table reports the contraction of [p](t_0) too.
// --duration shortens the mission (the demo); the full 5760 s is the default
// of the bench (bench/bench_slam_bathymetry.cpp). --seabed 2 --transects 1
// --beam-angle 0 --beam-spread 3 is the coastal mission (coastal seabed,
// east-west transects, a 6 deg narrow-beam altimeter); --study 1 prints, per
// proven detection, what limits the contraction (bathymetry_study.h) and stops.
// --seabed 3 is the bank mission (bank_mission_options: two channel flanks
// under the east-west transects, the narrow-beam altimeter): it contracts.
// --tie-lines A (degrees) flies tie lines at A to the rails first, then the
// rails back over them (docs/slam.md: measured, no better than the default).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bathymetry_check.h"
#include "bathymetry_study.h"
#include "example_args.h"
#include "example_check.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/expr/function.h"
#include "sillage/figures/thickness_figure.h"
#include "sillage/missions/bathymetry_figures.h"
#include "sillage/missions/bathymetry_mission.h"
#include "sillage/missions/bathymetry_tubes.h"
#include "sillage/missions/slam_figures.h"
#include "sillage/slam/temporal_slam.h"

using namespace sillage;

namespace {

std::size_t position_misses(const BathymetryMission& m, const TubeVector& p) {
  return example::truth_misses(p[0], m.times(), m.x1()) + example::truth_misses(p[1], m.times(), m.x2());
}

}  // namespace

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  const auto seed = static_cast<std::uint64_t>(example::option_number(argc, argv, "--seed", 7));
  const double dt = example::option_number(argc, argv, "--dt", 1.0);
  const double eps = example::option_number(argc, argv, "--eps", dt);
  const double duration = example::option_number(argc, argv, "--duration", 1800);
  const int scenario = static_cast<int>(example::option_number(argc, argv, "--scenario", 1));
  if (scenario != 1 && scenario != 2) example::usage_error("bathymetry_slam", "--scenario is 1 or 2");

  const int seabed = static_cast<int>(example::option_number(argc, argv, "--seabed", 1));
  if (seabed < 1 || seabed > 3)
    example::usage_error("bathymetry_slam", "--seabed is 1 (smooth), 2 (coastal) or 3 (channel banks)");
  // --seabed 3 is the whole bank mission (seabed, transects, narrow beam); the flags below override it.
  BathymetryMissionOptions mo = seabed == 3 ? bank_mission_options() : BathymetryMissionOptions{};
  mo.duration = duration;
  if (seabed == 2) mo.seabed = coastal_seabed_options();
  mo.seabed.dune_height = example::option_number(argc, argv, "--dune-height", mo.seabed.dune_height);
  mo.transects = example::option_number(argc, argv, "--transects", mo.transects) != 0;
  mo.tie_line_angle = example::option_number(argc, argv, "--tie-lines", 0);
  mo.seabed.relief = example::option_number(argc, argv, "--relief", 1);
  mo.depth = example::option_number(argc, argv, "--vehicle-depth", mo.depth);
  mo.bounds.beam_angle = example::option_number(argc, argv, "--beam-angle", mo.bounds.beam_angle);
  mo.bounds.beam_spread = example::option_number(argc, argv, "--beam-spread", mo.bounds.beam_spread);
  const BathymetryMission m(seed, mo);
  const auto td = m.tdomain(dt);
  const std::size_t N = td->nb_slices();
  const TubeVector w = bathymetry_velocity_tube(m, td);
  const TubeVector z(std::vector<Tube>{bathymetry_observation_tube(m, td)});
  // x: dead reckoning from a GNSS fix at the dive (scenario 1), or, for
  // scenario 2, unknown horizontally but for one fix at mid-mission (the depth
  // is the pressure sensor's in both).
  TubeVector x = bathymetry_dead_reckoning(m, td, bathymetry_initial_box(m));
  const std::size_t k_fix = N / 2;
  if (scenario == 2) {
    const std::ptrdiff_t i = m.sample_index(td->t(k_fix));
    x[0].set(Interval());
    x[1].set(Interval());
    x[0].set_gate(k_fix, Interval(m.x1()[i]) + Interval(-1, 1));
    x[1].set_gate(k_fix, Interval(m.x2()[i]) + Interval(-1, 1));
  }
  TubeVector v = w;
  const Function f({"x1", "x2", "x3", "u1", "u2", "u3"}, "(u1, u2, u3)");
  const Function h({"x1", "x2", "x3"}, "(x1, x2)");

  // The snapshots of the figures and the truth check at every iteration.
  TubeVector dr(td, 2), after_fast(td, 2), after_accurate(td, 2);
  std::vector<IntervalVector> tf_boxes;
  std::size_t misses = 0, checks = 0;
  TemporalSlamOptions o;
  o.eps = eps;
  o.on_iteration = [&](const SlamRow& r, const TubeVector& p) {
    ++checks;
    const std::size_t miss = position_misses(m, p);
    if (miss) std::fprintf(stderr, "bathymetry_slam: iteration %zu lost the truth at %zu samples\n", r.iteration, miss);
    misses += miss;
    tf_boxes.push_back(p.gate(N));
    (r.fast ? after_fast : after_accurate) = p;
  };
  {  // dead reckoning alone: what temporal_slam contracts from (its reference)
    TubeVector xd = x;
    CtcDeriv().contract(xd, w);
    dr = xd.subvector(0, 1);
  }
  tf_boxes.push_back(dr.gate(N));
  if (example::option_number(argc, argv, "--study", 0) != 0) {  // what limits it, then stop
    example::bathymetry_study(m, dr, w.subvector(0, 1), z[0], eps);
    return 0;
  }

  std::printf("Bathymetric temporal SLAM, scenario %d (%s), seed %llu\n", scenario,
              scenario == 1 ? "start known to +-1 m" : "start unknown, one +-1 m fix at mid-mission",
              static_cast<unsigned long long>(seed));
  std::printf("  mission %.0f s, %zu slices of %g s, eps = %g s, path %.0f m\n", duration, N, dt, eps,
              m.path_length());
  const std::vector<SlamRow> rows = temporal_slam(x, v, w, z, f, h, o);
  if (after_accurate.is_empty() || rows.empty() || rows.back().fast) after_accurate = after_fast;

  std::printf("  %-4s %-9s %10s %7s %9s %10s %12s %12s\n", "it", "algorithm", "detections", "proofs", "time (s)",
              "cumul (s)", "contr. p(tf)", "contr. p(t0)");
  for (const SlamRow& r : rows)
    std::printf("  %-4zu %-9s %10zu %7zu %9.2f %10.2f %11.1f%% %11.1f%%\n", r.iteration, r.fast ? "fast" : "accurate",
                r.nb_detections, r.nb_proofs, r.seconds, r.cumulated_seconds, 100 * r.contraction_tf,
                100 * r.contraction_t0);

  // Accurate never wider than fast, at every gate and slice.
  const bool nested = after_accurate.is_subset(after_fast);
  const std::size_t final_miss = position_misses(m, x.subvector(0, 1)) +
                                 example::truth_misses(x[2], m.times(), m.truth().depth);
  const bool ok = !rows.empty() && example::enclosure_ok(x) && misses == 0 && final_miss == 0 && nested;
  const IntervalVector pf = x.gate(N), p0 = x.gate(0);
  std::printf("  [p](t_f): dead reckoning %.1f x %.1f m -> SLAM %.1f x %.1f m\n", dr.gate(N)[0].diam(),
              dr.gate(N)[1].diam(), pf[0].diam(), pf[1].diam());
  const auto mean_diagonal = [](const TubeVector& q) {
    const std::vector<double> d = thickness_values(q.subvector(0, 1), ThicknessMeasure::Diagonal);
    double s = 0;
    for (double v : d) s += v;
    return s / static_cast<double>(d.size());
  };
  std::printf("  mean diagonal of [p](t) over the mission: dead reckoning %.2f m -> SLAM %.2f m\n", mean_diagonal(dr),
              mean_diagonal(x));
  if (scenario == 2)
    std::printf("  [p](t_0): propagated fix %.1f x %.1f m -> SLAM %.1f x %.1f m\n", dr.gate(0)[0].diam(),
                dr.gate(0)[1].diam(), p0[0].diam(), p0[1].diam());
  std::printf("  truth inside [p](.) at every gate and slice of every iteration (%zu checks): %s\n", checks,
              misses == 0 ? "yes" : "NO");
  std::printf("  truth inside the final [x](.) (east, north, depth): %s\n", final_miss == 0 ? "yes" : "NO");
  std::printf("  accurate within fast at every gate and slice: %s\n", nested ? "yes" : "NO");

  const std::string tag = scenario == 1 ? "" : "_scenario2";
  std::vector<std::pair<std::string, std::string>> figures = {
      {"bathymetry_slam_thickness" + tag + ".svg", "Thickness of [p]: dead reckoning, fast, accurate (Fig. 7.17)"},
      {"bathymetry_slam_map" + tag + ".svg", "Mission map: DR tube, SLAM tube, truth, successive [p](t_f) (Fig. 7.16)"},
      {"bathymetry_slam_dem" + tag + ".svg", "Seabed DEM with the path (Fig. 7.20)"}};
  slam_thickness_figure({{dr, "dead reckoning", "#777777"},
                         {after_fast, "fast (Alg. 14)", "#2a6aa8"},
                         {after_accurate, "accurate (Alg. 13)", "#d62728"}})
      .save((out / figures[0].first).string());
  slam_map_figure(m, dr, x.subvector(0, 1), tf_boxes).save((out / figures[1].first).string());
  bathymetry_dem_figure(m.dem(), m.x1(), m.x2()).save((out / figures[2].first).string());

  char summary[240];
  const SlamRow last = rows.empty() ? SlamRow{} : rows.back();
  std::snprintf(summary, sizeof summary,
                "scenario %d: %zu iterations, %.1f s, p(tf) contracted by %.0f %%, p(t0) by %.0f %%, truth inside: %s",
                scenario, rows.size(), last.cumulated_seconds, 100 * last.contraction_tf, 100 * last.contraction_t0,
                ok ? "yes" : "no");
  example::print_result("bathymetry_slam", summary, ok, figures);
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }

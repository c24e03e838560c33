// The synthetic bathymetric mission of thesis 7.3.2 (Daurade, 20 October 2015):
// a generated seabed (Fig. 7.20), 5760 s of survey at 10 Hz (crossing then
// keyhole-turn boustrophedon, Fig. 7.16), sensors drawn inside stated bounds,
// and the tubes a temporal SLAM starts from: the world velocity w (7.31), the
// dead reckoning p from a start box (Fig. 7.17: its drift), the observation
// z = z_alt + z_depth + z_tide (7.30, Fig. 7.14). Checks the truth inside
// every tube at every gate and slice.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "bathymetry_check.h"
#include "example_args.h"
#include "example_check.h"
#include "sillage/figures/thickness_figure.h"
#include "sillage/missions/bathymetry_figures.h"
#include "sillage/missions/bathymetry_mission.h"
#include "sillage/missions/bathymetry_tubes.h"

using namespace sillage;

namespace {

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// Standard deviation of the DEM nodes over the x-range [a, b].
double relief_std(const BathymetryDem& d, double a, double b) {
  double s = 0, s2 = 0, n = 0;
  for (std::size_t j = 0; j < d.ny(); ++j)
    for (std::size_t i = 0; i < d.nx(); ++i) {
      const double x = d.x0() + i * d.cell_size();
      if (x < a || x > b) continue;
      const double z = d.node(i, j);
      s += z, s2 += z * z, n += 1;
    }
  return std::sqrt(std::max(0.0, s2 / n - (s / n) * (s / n)));
}

}  // namespace

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  const auto seed = static_cast<std::uint64_t>(example::option_number(argc, argv, "--seed", 7));
  const double dt = example::option_number(argc, argv, "--dt", 1.0);

  double t0 = cpu_seconds();
  const BathymetryMission m(seed);
  const double t_gen = cpu_seconds() - t0;
  const auto td = m.tdomain(dt);
  t0 = cpu_seconds();
  const TubeVector p = bathymetry_dead_reckoning(m, td, bathymetry_initial_box(m));
  const Tube z = bathymetry_observation_tube(m, td);
  const double t_tubes = cpu_seconds() - t0;

  const std::size_t N = td->nb_slices();
  const IntervalVector pf = p.gate(N);
  const double diag = std::hypot(pf[0].diam(), pf[1].diam());
  const auto& dem = m.dem();
  const SeabedClass& c = m.seabed().bounds;
  double zw = 0;
  for (std::size_t k = 0; k <= N; ++k) zw += z.gate(k).diam();
  zw /= static_cast<double>(N + 1);

  std::printf("Synthetic bathymetric mission (seed %llu)\n", static_cast<unsigned long long>(seed));
  std::printf("  duration %.0f s at %.1f s steps (%zu samples), path length %.0f m\n", m.options().duration,
              m.options().step, m.nb_samples(), m.path_length());
  std::printf("  seabed: %zu x %zu nodes at %.0f m, depth %.2f .. %.2f m (relief %.2f m);\n", dem.nx(), dem.ny(),
              dem.cell_size(), dem.min_depth(), dem.max_depth(), dem.max_depth() - dem.min_depth());
  std::printf("          depth std %.2f m in the smooth strip x < %.0f m, %.2f m beyond; %s\n",
              relief_std(dem, 0, m.seabed().smooth_region[0].ub()), m.seabed().smooth_region[0].ub(),
              relief_std(dem, m.seabed().smooth_region[0].ub(), 500), repr(c).c_str());
  std::printf("  sensors: %s\n", repr(m.bounds()).c_str());
  std::printf("  tide: %s\n", repr(m.tide()).c_str());
  std::printf("  dead reckoning on %zu slices (dt = %g s): [p](t_f) = [%.1f, %.1f] x [%.1f, %.1f], "
              "widths %.1f x %.1f m, diagonal %.1f m\n",
              N, dt, pf[0].lb(), pf[0].ub(), pf[1].lb(), pf[1].ub(), pf[0].diam(), pf[1].diam(), diag);
  std::printf("  observation tube: mean gate width %.2f m, |z'| <= %.3f m/s between samples\n", zw,
              bathymetry_observation_rate_bound(m));
  std::printf("  CPU: generation %.2f s, tubes %.2f s\n", t_gen, t_tubes);

  const std::size_t miss = example::truth_misses(p[0], m.times(), m.x1()) + example::truth_misses(p[1], m.times(), m.x2()) +
                           example::truth_misses(p[2], m.times(), m.truth().depth) +
                           example::truth_misses(z, m.times(), bathymetry_truth_observation(m).sample_values());
  const bool ok = example::enclosure_ok(p) && example::enclosure_ok(z) && miss == 0;
  std::printf("  truth inside p and z at every gate and slice: %s (%zu misses)\n", ok ? "yes" : "NO", miss);

  std::vector<std::pair<std::string, std::string>> figures = {
      {"bathymetry_dem.svg", "Seabed DEM with the path (Fig. 7.20)"},
      {"bathymetry_map.svg", "Mission map: dead-reckoning tube and truth (Fig. 7.16)"},
      {"bathymetry_thickness.svg", "Dead-reckoning thickness d(t) (Fig. 7.17)"},
      {"bathymetry_observation.svg", "Observation tube [z](t) (Fig. 7.14)"}};
  bathymetry_dem_figure(dem, m.x1(), m.x2()).save((out / figures[0].first).string());
  bathymetry_map_figure(m, p).save((out / figures[1].first).string());
  thickness_figure(p.subvector(0, 1), ThicknessMeasure::Diagonal, "Dead-reckoning thickness (diagonal of [p1] x [p2])")
      .save((out / figures[2].first).string());
  bathymetry_observation_figure(m, z).save((out / figures[3].first).string());

  char summary[200];
  std::snprintf(summary, sizeof summary, "path %.0f m, relief %.1f m, DR diagonal %.1f m at t_f, truth inside: %s",
                m.path_length(), dem.max_depth() - dem.min_depth(), diag, ok ? "yes" : "no");
  example::print_result("bathymetry_mission", summary, ok, figures);
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }

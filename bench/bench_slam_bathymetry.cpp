// The bathymetric temporal SLAM (thesis 7.3.2, Table 7.2) on the full
// synthetic mission (5760 s, 1 s slices, eps = 1 s): the fast algorithm
// (Alg. 14) to its fixed point from dead reckoning, and the accurate one
// (Alg. 13) to its fixed point from the fast one's. Targets on 2 cores: fast
// <= 10 s, accurate <= 60 s. Each benchmark iteration takes a new mission
// (seed 7, 8, ...; generation and tubes untimed), so nothing is replayed.
// Counters: iterations of C_{p⇒z}, detections and proofs of the last
// iteration, contraction of [p](t_f) against dead reckoning. Second argument:
// the default mission (0), the coastal one (1) or the bank one (2).
#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>

#include "sillage/expr/function.h"
#include "sillage/missions/bathymetry_mission.h"
#include "sillage/missions/bathymetry_tubes.h"
#include "sillage/slam/temporal_slam.h"

using namespace sillage;

namespace {

struct SlamInput {
  TubeVector x, v, w;
  Tube z;
};

// 1 (coastal): the coastal seabed, a narrow-beam altimeter (6 deg cone) and
// the east-west transects (docs/slam.md); 2: bank_mission_options(); 0: the
// smoother default mission.
SlamInput slam_input(std::uint64_t seed, double dt, int mission) {
  BathymetryMissionOptions mo = mission == 2 ? bank_mission_options() : BathymetryMissionOptions{};
  if (mission == 1) {
    mo.seabed = coastal_seabed_options();
    mo.transects = true;
    mo.bounds.beam_angle = 0;
    mo.bounds.beam_spread = 3;
  }
  const BathymetryMission m(seed, mo);
  const auto td = m.tdomain(dt);
  TubeVector w = bathymetry_velocity_tube(m, td);
  return {bathymetry_dead_reckoning(m, td, bathymetry_initial_box(m)), w, w, bathymetry_observation_tube(m, td)};
}

void BM_BathymetrySlam(benchmark::State& state) {
  const bool accurate = state.range(0) != 0;
  const int mission = static_cast<int>(state.range(1));
  const Function f({"x1", "x2", "x3", "u1", "u2", "u3"}, "(u1, u2, u3)");
  const Function h({"x1", "x2", "x3"}, "(x1, x2)");
  std::uint64_t seed = 7;
  double iterations = 0, detections = 0, proofs = 0, contraction = 0, runs = 0;
  for (auto _ : state) {
    state.PauseTiming();
    SlamInput in = slam_input(seed++, 1.0, mission);
    const TubeVector z(std::vector<Tube>{in.z});
    TemporalSlamOptions o;
    o.eps = 1.0;
    o.accurate = false;
    double reference = 0;
    if (accurate) {  // from the fast fixed point, untimed
      const auto rows = temporal_slam(in.x, in.v, in.w, z, f, h, o);
      reference = rows.back().contraction_tf;
      o.fast = false;
      o.accurate = true;
    }
    state.ResumeTiming();
    const auto rows = temporal_slam(in.x, in.v, in.w, z, f, h, o);
    state.PauseTiming();
    iterations += static_cast<double>(rows.size());
    detections += static_cast<double>(rows.back().nb_detections);
    proofs += static_cast<double>(rows.back().nb_proofs);
    // Against dead reckoning: 1 - (1 - c_fast)(1 - c_accurate relative to fast).
    contraction += 1.0 - (1.0 - reference) * (1.0 - rows.back().contraction_tf);
    runs += 1;
    state.ResumeTiming();
  }
  state.SetLabel(std::string(accurate ? "accurate (from the fast fixed point)" : "fast (from dead reckoning)") +
                 (mission == 2 ? ", bank mission" : mission == 1 ? ", coastal mission" : ", default mission"));
  state.counters["iterations"] = iterations / runs;
  state.counters["detections"] = detections / runs;
  state.counters["proofs"] = proofs / runs;
  state.counters["contraction_tf"] = contraction / runs;
}
BENCHMARK(BM_BathymetrySlam)
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Args({0, 2})
    ->Args({1, 2})
    ->Iterations(3)
    ->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();

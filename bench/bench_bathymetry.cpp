// The synthetic bathymetric mission (thesis 7.3.2): generation of the seabed
// and of the whole mission (5760 s at 10 Hz), the tubes (velocity, dead
// reckoning, observation) on 1 s slices, and the DEM's box evaluation (exact
// range and cell hull) over a pool of 4096 random boxes of a given side,
// cycled (the pool is far larger than what a cache line pattern would learn).
#include <benchmark/benchmark.h>

#include <vector>

#include "sillage/missions/bathymetry_mission.h"
#include "sillage/missions/bathymetry_rng.h"
#include "sillage/missions/bathymetry_tubes.h"

using namespace sillage;

namespace {

const BathymetryMission& mission() {
  static const BathymetryMission m(7);
  return m;
}

std::vector<IntervalVector> box_pool(double side) {
  detail::BathymetryRng r(static_cast<std::uint64_t>(side * 1000) + 1);
  std::vector<IntervalVector> pool;
  for (int k = 0; k < 4096; ++k) {
    const double x = r.uniform(0, 500 - side), y = r.uniform(0, 500 - side);
    pool.push_back({Interval(x, x + side), Interval(y, y + side)});
  }
  return pool;
}

void BM_GenerateSeabed(benchmark::State& st) {
  std::uint64_t seed = 1;
  for (auto _ : st) benchmark::DoNotOptimize(generate_seabed(seed++).dem.max_depth());
}
BENCHMARK(BM_GenerateSeabed)->Unit(benchmark::kMillisecond);

void BM_GenerateMission(benchmark::State& st) {
  std::uint64_t seed = 1;
  for (auto _ : st) benchmark::DoNotOptimize(BathymetryMission(seed++).path_length());
}
BENCHMARK(BM_GenerateMission)->Unit(benchmark::kMillisecond);

void BM_DeadReckoningTube(benchmark::State& st) {
  const auto& m = mission();
  const auto td = m.tdomain(1.0);
  const IntervalVector x0 = bathymetry_initial_box(m);
  for (auto _ : st) benchmark::DoNotOptimize(bathymetry_dead_reckoning(m, td, x0).volume());
}
BENCHMARK(BM_DeadReckoningTube)->Unit(benchmark::kMillisecond);

void BM_ObservationTube(benchmark::State& st) {
  const auto& m = mission();
  const auto td = m.tdomain(1.0);
  for (auto _ : st) benchmark::DoNotOptimize(bathymetry_observation_tube(m, td).volume());
}
BENCHMARK(BM_ObservationTube)->Unit(benchmark::kMillisecond);

void BM_DemEval(benchmark::State& st) {
  const auto& dem = mission().dem();
  const auto pool = box_pool(static_cast<double>(st.range(0)));
  std::size_t k = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(dem.eval(pool[k]));
    k = (k + 1) & 4095;
  }
}
BENCHMARK(BM_DemEval)->Arg(1)->Arg(5)->Arg(20)->Arg(80)->Arg(300);

void BM_DemEvalCells(benchmark::State& st) {
  const auto& dem = mission().dem();
  const auto pool = box_pool(static_cast<double>(st.range(0)));
  std::size_t k = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(dem.eval_cells(pool[k]));
    k = (k + 1) & 4095;
  }
}
BENCHMARK(BM_DemEvalCells)->Arg(1)->Arg(5)->Arg(20)->Arg(80)->Arg(300);

void BM_DemPoint(benchmark::State& st) {
  const auto& dem = mission().dem();
  detail::BathymetryRng r(3);
  std::vector<double> xs(4096), ys(4096);
  for (int k = 0; k < 4096; ++k) xs[k] = r.uniform(0, 500), ys[k] = r.uniform(0, 500);
  std::size_t k = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(dem(xs[k], ys[k]));
    k = (k + 1) & 4095;
  }
}
BENCHMARK(BM_DemPoint);

}  // namespace

BENCHMARK_MAIN();

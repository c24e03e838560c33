// The `sillage` command's problem files (examples/problems/*.toml):
//   BM_Parse/i        load_problem alone (TOML, CSV tables, checks)
//   BM_ParseBuild/i   load_problem + build_network (the file's δ): the
//                     overhead of the file over a hand-written network
//   BM_Solve/i        the contraction of the built network to its fixed point
//   BM_Order/i/o      parse + build + solve with the constraints in file order
//                     (o = 0: the queue as written, FIFO) or cheap first (o = 1,
//                     [network] order = "cost"); counters: contractor calls,
//                     rounds, mean thickness (the fixed point reached)
//   BM_AutoDelta/i/m  the δ of the file (m = 0) against the automatic δ by
//                     uniform halving (m = 1) and by time regions (m = 2, the
//                     thicker half of the slices split); counters: slices,
//                     steps and mean thickness of the result (the problems
//                     with a δ: 0 to 5)
//   BM_Schedule/i/s   the network's scheduling (s = 0: FIFO, 1: by expected
//                     contraction over cost); counters: contractor calls,
//                     rounds, mean thickness (the same fixed point)
//   BM_Plaza1Cpp      the C++ example's network on the same data
//                     (examples/cpp/plaza1_network.h), to compare with
//                     BM_Solve of plaza1.toml
// Problem i: 0 dead_reckoning, 1 causal_chain, 2 line_ranges,
// 3 kidnapped_robot, 4 drifting_clock, 5 lowcost_beacons, 6 plaza1.
#include <benchmark/benchmark.h>

#include <array>
#include <filesystem>
#include <string>

#include "../examples/cpp/plaza1_network.h"
#include "sillage/problem/load_problem.h"
#include "sillage/problem/solve_problem.h"

namespace {

using namespace sillage;

constexpr std::array<const char*, 7> kProblems{"dead_reckoning", "causal_chain",    "line_ranges", "kidnapped_robot",
                                               "drifting_clock", "lowcost_beacons", "plaza1"};

const std::filesystem::path kPlaza1 = std::filesystem::path(SILLAGE_SHARED_DIR) / "data" / "plaza1";

std::string path_of(std::int64_t i) {
  return std::string(SILLAGE_SOURCE_DIR) + "/examples/problems/" + kProblems.at(static_cast<std::size_t>(i)) + ".toml";
}

bool skip_without_data(benchmark::State& state) {
  if (state.range(0) != 6 || std::filesystem::exists(kPlaza1 / "odometry.csv")) return false;
  state.SkipWithError(("no plaza1 data at " + kPlaza1.string()).c_str());
  return true;
}

void BM_Parse(benchmark::State& state) {
  if (skip_without_data(state)) return;
  const std::string path = path_of(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(load_problem(path));
  state.SetLabel(kProblems.at(static_cast<std::size_t>(state.range(0))));
}
BENCHMARK(BM_Parse)->DenseRange(0, 6)->Unit(benchmark::kMillisecond);

void BM_ParseBuild(benchmark::State& state) {
  if (skip_without_data(state)) return;
  const std::string path = path_of(state.range(0));
  std::size_t nodes = 0;
  for (auto _ : state) {
    const Problem p = load_problem(path);
    const BuiltProblem b = build_network(p, p.time.delta.value_or(p.time.tf - p.time.t0));
    nodes = b.cn->nb_ctc();
  }
  state.counters["nodes"] = static_cast<double>(nodes);
  state.SetLabel(kProblems.at(static_cast<std::size_t>(state.range(0))));
}
BENCHMARK(BM_ParseBuild)->DenseRange(0, 6)->Unit(benchmark::kMillisecond);

void BM_Solve(benchmark::State& state) {
  if (skip_without_data(state)) return;
  const Problem p = load_problem(path_of(state.range(0)));
  ContractStats s;
  for (auto _ : state) {
    state.PauseTiming();
    BuiltProblem b = build_network(p, p.time.delta.value_or(p.time.tf - p.time.t0));
    state.ResumeTiming();
    s = b.cn->contract();
  }
  state.counters["calls"] = static_cast<double>(s.contractor_calls);
  state.counters["rounds"] = static_cast<double>(s.iterations);
  state.SetLabel(kProblems.at(static_cast<std::size_t>(state.range(0))));
}
BENCHMARK(BM_Solve)->DenseRange(0, 6)->Unit(benchmark::kMillisecond);

void BM_Order(benchmark::State& state) {
  if (skip_without_data(state)) return;
  Problem p = load_problem(path_of(state.range(0)));
  p.network.order = state.range(1) == 0 ? ConstraintOrder::File : ConstraintOrder::Cost;
  ScheduleStep s;
  for (auto _ : state) s = solve_problem(p).schedule.back();
  state.counters["calls"] = static_cast<double>(s.stats.contractor_calls);
  state.counters["rounds"] = static_cast<double>(s.stats.iterations);
  state.counters["thickness"] = s.mean_thickness;
  state.SetLabel(std::string(kProblems.at(static_cast<std::size_t>(state.range(0)))) +
                 (state.range(1) == 0 ? " file order" : " cost order"));
}
BENCHMARK(BM_Order)->ArgsProduct({benchmark::CreateDenseRange(0, 6, 1), {0, 1}})->Unit(benchmark::kMillisecond);

void BM_AutoDelta(benchmark::State& state) {
  const Problem p = load_problem(path_of(state.range(0)));
  SolveOptions o;
  o.auto_delta = state.range(1) != 0;
  o.refinement = state.range(1) == 1 ? DeltaRefinement::Halving : DeltaRefinement::Regions;
  SolveResult r;
  for (auto _ : state) r = solve_problem(p, o);
  state.counters["slices"] = static_cast<double>(r.schedule.back().slices);
  state.counters["steps"] = static_cast<double>(r.schedule.size());
  state.counters["thickness"] = r.schedule.back().mean_thickness;
  static constexpr std::array<const char*, 3> kModes{" file delta", " auto halving", " auto regions"};
  state.SetLabel(std::string(kProblems.at(static_cast<std::size_t>(state.range(0)))) +
                 kModes.at(static_cast<std::size_t>(state.range(1))));
}
BENCHMARK(BM_AutoDelta)
    ->ArgsProduct({benchmark::CreateDenseRange(0, 5, 1), {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

void BM_Schedule(benchmark::State& state) {
  if (skip_without_data(state)) return;
  const Problem p = load_problem(path_of(state.range(0)));
  const Scheduling scheduling = state.range(1) == 0 ? Scheduling::Fifo : Scheduling::Priority;
  ContractStats s;
  double thickness = 0;
  for (auto _ : state) {
    state.PauseTiming();
    BuiltProblem b = build_network(p, p.time.delta.value_or(p.time.tf - p.time.t0));
    b.cn->set_scheduling(scheduling);
    state.ResumeTiming();
    s = b.cn->contract();
    thickness = mean_thickness(b);
  }
  state.counters["calls"] = static_cast<double>(s.contractor_calls);
  state.counters["rounds"] = static_cast<double>(s.iterations);
  state.counters["thickness"] = thickness;
  state.SetLabel(std::string(kProblems.at(static_cast<std::size_t>(state.range(0)))) +
                 (state.range(1) == 0 ? " fifo" : " priority"));
}
BENCHMARK(BM_Schedule)->ArgsProduct({benchmark::CreateDenseRange(0, 6, 1), {0, 1}})->Unit(benchmark::kMillisecond);

void BM_Plaza1Cpp(benchmark::State& state) {
  if (!std::filesystem::exists(kPlaza1 / "odometry.csv")) {
    state.SkipWithError(("no plaza1 data at " + kPlaza1.string()).c_str());
    return;
  }
  const example::Plaza1Data d = example::load_plaza1(kPlaza1);
  plaza1::Solution s;
  for (auto _ : state) s = plaza1::solve(d, plaza1::with_start({}, d), true);
  state.counters["calls"] = static_cast<double>(s.stats.contractor_calls);
  state.counters["rounds"] = static_cast<double>(s.stats.iterations);
}
BENCHMARK(BM_Plaza1Cpp)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

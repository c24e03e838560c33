// Loops of the synthetic survey of examples/cpp/looping_mission.h (thesis
// 6.4): detections (Alg. 6) and proofs (degree test T, Newton test N,
// count of Alg. 10) with TPlane, and the true crossings by self_crossings.
//   BM_DetectionsAndProofs/<hours>      both, eps = (tf - t0)/2000 (targets: 1 h <= 0.5 s, 2 h <= 2 s)
//   BM_Detections/<hours>, BM_Proofs/<hours>   each alone
//   BM_ProofsWithoutSplit/<hours>       the proofs with ProofOptions::split off (the cost of the split)
//   BM_ProofsVsSplitLevels/<s>/<levels>  proofs of the <s> seconds mission with split_max_levels = levels
//   BM_DetectionsVsEps/<divisor>        1 h mission, eps = 3600 s / divisor
//   BM_TrueCrossings/<points>           self_crossings on the 1 h true path with that many samples
//   BM_Mission/<hours>                  generation of the mission and its velocity tube
// Counters: detections (all, complete), proofs by T and N, lambda* (true
// crossings in complete detections), the share of it inside proven
// detections or proven pieces of split ones (proven_pct), and the proven
// sub-loops (sub_loops, TPlane::proofs()). The proofs run on every core:
// their CPU column is that of the whole process.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "looping_mission.h"
#include "sillage/loops/tplane.h"

using namespace sillage;

namespace {

// Missions are deterministic: built once per duration.
const looping_mission::Mission& mission(double hours) {
  static std::map<double, std::unique_ptr<looping_mission::Mission>> cache;
  auto& m = cache[hours];
  if (!m) {
    looping_mission::Parameters p;
    p.duration = 3600.0 * hours;
    m = std::make_unique<looping_mission::Mission>(p);
  }
  return *m;
}

const std::vector<PathCrossing>& truth(double hours) {
  static std::map<double, std::vector<PathCrossing>> cache;
  auto it = cache.find(hours);
  if (it == cache.end()) it = cache.emplace(hours, mission(hours).true_crossings(0.05)).first;
  return it->second;
}

void report(benchmark::State& state, const TPlane& tp, double hours, bool proofs) {
  state.counters["detections"] = double(tp.nb_detections());
  state.counters["complete"] = double(tp.nb_complete_detections());
  state.counters["leaves"] = double(tp.paving().nb_leaves());
  if (!proofs) return;
  state.counters["proofs_T"] = double(tp.nb_proofs());
  state.counters["proofs_N"] = double(tp.nb_newton_proofs());
  std::size_t lambda_star = 0, proven = 0;
  for (const PathCrossing& c : truth(hours)) {
    for (const Loop& l : tp.detections()) {
      bool in = false;
      for (const IntervalVector& b : l.boxes()) in = in || (b[0].contains(c.t1) && b[1].contains(c.t2));
      if (!in) continue;
      bool in_piece = false;  // a proven piece of a split detection (component_split.h)
      for (const Loop& p : l.pieces()) {
        for (const IntervalVector& b : p.boxes()) in_piece = in_piece || (p.proven() && b[0].contains(c.t1) && b[1].contains(c.t2));
      }
      if (l.complete()) ++lambda_star, proven += (l.proven() || in_piece) ? 1 : 0;
      break;
    }
  }
  state.counters["lambda_star"] = double(lambda_star);
  state.counters["proven_pct"] = lambda_star ? 100.0 * double(proven) / double(lambda_star) : 0.0;
  state.counters["sub_loops"] = double(tp.proofs().size());
}

// Detections at eps = tf / eps_divisor, then proofs if asked, from scratch at each iteration.
void run_tplane(benchmark::State& state, double hours, double eps_divisor, bool proofs) {
  const auto& m = mission(hours);
  std::unique_ptr<TPlane> tp;
  for (auto _ : state) {
    tp = std::make_unique<TPlane>(m.tdomain());
    tp->compute_detections(m.tf() / eps_divisor, m.velocity_tube());
    if (proofs) tp->compute_proofs(m.velocity_tube());
  }
  report(state, *tp, hours, proofs);
}

void BM_DetectionsAndProofs(benchmark::State& state) { run_tplane(state, double(state.range(0)), 2000, true); }
BENCHMARK(BM_DetectionsAndProofs)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// Against the mission length at dt = 0.1 s: 1e4, 3.6e4, 7.2e4 and 1e5 slices (arg in seconds).
void BM_DetectionsAndProofsVsLength(benchmark::State& state) {
  run_tplane(state, double(state.range(0)) / 3600.0, 2000, true);
}
BENCHMARK(BM_DetectionsAndProofsVsLength)->Arg(1000)->Arg(3600)->Arg(7200)->Arg(10000)
    ->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Detections(benchmark::State& state) { run_tplane(state, double(state.range(0)), 2000, false); }
BENCHMARK(BM_Detections)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// Proofs with the split of degree-0 / uncounted detections (the default), and without it.
void run_proofs(benchmark::State& state, bool split, double hours, std::size_t levels = ProofOptions{}.split_max_levels) {
  const auto& m = mission(hours);
  TPlane tp(m.tdomain());
  tp.compute_detections(m.tf() / 2000, m.velocity_tube());
  ProofOptions options;
  options.split = split;
  options.split_max_levels = levels;
  for (auto _ : state) tp.compute_proofs(m.velocity_tube(), options);
  report(state, tp, hours, true);
}
void BM_Proofs(benchmark::State& state) { run_proofs(state, true, double(state.range(0))); }
BENCHMARK(BM_Proofs)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime();
void BM_ProofsWithoutSplit(benchmark::State& state) { run_proofs(state, false, double(state.range(0))); }
BENCHMARK(BM_ProofsWithoutSplit)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime();

void BM_ProofsVsSplitLevels(benchmark::State& state) {
  run_proofs(state, true, double(state.range(0)) / 3600.0, std::size_t(state.range(1)));
}
BENCHMARK(BM_ProofsVsSplitLevels)->ArgsProduct({{7200, 10000}, {1, 2, 3, 4, 5, 6, 8}})->Unit(benchmark::kMillisecond)
    ->UseRealTime()->MeasureProcessCPUTime();

void BM_DetectionsVsEps(benchmark::State& state) { run_tplane(state, 1, double(state.range(0)), true); }
BENCHMARK(BM_DetectionsVsEps)->Arg(500)->Arg(1000)->Arg(2000)->Arg(4000)->Arg(8000)->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_TrueCrossings(benchmark::State& state) {
  const auto samples = mission(1).true_path(3600.0 / double(state.range(0)));
  std::size_t n = 0;
  for (auto _ : state) n = self_crossings(samples.t, samples.x, samples.y).size();
  state.counters["crossings"] = double(n);
  state.counters["points"] = double(samples.t.size());
}
BENCHMARK(BM_TrueCrossings)->Arg(72000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void BM_Mission(benchmark::State& state) {
  looping_mission::Parameters p;
  p.duration = 3600.0 * double(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(looping_mission::Mission(p).velocity_tube().nb_slices());
}
BENCHMARK(BM_Mission)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

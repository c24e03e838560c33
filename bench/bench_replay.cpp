// A problem file run online (sillage replay, docs/online.md): the recorded rows
// of examples/problems/*.toml fed through OnlineProblem in stamp order, the
// latency of every row kept (the estimator's work; the replay's bookkeeping left
// out). The figure a user of `sillage replay` sees, without the batch solve.
#include <benchmark/benchmark.h>

#include <string>

#include "sillage/problem/load_problem.h"
#include "sillage/problem/replay_problem.h"

namespace {

const std::string kProblems = std::string(SILLAGE_SOURCE_DIR) + "/examples/problems/";
const char* kNames[] = {"plaza1", "lowcost_beacons", "drifting_clock", "kidnapped_robot"};

void BM_ProblemReplay(benchmark::State& state) {
  const std::string name = kNames[state.range(0)];
  sillage::Problem p;
  try {
    p = sillage::load_problem(kProblems + name + ".toml");
  } catch (const std::exception& e) {
    state.SkipWithError((name + ": " + e.what()).c_str());  // plaza1 without its data
    return;
  }
  sillage::ReplayOptions o;
  o.batch = false;
  sillage::ReplayResult r;
  for (auto _ : state) {
    r = sillage::replay_problem(p, o);
    benchmark::DoNotOptimize(r.t.back());
  }
  state.SetLabel(name);
  double sum = 0;
  for (const double x : r.latency) sum += x;
  state.counters["rows"] = static_cast<double>(r.rows);
  state.counters["log_s"] = sum;
  state.counters["realtime_x"] = r.t.empty() ? 0 : (r.t.back() - p.time.t0) / sum;
  state.counters["median_us"] = 1e6 * r.latency_quantile(0.5);
  state.counters["p99_us"] = 1e6 * r.latency_quantile(0.99);
  state.counters["max_us"] = 1e6 * r.latency_quantile(1.0);
  state.counters["truth_out"] = static_cast<double>(r.truth_samples - r.truth_inside - r.truth_unbounded);
}
BENCHMARK(BM_ProblemReplay)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();

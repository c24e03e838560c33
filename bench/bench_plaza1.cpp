// The real-data example plaza1 (examples/cpp/plaza1.cpp, data in
// ../shared/data/plaza1 read in place), from building the tubes to the fixed
// point, the data loaded once:
//   BM_Plaza1/0   dead reckoning from the odometry alone
//   BM_Plaza1/1   the same plus the 3529 ranges at uncertain times
//   BM_Plaza1/2   the ranges q-relaxed, at most 2 wrong (one CtcQEval)
// Counters: rounds of the network ("iterations"), contractor calls, ranges.
// Skipped with a message when the data folder is missing.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <optional>
#include <string>

#include "plaza1_network.h"

namespace {

const std::filesystem::path kDir = std::filesystem::path(SILLAGE_SHARED_DIR) / "data" / "plaza1";

// The data, read on first use; nullopt if the folder holds none.
const std::optional<example::Plaza1Data>& data() {
  static const std::optional<example::Plaza1Data> d =
      std::filesystem::exists(kDir / "odometry.csv") ? std::optional(example::load_plaza1(kDir)) : std::nullopt;
  return d;
}

void BM_Plaza1(benchmark::State& state) {
  if (!data()) {
    state.SkipWithError(("no plaza1 data at " + kDir.string()).c_str());
    return;
  }
  const bool with_ranges = state.range(0) >= 1;
  const int q = state.range(0) == 2 ? 2 : -1;
  plaza1::Solution s;
  for (auto _ : state) s = plaza1::solve(*data(), plaza1::with_start({}, *data()), with_ranges, q);
  state.counters["iterations"] = static_cast<double>(s.stats.iterations);
  state.counters["calls"] = static_cast<double>(s.stats.contractor_calls);
  state.counters["ranges"] = static_cast<double>(s.nb_ranges);
  if (s.stats.empty) state.SkipWithError("empty result");
  state.SetLabel(q >= 0 ? "odometry + ranges, at most 2 wrong" : with_ranges ? "odometry + ranges" : "odometry only");
}
BENCHMARK(BM_Plaza1)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

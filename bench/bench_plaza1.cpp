// The real-data example plaza1 (examples/cpp/plaza1.cpp, data in
// ../shared/data/plaza1 read in place), from building the tubes to the fixed
// point, the data loaded once:
//   BM_Plaza1/0   dead reckoning from the odometry alone
//   BM_Plaza1/1   the same plus the 3529 ranges at uncertain times
//   BM_Plaza1/2   the ranges q-relaxed, at most 2 wrong (one CtcQEval)
//   BM_Plaza1Heading/W/U   odometry + ranges with CtcHeadingWindow over W s
//                 windows (0: none), the start known (U = 0) or unknown (U = 1:
//                 anywhere near the beacons, any heading, solved as its two halves
//                 [−π, 0] and [0, π], one network each, and their hull, as the example does)
// (all with CtcHeadingWindow over 40 s windows, the example's default, but the last with W = 0)
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
const std::optional<example::Plaza1Data>& data() { return example::plaza1_once(kDir); }

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

void BM_Plaza1Heading(benchmark::State& state) {
  if (!data()) {
    state.SkipWithError(("no plaza1 data at " + kDir.string()).c_str());
    return;
  }
  const auto window = static_cast<double>(state.range(0));
  const plaza1::Bounds b =
      state.range(1) ? plaza1::unknown_start({}, *data()) : plaza1::with_start({}, *data());
  // The unknown start as the example runs it: its heading in two halves, one network each, the hull.
  const int pieces = state.range(1) ? 2 : 1;
  plaza1::PieceSolution s;
  for (auto _ : state) s = plaza1::solve_pieces(*data(), b, true, -1, window, pieces);
  state.counters["iterations"] = static_cast<double>(s.hull.stats.iterations);
  state.counters["calls"] = static_cast<double>(s.hull.stats.contractor_calls);
  if (s.hull.stats.empty) state.SkipWithError("empty result");
  state.SetLabel(std::string(state.range(1) ? "unknown start, heading in 2 pieces" : "known start") +
                 (window > 0 ? ", heading windows" : ", no heading windows"));
}
BENCHMARK(BM_Plaza1Heading)->ArgsProduct({{0, 40}, {0, 1}})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

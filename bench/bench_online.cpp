// Online estimation (docs/online.md): plaza1 replayed through OnlineEstimator
// in stamp order, the figures a robot would see: per-update latency (median,
// p99), the whole 1933 s log, the online box against the batch one; and a
// synthetic mission of growing length at a fixed window (memory and latency
// flat in the mission's length).
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <filesystem>
#include <optional>
#include <random>

#include "plaza1_network.h"
#include "plaza1_online.h"
#include "sillage/dynamics/ctc_deriv.h"

namespace {

const std::filesystem::path kDir = std::filesystem::path(SILLAGE_SHARED_DIR) / "data" / "plaza1";

// The data, read on first use; nullopt if the folder holds none.
const std::optional<example::Plaza1Data>& data() { return example::plaza1_once(kDir); }

// The area of the p box, m².
double area(const sillage::IntervalVector& p) { return p[0].diam() * p[1].diam(); }

// plaza1 online with a window of range(0) seconds (0: infinite).
void BM_Plaza1Online(benchmark::State& state) {
  if (!data()) {
    state.SkipWithError(("no plaza1 data at " + kDir.string()).c_str());
    return;
  }
  const auto& d = *data();
  const plaza1::Bounds b = plaza1::with_start({}, d);
  const double window = state.range(0) > 0 ? static_cast<double>(state.range(0)) : INFINITY;
  plaza1::Replay r;
  sillage::OnlineStats st;
  for (auto _ : state) {
    auto est = plaza1::online_estimator(d, b, window);
    r = plaza1::replay(*est, d, b);
    st = est->stats();
    benchmark::DoNotOptimize(r.now.back());
  }
  state.counters["layout_s"] = st.layout_seconds;
  state.counters["runs_per_update"] = static_cast<double>(st.contractor_runs) / static_cast<double>(st.updates);
  double sum = 0;
  for (const double x : r.latency) sum += x;
  state.counters["updates"] = static_cast<double>(r.latency.size());
  state.counters["median_us"] = 1e6 * plaza1::quantile(r.latency, 0.5);
  state.counters["p99_us"] = 1e6 * plaza1::quantile(r.latency, 0.99);
  state.counters["advance_median_us"] = 1e6 * plaza1::quantile(r.advance_latency, 0.5);
  state.counters["advance_p99_us"] = 1e6 * plaza1::quantile(r.advance_latency, 0.99);
  state.counters["max_us"] = 1e6 * plaza1::quantile(r.latency, 1.0);
  state.counters["log_s"] = sum;
  state.counters["realtime_x"] = (d.t.back() - d.t.front()) / sum;
  // Online box against the batch one, once the first ranges are in (after 60 s).
  plaza1::Bounds same = b;  // the same model: the gyro's bias free at every step
  same.gyro_drift = same.gyro_bias;
  const auto batch = plaza1::solve(d, same, true, -1, plaza1::kHeadingWindow);
  double ratio = 0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    if (r.t[k] < d.t.front() + 60) continue;
    const double a = area(batch.p->gate(k + 1));
    if (a > 0) {
      ratio += std::sqrt(area(r.now[k]) / a);  // the ratio of the box sides' geometric mean
      ++n;
    }
  }
  state.counters["online_vs_batch"] = n ? ratio / static_cast<double>(n) : 0;
  state.counters["consistent"] = r.consistent;
}
BENCHMARK(BM_Plaza1Online)->Arg(60)->Arg(0)->Unit(benchmark::kMillisecond)->Iterations(1);

// A synthetic robot, p' = v, v known within ±0.05 at 10 Hz, a range every
// ~1 s, for range(0) hours with W = 120 s: latency and peak memory flat.
void BM_OnlineLongMission(benchmark::State& state) {
  using namespace sillage;
  const double hours = static_cast<double>(state.range(0)) / 10.0;
  const std::size_t steps = static_cast<std::size_t>(hours * 3600 * 10);
  // A uniform sample of the latencies, of fixed size (reservoir sampling): the
  // benchmark's own memory must not grow with the mission either.
  constexpr std::size_t kKept = 1 << 16;
  std::vector<double> latency;
  latency.reserve(kKept);
  std::mt19937_64 gen(1);
  std::size_t seen = 0;
  const auto record = [&](double x) {
    ++seen;
    if (latency.size() < kKept) {
      latency.push_back(x);
    } else if (const std::size_t j = std::uniform_int_distribution<std::size_t>(0, seen - 1)(gen); j < kKept) {
      latency[j] = x;
    }
  };
  std::size_t most = 0;
  for (auto _ : state) {
    OnlineOptions o;
    o.window = 120;
    OnlineEstimator est(0.0, o);
    est.add_state("p", 2, IntervalVector{{-0.1, 0.1}, {9.9, 10.1}});
    est.add_input("v", 2);
    est.add_deriv("p", "v");
    const auto ring = std::make_shared<CtcFunction>(Function({"q0", "q1", "r"}, "sqrt(q0^2 + q1^2) - r"));
    for (std::size_t k = 1; k <= steps; ++k) {
      const double t = 0.1 * static_cast<double>(k);
      const Interval tk(t - 0.1, t);
      // On the circle of radius 10 at 0.1 rad/s: v = (cos(t/10), -sin(t/10)).
      const auto start = std::chrono::steady_clock::now();
      est.advance(t, {{"v", IntervalVector{cos(tk / 10) + Interval(-0.05, 0.05), -sin(tk / 10) + Interval(-0.05, 0.05)}}});
      if (k % 10 == 0) est.observe(Interval(t - 0.15, t - 0.05), "p", ring, {std::make_shared<Interval>(9.9, 10.1)});
      record(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      most = std::max(most, est.stats().slices);
    }
  }
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  state.counters["hours"] = hours;
  state.counters["median_us"] = 1e6 * plaza1::quantile(latency, 0.5);
  state.counters["p99_us"] = 1e6 * plaza1::quantile(latency, 0.99);
  state.counters["max_slices"] = static_cast<double>(most);
  state.counters["peak_rss_MB"] = static_cast<double>(u.ru_maxrss) / 1024.0;
}
// 1 h and 24 h (the argument is tenths of an hour); run each alone to compare the peak RSS
// (--benchmark_filter=LongMission/10/ and LongMission/240/: the peak is the process's).
BENCHMARK(BM_OnlineLongMission)->Arg(10)->Arg(240)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();

// CtcEval (Prop. 5.1) per call on a tube of 1e5 slices, with [t] covering 1 %
// and 10 % of the domain (the cases), from a fresh copy of the tube
// each time (the copy is not timed).
#include <benchmark/benchmark.h>

#include "sillage/dynamics/ctc_eval.h"
#include "sillage/interval/elementary.h"

namespace {

using namespace sillage;

void BM_CtcEval(benchmark::State& state) {
  const std::size_t n = 100000;
  const double share = static_cast<double>(state.range(0)) / 100.0;
  const auto td = TDomain::create(0.0, 1e-3 * n, 1e-3);
  const double tf = td->tf();
  const Tube y0(td, "sin(t) + [-0.5, 0.5]"), w(td, "cos(t) + [-0.05, 0.05]");
  const double tc = 0.5 * tf, half = 0.5 * share * tf;
  CtcEval ctc;
  ctc.enable_time_sampling(false);
  for (auto _ : state) {
    state.PauseTiming();
    Tube y = y0;
    Interval t(tc - half, tc + half), z(sin(Interval(tc)) + Interval(-0.01, 0.01));
    state.ResumeTiming();
    benchmark::DoNotOptimize(ctc.contract(t, z, y, w));
  }
  state.SetLabel("[t] covers " + std::to_string(state.range(0)) + " % of 1e5 slices");
}

BENCHMARK(BM_CtcEval)->Arg(1)->Arg(10)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();

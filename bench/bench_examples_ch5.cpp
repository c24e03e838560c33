// The two worked examples of thesis chapter 5, timed to their fixed point
// (ratio 0), network construction included; the same networks as
// examples/cpp/lowcost_beacons.cpp and examples/cpp/drifting_clock.cpp.
//   BM_LowcostBeacons/<1/dt>   5.3.1, t in [0, 64] (thesis: 52 iterations, 2 min)
//   BM_DriftingClock/<1/dt>    5.3.2, t in [0, 13] (thesis: 5 steps, < 2 s)
// Counters: rounds of the network ("iterations"), contractor calls, and the
// time of contract() alone ("contract_s").
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "drifting_clock_network.h"
#include "lowcost_beacons_network.h"

using namespace sillage;

namespace {

ContractStats lowcost_beacons_run(double dt) {
  const lowcost_beacons::Problem p = lowcost_beacons::build(lowcost_beacons::make_tdomain(dt), 0.0);
  return p.cn->contract();
}

ContractStats drifting_clock_run(double dt) {
  const drifting_clock::Problem p = drifting_clock::build(TDomain::create(0.0, drifting_clock::kTf, dt), 0.0);
  return p.cn->contract();
}

void report(benchmark::State& state, const ContractStats& s) {
  state.counters["iterations"] = static_cast<double>(s.iterations);
  state.counters["calls"] = static_cast<double>(s.contractor_calls);
  state.counters["contract_s"] = s.time;
  if (s.empty) state.SkipWithError("empty result");
}

void BM_LowcostBeacons(benchmark::State& state) {
  ContractStats s;
  for (auto _ : state) s = lowcost_beacons_run(1.0 / static_cast<double>(state.range(0)));
  report(state, s);
}
BENCHMARK(BM_LowcostBeacons)->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);

void BM_DriftingClock(benchmark::State& state) {
  ContractStats s;
  for (auto _ : state) s = drifting_clock_run(1.0 / static_cast<double>(state.range(0)));
  report(state, s);
}
BENCHMARK(BM_DriftingClock)->Arg(20)->Arg(100)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

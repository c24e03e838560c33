// CtcDeriv (thesis Alg. 3-5): ns per slice of one contraction, FWD_BWD and
// one direction, for N = 1e3 .. 1e6 slices. The tube is x(t) = sin(t) with
// random inflation, v = cos(t) inflated (it straddles 0 about 40% of the
// time, the case where the polygon has its crossing), one gate known; each iteration
// restores the original tube first (a copy of two arrays, timed apart in
// BM_RestoreOnly so that it can be subtracted).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/interval/rounding_policies.h"
#include "sillage/tube/tdomain.h"
#include "sillage/tube/tube.h"

namespace {

using sillage::CtcDeriv;
using sillage::Interval;
using sillage::TDomain;
using sillage::TimePropag;
using sillage::Tube;

struct Problem {
  Tube x, v;
};

Problem make_problem(std::size_t n) {
  const double dt = 0.01;
  const auto td = TDomain::create(0.0, dt * static_cast<double>(n), dt);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> e(0.0, 0.5);
  std::vector<Interval> xs(td->nb_slices()), vs(td->nb_slices());
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const double t = td->t(k);
    xs[k] = Interval(std::sin(t) - 0.1 - e(rng), std::sin(t) + 0.1 + e(rng));
    vs[k] = Interval(std::cos(t) - 0.3 - e(rng), std::cos(t) + 0.3 + e(rng));
  }
  Tube x(td, xs);
  x.set_gate(0, Interval(-0.01, 0.01));
  return {x, Tube(td, vs)};
}

void set_counter(benchmark::State& state) {
  state.counters["ns_per_slice"] = benchmark::Counter(static_cast<double>(state.range(0)),
                                                      benchmark::Counter::kIsIterationInvariantRate |
                                                          benchmark::Counter::kInvert);
}

// kSoft: the software rounding policy even where the hardware one exists.
template <TimePropag kP, bool kSoft = false>
void BM_CtcDeriv(benchmark::State& state) {
  Problem p = make_problem(static_cast<std::size_t>(state.range(0)));
  const Tube x0 = p.x;
  const CtcDeriv ctc(kP);
  const bool saved = sillage::detail::hardware_rounding();
  if (kSoft) sillage::detail::set_hardware_rounding(false);
  for (auto _ : state) {
    p.x = x0;  // same TDomain: copied into p.x's storage, no allocation
    benchmark::DoNotOptimize(ctc.contract(p.x, p.v));
  }
  sillage::detail::set_hardware_rounding(saved);
  state.SetLabel(sillage::detail::hardware_rounding_available() && !kSoft ? "hardware rounding" : "software rounding");
  set_counter(state);
}

// The contraction of a tube already at its fixed point (what a network pays
// when nothing changes), without the restoring copy.
void BM_CtcDerivFixedPoint(benchmark::State& state) {
  Problem p = make_problem(static_cast<std::size_t>(state.range(0)));
  const CtcDeriv ctc;
  ctc.contract(p.x, p.v);
  for (auto _ : state) benchmark::DoNotOptimize(ctc.contract(p.x, p.v));
  set_counter(state);
}

void BM_RestoreOnly(benchmark::State& state) {
  Problem p = make_problem(static_cast<std::size_t>(state.range(0)));
  const Tube x0 = p.x;
  for (auto _ : state) {
    p.x = x0;
    benchmark::ClobberMemory();
  }
  set_counter(state);
}

}  // namespace

BENCHMARK(BM_CtcDeriv<TimePropag::FWD_BWD>)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CtcDeriv<TimePropag::FORWARD>)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CtcDeriv<TimePropag::BACKWARD>)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CtcDeriv<TimePropag::FWD_BWD, true>)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CtcDerivFixedPoint)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RestoreOnly)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();

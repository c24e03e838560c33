// CtcIvp (validated integration on tubes, docs/ivp.md): the targets of the
// design issue, each with its final width as a counter.
//  - SinIvp: x' = -sin x, t ∈ [0, 10], 10 slices, forward only; x0 from a
//    pool of 4096 points around 1 (the counter: width of x(10) for x0 = 1).
//  - Harmonic: x1' = x2, x2' = -x1 over 100 periods from a point, 100 slices.
//  - Lorenz: (10, 28, 8/3) from (15, 15, 36), t ∈ [0, 10], 100 slices.
//  - DeadReckoning: thesis 3.4, inputs within 1/1000, x0 in the box (3.17),
//    t ∈ [0, 64], δ = 0.5 (counters: the final x1, x2 bounds).
//  - DeadReckoningCtcDeriv/δ: the same data through the CtcDeriv network of
//    the example (3.18) (examples/cpp/dead_reckoning_network.h), δ = 0.5,
//    0.05, 0.005 (slices are its only lever).
//  - ObservationRerun/0|1: a tube of 1000 slices from x0 ∈ [0.9, 1.1] already
//    contracted; an observation narrows one gate in the second half (pool
//    of 4096 observations) and CtcIvp runs again: /0 integrates the whole
//    tube, /1 with the memory of the network node (ivp_memory.h) resumes
//    at the observation (the copies of the tube and memory are not timed).
// Each iteration copies a fresh tube (cheap beside the integration).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "dead_reckoning_ivp.h"
#include "dead_reckoning_network.h"
#include "sillage/dynamics/ctc_ivp.h"
#include "sillage/dynamics/ivp_memory.h"
#include "sillage/interval/elementary.h"
#include "sillage/tube/tdomain.h"
#include "sillage/tube/tube_vector.h"

namespace {

using namespace sillage;

void BM_SinIvp(benchmark::State& state) {
  const auto td = TDomain::create(0.0, 10.0, 1.0);
  const CtcIvp ctc(Function({"x"}, "-sin(x)"), 0, static_cast<int>(state.range(0)), TimePropag::FORWARD);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> d(0.9, 1.1);
  std::vector<double> pool(4096);
  for (double& x0 : pool) x0 = d(rng);
  std::size_t i = 0;
  for (auto _ : state) {
    Tube x(td);
    x.set_gate(0, Interval(pool[i++ % pool.size()]));
    benchmark::DoNotOptimize(ctc.contract(x));
  }
  Tube x(td);
  x.set_gate(0, Interval(1.0));
  ctc.contract(x);
  state.counters["width_x10"] = x.gate(td->nb_slices()).diam();
}
BENCHMARK(BM_SinIvp)->Arg(12)->Arg(16)->Arg(20)->Unit(benchmark::kMillisecond);

void BM_ObservationRerun(benchmark::State& state) {
  const bool with_memory = state.range(0) == 1;
  const auto td = TDomain::create(0.0, 10.0, 0.01);
  const std::size_t N = td->nb_slices();
  const CtcIvp ctc(Function({"x"}, "-sin(x)"), 0, 16);
  TubeVector base(td, 1);
  base.set_gate(0, IntervalVector{Interval(0.9, 1.1)});
  detail::IvpMemory base_memory;
  ctc.contract(base, nullptr, base_memory);
  struct Obs {
    std::size_t k;
    Interval y;
  };
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> x0(0.9, 1.1);
  std::uniform_int_distribution<std::size_t> gate(N / 2, N);
  std::vector<Obs> pool(4096);
  for (Obs& o : pool) {
    o.k = gate(rng);
    // x(t) = 2 atan(e^{-t} tan(x0/2)), observed within 1e-4.
    const Interval t(td->t(o.k));
    o.y = (Interval(2.0) * atan(exp(-t) * tan(Interval(x0(rng)) / Interval(2.0)))).inflate(1e-4);
  }
  std::size_t i = 0;
  double w0 = 0;  // the mean width of x(0) after the run, same observations in /0 and /1
  for (auto _ : state) {
    state.PauseTiming();
    TubeVector x = base;
    detail::IvpMemory memory = base_memory;
    const Obs& o = pool[i++ % pool.size()];
    x[0].set_gate(o.k, x.gate(o.k)[0] & o.y);
    state.ResumeTiming();
    if (with_memory) {
      benchmark::DoNotOptimize(ctc.contract(x, nullptr, memory));
    } else {
      benchmark::DoNotOptimize(ctc.contract(x));
    }
    w0 += x.gate(0)[0].diam();
  }
  state.counters["mean_width_x0"] = w0 / static_cast<double>(i);
}
BENCHMARK(BM_ObservationRerun)->Arg(0)->Arg(1)->Iterations(16)->Unit(benchmark::kMillisecond);

void BM_Harmonic100Periods(benchmark::State& state) {
  const double T = 200 * M_PI;
  const auto td = TDomain::create(0.0, T, T / 100);
  const CtcIvp ctc(Function({"x1", "x2"}, "(x2, -x1)"), 0, 20, TimePropag::FORWARD);
  double w = 0;
  for (auto _ : state) {
    TubeVector x(td, 2);
    x.set_gate(0, IntervalVector{Interval(0.0), Interval(1.0)});
    benchmark::DoNotOptimize(ctc.contract(x));
    w = x.gate(td->nb_slices()).max_diam();
  }
  state.counters["final_width"] = w;
}
BENCHMARK(BM_Harmonic100Periods)->Unit(benchmark::kMillisecond);

void BM_Lorenz(benchmark::State& state) {
  const auto td = TDomain::create(0.0, 10.0, 0.1);
  const CtcIvp ctc(Function({"x", "y", "z"}, "(10*(y - x), x*(28 - z) - y, x*y - 8/3*z)"), 0, 20,
                   TimePropag::FORWARD);
  double w = 0;
  for (auto _ : state) {
    TubeVector x(td, 3);
    x.set_gate(0, IntervalVector{Interval(15.0), Interval(15.0), Interval(36.0)});
    benchmark::DoNotOptimize(ctc.contract(x));
    w = x.gate(td->nb_slices()).max_diam();
  }
  state.counters["final_width"] = w;
}
BENCHMARK(BM_Lorenz)->Unit(benchmark::kMillisecond);

void BM_DeadReckoning(benchmark::State& state) {
  // The known part of the inputs is written in f with the time as a state
  // (τ' = 1); only the noise is an input tube.
  const auto td = TDomain::create(0.0, 64.0, 0.5);
  const TubeVector u(td, 2, dead_reckoning::ivp_noise());
  const CtcIvp ctc = dead_reckoning::ivp_contractor();
  const IntervalVector x0 = dead_reckoning::ivp_initial_gate();
  IntervalVector end;
  for (auto _ : state) {
    TubeVector x(td, 5);
    x.set_gate(0, x0);
    benchmark::DoNotOptimize(ctc.contract(x, u));
    end = x.gate(td->nb_slices());
  }
  state.counters["x1_lb"] = end[0].lb();
  state.counters["x1_ub"] = end[0].ub();
  state.counters["x2_lb"] = end[1].lb();
  state.counters["x2_ub"] = end[1].ub();
}
BENCHMARK(BM_DeadReckoning)->Unit(benchmark::kMillisecond);

void BM_DeadReckoningCtcDeriv(benchmark::State& state) {
  const double dt = state.range(0) / 1000.0;
  const auto td = TDomain::create(0.0, 64.0, dt);
  const Tube u1(td, "-9/20*cos(t/5) + [-0.001,0.001]"), u2(td, "1/10 + sin(t/4) + [-0.001,0.001]");
  const Interval c = Interval(-1, 1) / Interval(100);
  const IntervalVector x0{Interval(-1, 1), Interval(-1, 1), Interval::half_pi() + c, c};
  IntervalVector end;
  for (auto _ : state) {
    auto x = std::make_shared<TubeVector>(td, 4), v = std::make_shared<TubeVector>(td, 4);
    x->set_gate(0, x0);
    (*v)[2] = u1;
    (*v)[3] = u2;
    ContractorNetwork cn;
    dead_reckoning::add_constraints(cn, x, v);
    benchmark::DoNotOptimize(cn.contract());
    end = x->gate(td->nb_slices());
  }
  state.counters["x1_lb"] = end[0].lb();
  state.counters["x1_ub"] = end[0].ub();
  state.counters["x2_lb"] = end[1].lb();
  state.counters["x2_ub"] = end[1].ub();
}
BENCHMARK(BM_DeadReckoningCtcDeriv)->Arg(500)->Arg(50)->Arg(5)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

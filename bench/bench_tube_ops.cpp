// Per-slice cost of building and combining tubes, for N = 1e4, 1e5, 1e6:
// construction from an expression of t (one batch evaluation), arithmetic
// (+, *, cos), the pointwise contractor v - x4 cos x3 = 0 on every slice and
// gate, and the same in a ContractorNetwork. Counter ns_per_slice. The
// construction shares its chunks among threads: its figures are wall time,
// with all the threads of the machine and with one thread.
#include <benchmark/benchmark.h>

#include <functional>
#include <memory>

#include <tbb/global_control.h>

#include "sillage/cn/contractor_network.h"
#include "sillage/interval/elementary.h"
#include "sillage/tube/tube_arithmetic.h"
#include "sillage/tube/tube_ctc.h"

namespace {

using sillage::Interval;
using sillage::TDomain;
using sillage::Tube;

std::shared_ptr<TDomain> domain(const benchmark::State& state) {
  return TDomain::create(0.0, 1e-3 * static_cast<double>(state.range(0)), 1e-3);
}

void per_slice(benchmark::State& state) {
  state.counters["ns_per_slice"] = benchmark::Counter(
      static_cast<double>(state.range(0)), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// range(1): the number of threads allowed (0: the machine's).
tbb::global_control thread_limit(const benchmark::State& state) {
  const std::size_t threads = state.range(1) > 0 ? static_cast<std::size_t>(state.range(1))
                                                 : tbb::global_control::active_value(
                                                       tbb::global_control::max_allowed_parallelism);
  return tbb::global_control(tbb::global_control::max_allowed_parallelism, threads);
}

void BM_TubeFromExpression(benchmark::State& state) {
  const auto td = domain(state);
  const tbb::global_control limit = thread_limit(state);
  for (auto _ : state) {
    Tube x(td, "-9/20*cos(t/5) + [-0.001,0.001]");
    benchmark::DoNotOptimize(x);
  }
  per_slice(state);
}

template <class Op>
void BM_TubeBinary(benchmark::State& state, Op op) {
  const auto td = domain(state);
  const Tube a(td, "sin(t)"), b(td, "cos(t)");
  for (auto _ : state) {
    Tube c = op(a, b);
    benchmark::DoNotOptimize(c);
  }
  per_slice(state);
}

// op(a) for the tube a of the expression `a_of_t`, in wall time, with range(1) threads.
template <class Op>
void unary_bench(benchmark::State& state, const char* a_of_t, Op op) {
  const auto td = domain(state);
  const tbb::global_control limit = thread_limit(state);
  const Tube a(td, a_of_t);
  for (auto _ : state) {
    Tube c = op(a);
    benchmark::DoNotOptimize(c);
  }
  per_slice(state);
}

void BM_TubeCos(benchmark::State& state) {
  unary_bench(state, "t/5 + [-0.01, 0.01]", [](const Tube& a) { return cos(a); });
}
void BM_TubeExp(benchmark::State& state) {
  unary_bench(state, "cos(t)/2 + [-0.01, 0.01]", [](const Tube& a) { return exp(a); });
}
void BM_TubeCopy(benchmark::State& state) {
  unary_bench(state, "cos(t)/2 + [-0.01, 0.01]", [](const Tube& a) { return Tube(a); });
}

const sillage::CtcFunction& v_ctc() {
  static const sillage::CtcFunction c(sillage::Function({"v", "a", "b"}, "v - b*cos(a)"));
  return c;
}

void BM_TubePointwiseContractor(benchmark::State& state) {
  const auto td = domain(state);
  const Tube x3(td, "t/5 + [-0.01, 0.01]"), x4(td, "[9.9, 10.1]");
  for (auto _ : state) {
    state.PauseTiming();
    Tube a = x3, b = x4, v(td, Interval(-20, 20));
    state.ResumeTiming();
    benchmark::DoNotOptimize(sillage::contract(v_ctc(), {&v, &a, &b}));
  }
  per_slice(state);
}

void BM_TubeNetworkPointwise(benchmark::State& state) {
  const auto td = domain(state);
  const Tube x3(td, "t/5 + [-0.01, 0.01]"), x4(td, "[9.9, 10.1]");
  const auto ctc = std::make_shared<sillage::CtcFunction>(v_ctc());
  for (auto _ : state) {
    state.PauseTiming();
    auto a = std::make_shared<Tube>(x3), b = std::make_shared<Tube>(x4);
    auto v = std::make_shared<Tube>(td, Interval(-20, 20));
    sillage::ContractorNetwork cn;
    cn.add(ctc, {v, a, b});
    state.ResumeTiming();
    benchmark::DoNotOptimize(cn.contract());
  }
  per_slice(state);
}

BENCHMARK(BM_TubeFromExpression)
    ->ArgsProduct({{10000, 100000, 1000000}, {0, 1}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TubeBinary, add, std::plus<>())
    ->RangeMultiplier(10)->Range(10000, 1000000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TubeBinary, mul, std::multiplies<>())
    ->RangeMultiplier(10)->Range(10000, 1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TubeCos)
    ->ArgsProduct({{10000, 100000, 1000000}, {0, 1}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TubeExp)
    ->ArgsProduct({{10000, 100000, 1000000}, {0, 1}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TubeCopy)
    ->ArgsProduct({{10000, 100000, 1000000}, {0, 1}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TubePointwiseContractor)->RangeMultiplier(10)->Range(10000, 1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TubeNetworkPointwise)->RangeMultiplier(10)->Range(10000, 1000000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

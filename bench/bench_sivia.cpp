// SIVIA on the two-beacon range-only problem of thesis 2.4.3 (Table 2.2,
// Fig. 2.13): beacons (8, 5) and (7, 2.2), ranges [9.03, 9.83] and
// [6.94, 7.74], robot at (0, 0), X0 = [-10, 10]^2. Plain SIVIA (Alg. 1) with
// the natural inclusion function; Alg. 1 with a contraction before each
// bisection (Fig. 2.13; one CtcFunction per beacon); separators (one
// SepFunction per beacon); contractors alone (outer approximation). At
// eps = 0.01 and 0.001, on 1 and 2 threads. Counters: leaves per tag, nodes,
// volumes, connected components of the outer approximation.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <memory>

#include "sillage/ctc/ctc_algebra.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/ctc/sep_algebra.h"
#include "sillage/ctc/sep_function.h"
#include "sillage/paving/sivia_function.h"

using namespace sillage;

namespace {

struct TwoBeacons {
  Function ranges{{"x1", "x2"}, "(sqrt((x1 - 8)^2 + (x2 - 5)^2), sqrt((x1 - 7)^2 + (x2 - 2.2)^2))"};
  IntervalVector y{Interval(9.03, 9.83), Interval(6.94, 7.74)};
  IntervalVector x0{Interval(-10, 10), Interval(-10, 10)};
  CtcInter ctc{{std::make_shared<CtcFunction>(ranges[0], y[0]), std::make_shared<CtcFunction>(ranges[1], y[1])}};
  SepInter sep{{std::make_shared<SepFunction>(ranges[0], y[0]), std::make_shared<SepFunction>(ranges[1], y[1])}};
};

const TwoBeacons& problem() {
  static const TwoBeacons p;
  return p;
}

double eps_of(const benchmark::State& state) { return state.range(0) == 0 ? 0.01 : 0.001; }

void report(benchmark::State& state, const Paving& p) {
  state.counters["eps"] = eps_of(state);
  state.counters["threads"] = static_cast<double>(state.range(1));
  state.counters["nodes"] = static_cast<double>(p.nb_nodes());
  state.counters["leaves"] = static_cast<double>(p.nb_leaves());
  state.counters["inner"] = static_cast<double>(p.count(PavingTag::Inner));
  state.counters["boundary"] = static_cast<double>(p.count(PavingTag::Boundary));
  state.counters["outside"] = static_cast<double>(p.count(PavingTag::Outside));
  state.counters["vol_inner"] = p.volume(PavingTag::Inner);
  state.counters["vol_outer"] = p.outer_volume();
  state.counters["components"] = static_cast<double>(p.components().size());
}

template <class Run>
void run(benchmark::State& state, Run solve) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(state.range(1)));
  Paving p;
  for (auto _ : state) {
    p = solve(eps_of(state));
    benchmark::DoNotOptimize(p);
  }
  report(state, p);
}

void BM_SiviaPlain(benchmark::State& state) {
  const auto& b = problem();
  run(state, [&](double eps) { return sivia(b.x0, b.ranges, b.y, eps); });
}

// Fig. 2.13: the inclusion test, then a contraction before each bisection.
void BM_SiviaTestThenContract(benchmark::State& state) {
  const auto& b = problem();
  run(state, [&](double eps) { return sivia(b.x0, b.ranges, b.y, b.ctc, eps); });
}

// Contractors only (no inclusion test): an outer approximation whose
// interior is bisected down to eps too, hence many more boxes.
void BM_SiviaContractorsOnly(benchmark::State& state) {
  const auto& b = problem();
  run(state, [&](double eps) { return sivia(b.x0, static_cast<const Ctc&>(b.ctc), eps); });
}

void BM_SiviaSeparators(benchmark::State& state) {
  const auto& b = problem();
  run(state, [&](double eps) { return sivia(b.x0, static_cast<const Sep&>(b.sep), eps); });
}

// Args: {eps index (0: 0.01, 1: 0.001), threads}.
void args(benchmark::internal::Benchmark* bm) {
  bm->ArgNames({"eps", "threads"})->Args({0, 1})->Args({0, 2})->Args({1, 1})->Args({1, 2});
  bm->Unit(benchmark::kMillisecond)->UseRealTime();
}

}  // namespace

BENCHMARK(BM_SiviaPlain)->Apply(args);
BENCHMARK(BM_SiviaTestThenContract)->Apply(args);
BENCHMARK(BM_SiviaSeparators)->Apply(args);
// eps = 0.01 only: at 0.001 the contractor-only paving has ~7 million leaves.
BENCHMARK(BM_SiviaContractorsOnly)->ArgNames({"eps", "threads"})->Args({0, 1})->Args({0, 2})
    ->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();

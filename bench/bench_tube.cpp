// Synthesis tree (thesis 3.3.1): query cost of [x]([t]) and of the integrals
// (3.8)-(3.9) for N = 1e4, 1e5, 1e6 slices (should be flat in N), tree build
// and primitive cost per slice, memory per slice. Queries use random [t]
// spread over the whole domain (wide ranges: the O(log N) worst case for the
// tree walk). BM_Eval*, BM_Integral*: on a tree built from arrays (no tube);
// BM_Tube*: through a tube and its cached tree, as user code does.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "sillage/tube/synthesis_tree.h"
#include "sillage/tube/tdomain.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_integral.h"

namespace {

using sillage::Interval;
using sillage::SynthesisTree;
using sillage::TDomain;
using sillage::Tube;

Tube random_tube(std::size_t n) {
  const auto td = TDomain::create(0.0, 0.01 * static_cast<double>(n), 0.01);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-1, 1), w(0, 0.5);
  std::vector<Interval> s(td->nb_slices());
  for (auto& y : s) {
    const double c = u(rng);
    y = Interval(c, c + w(rng));
  }
  return Tube(td, s);
}

std::vector<Interval> random_times(const Tube& x, bool degenerate) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> t(x.tdomain()->t0(), x.tdomain()->tf());
  std::vector<Interval> r(4096);
  for (auto& y : r) {
    double a = t(rng), b = degenerate ? a : t(rng);
    if (a > b) std::swap(a, b);
    y = Interval(a, b);
  }
  return r;
}

SynthesisTree tree_of(const Tube& x) { return SynthesisTree(x.tdomain()->times(), x.slices(), x.gates()); }

// The build of a tube's tree (Tube::synthesis_tree after a modification).
// Counters: bytes per slice of the tree, and of the tube with its tree.
void BM_TreeBuild(benchmark::State& state) {
  Tube x = random_tube(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    x.write().commit();  // a modification: the tree is built again
    benchmark::DoNotOptimize(x.synthesis_tree());
  }
  const auto n = static_cast<double>(state.range(0));
  state.counters["ns_per_slice"] = benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate |
                                                             benchmark::Counter::kInvert);
  state.counters["tree_bytes_per_slice"] = static_cast<double>(x.synthesis_tree()->memory_bytes()) / n;
  state.counters["tube_bytes_per_slice"] = static_cast<double>(x.memory_bytes()) / n;  // with the tree
}

template <bool kDegenerate>
void BM_EvalHull(benchmark::State& state) {
  const Tube x = random_tube(static_cast<std::size_t>(state.range(0)));
  const SynthesisTree tree = tree_of(x);
  const auto ts = random_times(x, kDegenerate);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(tree.eval(ts[i++ & 4095]));
  }
}

void BM_IntegralPoint(benchmark::State& state) {
  const Tube x = random_tube(static_cast<std::size_t>(state.range(0)));
  const SynthesisTree tree = tree_of(x);
  const auto ts = random_times(x, true);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(sillage::integral(tree, ts[i++ & 4095].lb()));
  }
}

// integral([t1], [t2]) on a tree built apart, or through the tube (its cached tree).
template <bool kThroughTube>
void BM_IntegralBounds(benchmark::State& state) {
  const Tube x = random_tube(static_cast<std::size_t>(state.range(0)));
  const SynthesisTree tree = tree_of(x);
  const auto t1 = random_times(x, false);
  auto t2 = t1;
  std::reverse(t2.begin(), t2.end());
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ & 4095;
    if constexpr (kThroughTube) {
      benchmark::DoNotOptimize(sillage::integral(x, t1[k], t2[k]));
    } else {
      benchmark::DoNotOptimize(sillage::integral(tree, t1[k], t2[k]));
    }
  }
}

void BM_Primitive(benchmark::State& state) {
  const Tube x = random_tube(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    Tube p = sillage::primitive(x, Interval(0.0));
    benchmark::DoNotOptimize(p);
  }
  state.counters["ns_per_slice"] = benchmark::Counter(static_cast<double>(state.range(0)),
                                                      benchmark::Counter::kIsIterationInvariantRate |
                                                          benchmark::Counter::kInvert);
}

// Tube::operator()([t]): through the tube's cached tree beyond 256 slices
// (each query also checks that the tree is current).
void BM_TubeEvalScan(benchmark::State& state) {
  const Tube x = random_tube(static_cast<std::size_t>(state.range(0)));
  const auto ts = random_times(x, false);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(x(ts[i++ & 4095]));
  }
}

BENCHMARK(BM_TreeBuild)->RangeMultiplier(10)->Range(10000, 1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EvalHull<true>)->Name("BM_EvalPoint")->RangeMultiplier(10)->Range(10000, 1000000);
BENCHMARK(BM_EvalHull<false>)->Name("BM_EvalHull")->RangeMultiplier(10)->Range(10000, 1000000);
BENCHMARK(BM_IntegralPoint)->RangeMultiplier(10)->Range(10000, 1000000);
BENCHMARK(BM_IntegralBounds<false>)->Name("BM_IntegralBounds")->RangeMultiplier(10)->Range(10000, 1000000);
BENCHMARK(BM_Primitive)->RangeMultiplier(10)->Range(10000, 1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TubeEvalScan)->RangeMultiplier(10)->Range(10000, 1000000);
BENCHMARK(BM_IntegralBounds<true>)->Name("BM_TubeIntegralBounds")->RangeMultiplier(10)->Range(10000, 1000000);

}  // namespace

BENCHMARK_MAIN();

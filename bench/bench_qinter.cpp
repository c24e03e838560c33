// The q-relaxed intersection: q_inter on m intervals, and CtcQInter over m
// contractors (m = 10, 100, 1000, q = m / 10) of two kinds: box constraints
// (the cost of the relaxation itself) and range constraints (rings, a
// realistic contractor: one HC4 pass each). Each iteration takes the next
// input from a pool of 4096 random ones, so that no input is seen twice in a row.
#include <benchmark/benchmark.h>

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "sillage/ctc/ctc_box.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/ctc/ctc_qinter.h"

using namespace sillage;

namespace {

constexpr std::size_t kPool = 4096;

Interval random_interval(std::mt19937_64& rng, double width) {
  std::uniform_real_distribution<double> u(-50, 50), w(0, width);
  const double a = u(rng);
  return Interval(a, a + w(rng));
}

// Pool of input boxes in [-50, 60]^2.
std::vector<IntervalVector> input_pool() {
  std::mt19937_64 rng(1);
  std::vector<IntervalVector> pool;
  for (std::size_t i = 0; i < kPool; ++i) pool.push_back({random_interval(rng, 60), random_interval(rng, 60)});
  return pool;
}

std::vector<CtcPtr> box_ctcs(std::size_t m) {
  std::mt19937_64 rng(2);
  std::vector<CtcPtr> v;
  for (std::size_t i = 0; i < m; ++i) {
    v.push_back(std::make_shared<CtcBox>(IntervalVector{random_interval(rng, 40), random_interval(rng, 40)}));
  }
  return v;
}

std::vector<CtcPtr> ring_ctcs(std::size_t m) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> pos(-40, 40);
  std::uniform_real_distribution<double> r(5, 60);
  std::vector<CtcPtr> v;
  for (std::size_t i = 0; i < m; ++i) {
    const Function d({"x1", "x2"}, "sqrt((x1 - (" + std::to_string(pos(rng)) + "))^2 + (x2 - (" +
                                       std::to_string(pos(rng)) + "))^2)");
    const double c = r(rng);
    v.push_back(std::make_shared<CtcFunction>(d, Interval(c - 0.1, c + 0.1)));
  }
  return v;
}

void run_ctc(benchmark::State& state, const std::vector<CtcPtr>& ctcs) {
  static const auto pool = input_pool();
  const CtcQInter ctc(ctcs, static_cast<int>(ctcs.size() / 10));
  std::size_t k = 0, empty = 0;
  for (auto _ : state) {
    IntervalVector x = pool[k++ % kPool];
    ctc.contract(x);
    empty += x.is_empty();
    benchmark::DoNotOptimize(x);
  }
  state.counters["m"] = static_cast<double>(ctcs.size());
  state.counters["empty_ratio"] = static_cast<double>(empty) / static_cast<double>(k);
  state.SetItemsProcessed(static_cast<int64_t>(k * ctcs.size()));  // contractor calls
}

void BM_QInterIntervals(benchmark::State& state) {
  const auto m = static_cast<std::size_t>(state.range(0));
  std::mt19937_64 rng(4);
  std::vector<std::vector<Interval>> pool(256);
  for (auto& xs : pool) {
    for (std::size_t i = 0; i < m; ++i) xs.push_back(random_interval(rng, 60));
  }
  std::size_t k = 0;
  for (auto _ : state) benchmark::DoNotOptimize(q_inter(pool[k++ % pool.size()], static_cast<int>(m / 10)));
  state.SetItemsProcessed(static_cast<int64_t>(k * m));
}

void BM_CtcQInterBoxes(benchmark::State& state) { run_ctc(state, box_ctcs(static_cast<std::size_t>(state.range(0)))); }
void BM_CtcQInterRings(benchmark::State& state) { run_ctc(state, ring_ctcs(static_cast<std::size_t>(state.range(0)))); }

}  // namespace

BENCHMARK(BM_QInterIntervals)->ArgName("m")->Arg(10)->Arg(100)->Arg(1000);
BENCHMARK(BM_CtcQInterBoxes)->ArgName("m")->Arg(10)->Arg(100)->Arg(1000);
BENCHMARK(BM_CtcQInterRings)->ArgName("m")->Arg(10)->Arg(100)->Arg(1000);

BENCHMARK_MAIN();

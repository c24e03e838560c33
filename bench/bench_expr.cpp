// Expression layer timings: natural evaluation, HC4-revise and batch
// evaluation of the range function of the thesis (2.27), ns per call/element.
#include <benchmark/benchmark.h>

#include <random>

#include "sillage/expr/function.h"

using namespace sillage;

namespace {

const Function& range() {
  static const Function f({"x1", "x2"}, "sqrt((x1 + 0.5)^2 + (x2 - 4.0)^2)");
  return f;
}

// Random boxes, 2^16 of them: a short cycle would let the branch predictor
// learn the sign cases of the interval operations and flatter the timings.
std::vector<IntervalVector> boxes(std::size_t n) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> c(-5, 5), w(0, 1);
  std::vector<IntervalVector> xs;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = c(rng), b = c(rng);
    xs.push_back(IntervalVector{Interval(a, a + w(rng)), Interval(b, b + w(rng))});
  }
  return xs;
}

void BM_Eval(benchmark::State& state) {
  const auto xs = boxes(1 << 16);
  std::size_t k = 0;
  for (auto _ : state) benchmark::DoNotOptimize(range().eval(xs[k++ & 0xffff]));
}
BENCHMARK(BM_Eval);

void BM_EvalVector(benchmark::State& state) {
  const auto xs = boxes(1 << 16);
  std::size_t k = 0;
  for (auto _ : state) benchmark::DoNotOptimize(range().eval_vector(xs[k++ & 0xffff]));
}
BENCHMARK(BM_EvalVector);

void BM_Hc4Revise(benchmark::State& state) {
  const auto xs = boxes(1 << 16);
  const IntervalVector y{Interval(3.63, 4.43)};
  std::size_t k = 0;
  for (auto _ : state) {
    IntervalVector x = xs[k++ & 0xffff];
    benchmark::DoNotOptimize(range().hc4_revise(x, y));
  }
}
BENCHMARK(BM_Hc4Revise);

void BM_CenteredEval(benchmark::State& state) {
  const auto xs = boxes(1 << 16);
  std::size_t k = 0;
  for (auto _ : state) benchmark::DoNotOptimize(range().centered_eval(xs[k++ & 0xffff]));
}
BENCHMARK(BM_CenteredEval);

// Per element: structure-of-arrays columns, as tubes use it.
void BM_EvalBatchColumns(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const auto xs = boxes(n);
  std::vector<Interval> x1(n), x2(n), y(n);
  for (std::size_t k = 0; k < n; ++k) x1[k] = xs[k][0], x2[k] = xs[k][1];
  const Interval* in[] = {x1.data(), x2.data()};
  Interval* out[] = {y.data()};
  for (auto _ : state) {
    range().eval_batch(in, n, out);
    benchmark::DoNotOptimize(y.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}
BENCHMARK(BM_EvalBatchColumns)->Arg(1 << 16);

// Per element: a vector of boxes in, a vector of boxes out.
void BM_EvalBatchBoxes(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const auto xs = boxes(n);
  for (auto _ : state) benchmark::DoNotOptimize(range().eval_batch(xs));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}
BENCHMARK(BM_EvalBatchBoxes)->Arg(1 << 16);

void BM_Parse(benchmark::State& state) {
  for (auto _ : state) {
    Function f({"x1", "x2"}, "sqrt((x1 + 0.5)^2 + (x2 - 4.0)^2)");
    benchmark::DoNotOptimize(f.nb_vars());
  }
}
BENCHMARK(BM_Parse);

}  // namespace

BENCHMARK_MAIN();

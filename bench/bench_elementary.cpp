// Time per interval operation of the elementary functions (and, for scale,
// of + * / sqrt and of the raw libm calls). Inputs: 4096 random intervals of
// small to moderate width in the range where the function is usually used.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "sillage/interval/elementary.h"
#include "sillage/interval/interval.h"

using sillage::Interval;

namespace {

constexpr std::size_t kN = 4096;

std::vector<Interval> inputs(double lo, double hi, double max_width) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> pos(lo, hi), width(0, max_width);
  std::vector<Interval> v;
  v.reserve(kN);
  for (std::size_t i = 0; i < kN; ++i) {
    const double a = pos(rng);
    v.emplace_back(a, a + width(rng));
  }
  return v;
}

template <class F>
void run(benchmark::State& state, const std::vector<Interval>& xs, F f) {
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(f(xs[i]));
    i = (i + 1) & (kN - 1);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

#define SILLAGE_BENCH_UNARY(name, lo, hi, width, expr)                 \
  void BM_##name(benchmark::State& state) {                            \
    static const std::vector<Interval> xs = inputs(lo, hi, width);     \
    run(state, xs, [](const Interval& x) { return expr; });            \
  }                                                                    \
  BENCHMARK(BM_##name)

SILLAGE_BENCH_UNARY(exp, -20, 20, 1, sillage::exp(x));
SILLAGE_BENCH_UNARY(log, 1e-3, 1e3, 1, sillage::log(x));
SILLAGE_BENCH_UNARY(sin, -10, 10, 1, sillage::sin(x));
SILLAGE_BENCH_UNARY(cos, -10, 10, 1, sillage::cos(x));
SILLAGE_BENCH_UNARY(sin_narrow, -10, 10, 1e-6, sillage::sin(x));
SILLAGE_BENCH_UNARY(sin_huge, 1e15, 1e16, 1e3, sillage::sin(x));
SILLAGE_BENCH_UNARY(tan, -1.5, 1.5, 0.1, sillage::tan(x));
SILLAGE_BENCH_UNARY(asin, -1, 0.9, 0.1, sillage::asin(x));
SILLAGE_BENCH_UNARY(acos, -1, 0.9, 0.1, sillage::acos(x));
SILLAGE_BENCH_UNARY(atan, -10, 10, 1, sillage::atan(x));
SILLAGE_BENCH_UNARY(sinh, -10, 10, 1, sillage::sinh(x));
SILLAGE_BENCH_UNARY(cosh, -10, 10, 1, sillage::cosh(x));
SILLAGE_BENCH_UNARY(tanh, -10, 10, 1, sillage::tanh(x));
SILLAGE_BENCH_UNARY(pow_int3, -10, 10, 1, sillage::pow(x, 3));
SILLAGE_BENCH_UNARY(pow_int_m2, 0.1, 10, 1, sillage::pow(x, -2));
SILLAGE_BENCH_UNARY(pow_real, 0.1, 10, 1, sillage::pow(x, Interval(1.3, 2.7)));
SILLAGE_BENCH_UNARY(root3, -10, 10, 1, sillage::root(x, 3));
SILLAGE_BENCH_UNARY(atan2, -10, 10, 1, sillage::atan2(x, Interval(0.5, 2.0)));
SILLAGE_BENCH_UNARY(add, -10, 10, 1, x + Interval(0.5, 2.0));
SILLAGE_BENCH_UNARY(mul, -10, 10, 1, x * Interval(-0.5, 2.0));
SILLAGE_BENCH_UNARY(div, -10, 10, 1, x / Interval(0.5, 2.0));
SILLAGE_BENCH_UNARY(sqrt, 0, 100, 1, sillage::sqrt(x));

// The raw libm cost (two calls, one per bound) for comparison.
SILLAGE_BENCH_UNARY(libm_exp_x2, -20, 20, 1, std::exp(x.lb()) + std::exp(x.ub()));
SILLAGE_BENCH_UNARY(libm_sin_x2, -10, 10, 1, std::sin(x.lb()) + std::sin(x.ub()));
SILLAGE_BENCH_UNARY(libm_log_x2, 1e-3, 1e3, 1, std::log(x.lb()) + std::log(x.ub()));

}  // namespace

BENCHMARK_MAIN();

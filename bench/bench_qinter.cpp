// The q-relaxed intersection: q_inter on m intervals, and CtcQInter over m
// contractors (m = 10, 100, 1000, q = m / 10) of two kinds: box constraints
// (the cost of the relaxation itself) and range constraints (rings, a
// realistic contractor: one HC4 pass each). One constraint in ten is wrong, so
// that the true point survives and few results are empty (counter
// empty_ratio). Each iteration takes the next input from a pool of 4096
// random boxes around the true point, so that no input is seen twice in a row.
// Then the whole GOMNE loop on 20 of the ranges. Last, CtcQEval's direct call
// on a tube: m position fixes of x(t) = (cos t, sin t), one in ten 2 m off.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "sillage/ctc/ctc_box.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/ctc/ctc_qinter.h"
#include "sillage/ctc/gomne.h"
#include "sillage/dynamics/ctc_qeval.h"

using namespace sillage;

namespace {

constexpr std::size_t kPool = 4096;

// [-u, v] with u, v drawn in (0, w]: an interval around 0.
Interval around_zero(std::mt19937_64& rng, double w) {
  std::uniform_real_distribution<double> u(0, w);
  return Interval(-u(rng), u(rng));
}

bool is_wrong(std::size_t i) { return i % 10 == 9; }  // one constraint in ten, q = m / 10

// Pool of input boxes around the true point (0, 0), up to 30 wide.
std::vector<IntervalVector> input_pool() {
  std::mt19937_64 rng(1);
  std::vector<IntervalVector> pool;
  for (std::size_t i = 0; i < kPool; ++i) pool.push_back({around_zero(rng, 15), around_zero(rng, 15)});
  return pool;
}

// Boxes containing (0, 0), but one in ten shifted away from it.
std::vector<CtcPtr> box_ctcs(std::size_t m) {
  std::mt19937_64 rng(2);
  std::vector<CtcPtr> v;
  for (std::size_t i = 0; i < m; ++i) {
    IntervalVector b{around_zero(rng, 10), around_zero(rng, 10)};
    if (is_wrong(i)) b += IntervalVector{Interval(25), Interval(-25)};
    v.push_back(std::make_shared<CtcBox>(b));
  }
  return v;
}

// Ranges from integer beacons to (0, 0), +-0.1; one in ten off by 5 to 15.
std::vector<CtcPtr> ring_ctcs(std::size_t m) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> pos(-40, 40);
  std::uniform_real_distribution<double> shift(5, 15);
  std::vector<CtcPtr> v;
  for (std::size_t i = 0; i < m; ++i) {
    const int bx = pos(rng), by = pos(rng);
    const Function d({"x1", "x2"}, "sqrt((x1 - (" + std::to_string(bx) + "))^2 + (x2 - (" + std::to_string(by) +
                                       "))^2)");
    const double r = std::hypot(bx, by) + (is_wrong(i) ? shift(rng) : 0.0);
    v.push_back(std::make_shared<CtcFunction>(d, Interval(r - 0.1, r + 0.1)));
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
  std::uniform_real_distribution<double> shift(-1, 1);
  std::vector<std::vector<Interval>> pool(256);  // m intervals around a common point, shifted a little
  for (auto& xs : pool) {
    for (std::size_t i = 0; i < m; ++i) xs.push_back(around_zero(rng, 10) + shift(rng));
  }
  std::size_t k = 0;
  for (auto _ : state) benchmark::DoNotOptimize(q_inter(pool[k++ % pool.size()], static_cast<int>(m / 10)));
  state.SetItemsProcessed(static_cast<int64_t>(k * m));
}

void BM_CtcQInterBoxes(benchmark::State& state) { run_ctc(state, box_ctcs(static_cast<std::size_t>(state.range(0)))); }
void BM_CtcQInterRings(benchmark::State& state) { run_ctc(state, ring_ctcs(static_cast<std::size_t>(state.range(0)))); }

// GOMNE on m = 20 ranges (2 wrong) from X0 = [-50, 50]^2, paved to eps.
void BM_Gomne20Ranges(benchmark::State& state) {
  const auto ctcs = ring_ctcs(20);
  GomneOptions o;
  o.eps = state.range(0) == 0 ? 0.1 : 0.01;
  GomneResult r;
  for (auto _ : state) {
    r = gomne(ctcs, IntervalVector{{-50, 50}, {-50, 50}}, o);
    benchmark::DoNotOptimize(r);
  }
  state.counters["eps"] = o.eps;
  state.counters["q"] = r.q;
  state.counters["outliers"] = static_cast<double>(r.outliers.size());
  state.counters["leaves"] = static_cast<double>(r.leaves.size());
}

// CtcQEval(q).contract(x, v, fixes), q = m / 10, over 2000 slices on [0, 10]:
// x unknown in [-10, 10]^2, x' = (-sin t, cos t) +- 0.01; each fix at a time
// known to +-0.01 s, within 0.05 of the truth (noise from a pool of 8 sets).
void BM_CtcQEvalFixes(benchmark::State& state) {
  const auto m = static_cast<std::size_t>(state.range(0));
  const auto td = TDomain::create(0.0, 10.0, 0.005);
  const TubeVector x0(td, IntervalVector(2, Interval(-10, 10)));
  TubeVector v(td, "(-sin(t), cos(t))");
  for (std::size_t j = 0; j < 2; ++j) v[j] += Interval(-0.01, 0.01);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> noise(-0.04, 0.04);
  std::vector<std::vector<TubeObservation>> sets(8);
  for (auto& obs : sets) {
    for (std::size_t i = 0; i < m; ++i) {
      const double t = 10.0 * (static_cast<double>(i) + 0.5) / static_cast<double>(m);
      const double off = is_wrong(i) ? 2.0 : 0.0;
      obs.push_back({Interval(t).inflate(0.01), IntervalVector{Interval(std::cos(t) + off + noise(rng)).inflate(0.05),
                                                               Interval(std::sin(t) + noise(rng)).inflate(0.05)}});
    }
  }
  const CtcQEval ctc(static_cast<int>(m / 10));
  std::size_t k = 0, wrong = 0;
  for (auto _ : state) {
    TubeVector x = x0;
    wrong = ctc.contract(x, v, sets[k++ % sets.size()]).size();
    benchmark::DoNotOptimize(x);
  }
  state.counters["violated"] = static_cast<double>(wrong);
  state.SetItemsProcessed(static_cast<int64_t>(k * m));
}

}  // namespace

BENCHMARK(BM_QInterIntervals)->ArgName("m")->Arg(10)->Arg(100)->Arg(1000);
BENCHMARK(BM_CtcQInterBoxes)->ArgName("m")->Arg(10)->Arg(100)->Arg(1000);
BENCHMARK(BM_CtcQInterRings)->ArgName("m")->Arg(10)->Arg(100)->Arg(1000);

BENCHMARK(BM_Gomne20Ranges)->ArgName("eps_index")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CtcQEvalFixes)->ArgName("m")->Arg(20)->Arg(200)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();

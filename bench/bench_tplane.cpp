// TPlane (thesis ch. 6) on a synthetic survey: an open Lissajous path
// p(t) = (A sin(ω1 t), A sin(ω2 t + 0.4)), A = 120 m, ω1 = 7 and ω2 = 8.3
// cycles per hour (speed up to ~1.7 m/s; it crosses itself ~70 times in the
// first hour, ~230 times in two), and the velocity tube p'(t) ± 0.01 m/s
// sliced at T / slices. Timed: the detections (Alg. 6 and the components)
// and the proofs (degree, Newton, count) against the number of slices (1e4
// to 1e6 for one hour) and eps (T/2000, the thesis' choice, and T/8000), on
// 1 and 2 threads; and the two-hour mission at 0.1 s. Counters: leaves,
// outer and inner leaves, detections, complete ones, proofs by T and by N,
// loops counted by Alg. 10.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <map>
#include <memory>
#include <string>
#include <utility>

#include "sillage/loops/tplane.h"

using namespace sillage;

namespace {

struct Mission {
  std::shared_ptr<TDomain> td;
  TubeVector v;
};

// Built once per (hours, slices): the tubes are not what is measured.
const Mission& mission(double hours, std::size_t slices) {
  static std::map<std::pair<double, std::size_t>, std::unique_ptr<Mission>> cache;
  auto& m = cache[{hours, slices}];
  if (!m) {
    const double T = 3600 * hours;
    auto td = TDomain::create(0, T, T / static_cast<double>(slices));
    const std::string w1 = "(2*pi*7/3600)", w2 = "(2*pi*8.3/3600)";
    const std::string v = "(120*" + w1 + "*cos(" + w1 + "*t) + [-0.01,0.01], 120*" + w2 + "*cos(" + w2 +
                          "*t + 0.4) + [-0.01,0.01])";
    m = std::make_unique<Mission>(Mission{td, TubeVector(td, v)});
  }
  return *m;
}

void report(benchmark::State& state, const TPlane& tp) {
  const Paving& p = tp.paving();
  state.counters["leaves"] = static_cast<double>(p.nb_leaves());
  state.counters["outer"] = static_cast<double>(p.count(PavingTag::Inner) + p.count(PavingTag::Boundary));
  state.counters["inner"] = static_cast<double>(p.count(PavingTag::Inner));
  state.counters["detections"] = static_cast<double>(tp.nb_detections());
  state.counters["complete"] = static_cast<double>(tp.nb_complete_detections());
  state.counters["proofs"] = static_cast<double>(tp.nb_proofs());
  state.counters["newton"] = static_cast<double>(tp.nb_newton_proofs());
  std::size_t loops = 0;
  for (const Loop& l : tp.detections()) loops += l.count().value_or(0);
  state.counters["counted_loops"] = static_cast<double>(loops);
}

// Args: {slices, eps divisor, threads}; one hour.
void BM_Detections(benchmark::State& state) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(state.range(2)));
  const Mission& m = mission(1, static_cast<std::size_t>(state.range(0)));
  const double eps = m.td->tf() / static_cast<double>(state.range(1));
  TPlane tp(m.td);
  for (auto _ : state) {
    tp.compute_detections(eps, m.v);
    benchmark::DoNotOptimize(tp.nb_detections());
  }
  tp.compute_proofs(m.v);
  report(state, tp);
}

void BM_Proofs(benchmark::State& state) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(state.range(2)));
  const Mission& m = mission(1, static_cast<std::size_t>(state.range(0)));
  TPlane tp(m.td);
  tp.compute_detections(m.td->tf() / static_cast<double>(state.range(1)), m.v);
  for (auto _ : state) {
    tp.compute_proofs(m.v);
    benchmark::DoNotOptimize(tp.nb_proofs());
  }
  report(state, tp);
}

// Detections and proofs together, for a mission of range(0) hours at 0.1 s.
void BM_Mission(benchmark::State& state) {
  const double hours = static_cast<double>(state.range(0));
  const Mission& m = mission(hours, static_cast<std::size_t>(36000 * hours));
  TPlane tp(m.td);
  for (auto _ : state) {
    tp.compute_detections(m.td->tf() / 2000, m.v);
    tp.compute_proofs(m.v);
    benchmark::DoNotOptimize(tp.nb_proofs());
  }
  report(state, tp);
}

void args(benchmark::internal::Benchmark* bm) {
  bm->ArgNames({"slices", "eps_div", "threads"});
  for (long slices : {10000L, 100000L, 1000000L}) bm->Args({slices, 2000, 2});
  bm->Args({36000, 2000, 1})->Args({36000, 2000, 2})->Args({36000, 8000, 2});
  bm->Unit(benchmark::kMillisecond)->UseRealTime();
}

}  // namespace

BENCHMARK(BM_Detections)->Apply(args);
BENCHMARK(BM_Proofs)->Apply(args);
BENCHMARK(BM_Mission)->ArgName("hours")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();

// The slam/ layer: CtcT1T2 and CtcOmega per call and per gate/slice touched
// (the counter `s/atom`), CtcPImpliesZ fast and accurate, and temporal_slam on
// the small figure-eight mission of tests/cpp/slam/small_slam.h (500 slices).
// Inputs are drawn in turn from pools of 64 problems (different loop windows
// and start offsets), so no short cycle sits in the caches.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "sillage/cn/tube_changes.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/expr/function.h"
#include "sillage/slam/ctc_omega.h"
#include "sillage/slam/ctc_p_implies_z.h"
#include "sillage/slam/ctc_t1t2.h"
#include "sillage/slam/temporal_slam.h"

using namespace sillage;

namespace {

constexpr std::size_t kPool = 64;

// p*(t) = cos t drifting (Fig. 7.8), loop windows around (c, 2π - c).
struct LoopProblem {
  TubeVector p, w;
  IntervalVector box;
};

std::vector<LoopProblem> loop_pool(double dt) {
  const auto td = TDomain::create(0.0, 2 * std::numbers::pi, dt);
  const TubeVector p(std::vector<Tube>{Tube(td, "cos(t) + [-1,1]*(0.02 + 0.1*t)")});
  const TubeVector w(std::vector<Tube>{Tube(td, "-sin(t) + [-0.01,0.01]")});
  std::vector<LoopProblem> pool;
  for (std::size_t i = 0; i < kPool; ++i) {
    const double c = 0.8 + 0.8 * static_cast<double>(i) / kPool;
    pool.push_back({p, w, IntervalVector{Interval(c - 0.1, c + 0.1), Interval(2 * std::numbers::pi - c - 0.2,
                                                                                2 * std::numbers::pi - c + 0.2)}});
  }
  return pool;
}

void BM_CtcT1T2(benchmark::State& state) {
  const auto pool = loop_pool(2 * std::numbers::pi / static_cast<double>(state.range(0)));
  std::size_t i = 0, atoms = 0;
  for (auto _ : state) {
    state.PauseTiming();
    TubeVector p = pool[i % kPool].p;
    Interval t1 = pool[i % kPool].box[0], t2 = pool[i % kPool].box[1];
    std::vector<std::size_t> log;
    const std::vector<TubeChanges> changes{TubeChanges(log, 0, 0.0)};
    state.ResumeTiming();
    benchmark::DoNotOptimize(CtcT1T2().contract(t1, t2, {&p[0]}, {&pool[i % kPool].w[0]}, changes));
    atoms += log.size();
    ++i;
  }
  state.counters["atoms/call"] = benchmark::Counter(static_cast<double>(atoms) / static_cast<double>(i));
  state.counters["s/atom"] = benchmark::Counter(static_cast<double>(atoms), benchmark::Counter::kIsRate |
                                                                               benchmark::Counter::kInvert);
}
BENCHMARK(BM_CtcT1T2)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

// C_Ω over 16 t-boxes tiling each pool window (the accurate algorithm's case).
void BM_CtcOmega(benchmark::State& state) {
  const auto pool = loop_pool(2 * std::numbers::pi / static_cast<double>(state.range(0)));
  std::vector<std::vector<IntervalVector>> boxes(kPool);
  for (std::size_t k = 0; k < kPool; ++k) {
    const IntervalVector& b = pool[k].box;
    for (int a = 0; a < 4; ++a) {
      for (int c = 0; c < 4; ++c) {
        const auto part = [](const Interval& x, int j) {
          return Interval(x.lb() + x.diam() * j / 4, x.lb() + x.diam() * (j + 1) / 4);
        };
        boxes[k].push_back(IntervalVector{part(b[0], a), part(b[1], c)});
      }
    }
  }
  TubeVector work = pool[0].p;  // all pool tubes are equal: one scratch tube
  std::size_t i = 0, atoms = 0;
  for (auto _ : state) {
    const OmegaHull h = CtcOmega().hull(boxes[i % kPool], pool[i % kPool].p, pool[i % kPool].w, work);
    atoms += h.nb_touched;
    benchmark::DoNotOptimize(h.atoms.data());
    ++i;
  }
  state.counters["atoms/call"] = benchmark::Counter(static_cast<double>(atoms) / static_cast<double>(i));
  state.counters["s/atom"] = benchmark::Counter(static_cast<double>(atoms), benchmark::Counter::kIsRate |
                                                                               benchmark::Counter::kInvert);
}
BENCHMARK(BM_CtcOmega)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

// The figure eight (small_slam.h), the start shifted per pool entry.
struct SmallMission {
  TubeVector p, w, z;
};

std::vector<SmallMission> mission_pool(std::size_t n) {
  const auto td = TDomain::create(0.0, 5.0, 0.01);
  const TubeVector w(std::vector<Tube>{Tube(td, "10*cos(t - 0.5) + [-0.2,0.2]"), Tube(td, "10*cos(2*t - 1) + [-0.2,0.2]")});
  const TubeVector z(std::vector<Tube>{
      Tube(td, "sin(10*sin(t - 0.5)/3) + cos(5*sin(2*t - 1)/4) + sin(t - 0.5) + [-0.01,0.01]")});
  std::vector<SmallMission> pool;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = 0.04 * static_cast<double>(i) / static_cast<double>(n);
    TubeVector p(td, 2);
    p.set_gate(0, IntervalVector{Interval(-4.85 + d, -4.75 + d), Interval(-4.26 - d, -4.16 - d)});
    CtcDeriv().contract(p, w);
    pool.push_back({p, w, z});
  }
  return pool;
}

void BM_CtcPImpliesZ(benchmark::State& state) {
  const auto pool = mission_pool(8);
  const CtcPImpliesZ ctc(0.01, state.range(0) != 0);
  std::size_t i = 0, iterations = 0;
  for (auto _ : state) {
    state.PauseTiming();
    TubeVector p = pool[i % pool.size()].p;
    state.ResumeTiming();
    iterations += ctc.contract(p, pool[i % pool.size()].w, pool[i % pool.size()].z).size();
    ++i;
  }
  state.SetLabel(state.range(0) ? "fast" : "accurate");
  state.counters["iterations"] = benchmark::Counter(static_cast<double>(iterations) / static_cast<double>(i));
}
BENCHMARK(BM_CtcPImpliesZ)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

void BM_TemporalSlamSmall(benchmark::State& state) {
  const auto pool = mission_pool(8);
  const Function f({"x1", "x2", "u1", "u2"}, "(u1, u2)"), h({"x1", "x2"}, "(x1, x2)");
  TemporalSlamOptions o;
  o.eps = 0.01;
  std::size_t i = 0;
  for (auto _ : state) {
    state.PauseTiming();
    const SmallMission& m = pool[i % pool.size()];
    TubeVector x(m.p.tdomain(), 2), v(m.p.tdomain(), 2);
    x.set_gate(0, m.p.gate(0));
    state.ResumeTiming();
    benchmark::DoNotOptimize(temporal_slam(x, v, m.w, m.z, f, h, o).size());
    ++i;
  }
}
BENCHMARK(BM_TemporalSlamSmall)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

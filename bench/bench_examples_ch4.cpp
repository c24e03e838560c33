// The contractor networks of the chapter-4 examples (examples/cpp/
// sin_ivp.cpp, causal_chain.cpp, lissajous.cpp, kidnapped_robot.cpp), from
// building the tubes to the fixed point. The examples print the resulting
// enclosures; here only the time is measured.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>

#include "causal_chain_network.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"

namespace {

using namespace sillage;

// 4.3.3, decomposition (4.23): a = sin(x), b' = a, b(0) = 0, x = 1 - b, to
// the exact fixed point (ratio 0), on [0, 10].
void BM_SinIvp(benchmark::State& state) {
  const double dt = state.range(0) == 0 ? 0.01 : 0.001;
  for (auto _ : state) {
    const auto td = TDomain::create(0.0, 10.0, dt);
    auto x = std::make_shared<Tube>(td), a = std::make_shared<Tube>(td), b = std::make_shared<Tube>(td);
    b->set_gate(0, Interval(0));
    ContractorNetwork cn;
    cn.set_ratio(0);
    cn.add(std::make_shared<CtcFunction>(Function({"a", "x"}, "a - sin(x)")), {a, x});
    cn.add(std::make_shared<CtcDeriv>(), {b, a});
    cn.add(std::make_shared<CtcFunction>(Function({"x", "b"}, "x - 1 + b")), {x, b});
    benchmark::DoNotOptimize(cn.contract());
    benchmark::DoNotOptimize(x->gate(x->nb_slices()));
  }
  state.SetLabel("delta = " + std::to_string(dt));
}

// 4.4.1, the causal chain on [0, 14] with δ = 0.01 (the example's network):
// from x0 only (Fig. 4.8), then with the final box too (Fig. 4.9).
void BM_CausalChain(benchmark::State& state) {
  const bool final_box = state.range(0) == 1;
  for (auto _ : state) {
    const causal_chain::Problem p = causal_chain::build(TDomain::create(0.0, causal_chain::kTf, 0.01), final_box);
    benchmark::DoNotOptimize(p.cn->contract());
    benchmark::DoNotOptimize(p.x->gate(0));
  }
  state.SetLabel(final_box ? "x0 and final box" : "x0 only");
}

// 4.4.2, CN (4.29) on [0, 2π].
void BM_Lissajous(benchmark::State& state) {
  const double dt = state.range(0) == 0 ? 0.001 : 0.0001;
  for (auto _ : state) {
    const auto td = TDomain::create(0.0, 2 * std::acos(-1.0), dt);
    auto x = std::make_shared<TubeVector>(td, 2), dx = std::make_shared<TubeVector>(td, 2),
         ddx = std::make_shared<TubeVector>(td, 2);
    (*ddx)[0] = Tube(td, "-10*cos(t) + [-0.001, 0.001]");
    dx->set_gate(0, IntervalVector{Interval(0), Interval(10)});
    x->set_gate(0, IntervalVector{Interval(98, 102) / Interval(10), Interval(-2, 2) / Interval(10)});
    ContractorNetwork cn;
    cn.add(std::make_shared<CtcFunction>(Function({"a2", "v1", "a1"}, "a2 + 0.4*v1*a1")),
           {DomainRef::component(ddx, 1), DomainRef::component(dx, 0), DomainRef::component(ddx, 0)});
    cn.add(std::make_shared<CtcDeriv>(), {dx, ddx});
    cn.add(std::make_shared<CtcDeriv>(), {x, dx});
    benchmark::DoNotOptimize(cn.contract());
    benchmark::DoNotOptimize(x->gate(x->nb_slices()));
  }
  state.SetLabel("delta = " + std::to_string(dt));
}

// 4.4.3, the kidnapped robot on [0, 64] with the measurement gate at 37.
void BM_KidnappedRobot(benchmark::State& state) {
  const double dt = state.range(0) == 0 ? 0.01 : 0.005;
  const Interval c = Interval(-1, 1) / Interval(100);
  const IntervalVector x0{Interval(), Interval(), Interval::half_pi() + c, c};
  const Interval m1 = Interval(5925, 6125) / Interval(100), m2 = Interval(3616, 3816) / Interval(100);
  for (auto _ : state) {
    const auto td = TDomain::create(0.0, 64.0, dt);
    const std::size_t k37 = td->sample(37.0);
    auto x = std::make_shared<TubeVector>(td, 4), v = std::make_shared<TubeVector>(td, 4);
    (*v)[2] = Tube(td, "-9/20*cos(t/5) + [-0.001, 0.001]");
    (*v)[3] = Tube(td, "1/10 + sin(t/4) + [-0.001, 0.001]");
    x->set_gate(0, x0);
    (*x)[0].set_gate(k37, m1);
    (*x)[1].set_gate(k37, m2);
    ContractorNetwork cn;
    cn.add(std::make_shared<CtcFunction>(Function({"x3", "x4", "v1"}, "x4*cos(x3) - v1")),
           {DomainRef::component(x, 2), DomainRef::component(x, 3), DomainRef::component(v, 0)});
    cn.add(std::make_shared<CtcFunction>(Function({"x3", "x4", "v2"}, "x4*sin(x3) - v2")),
           {DomainRef::component(x, 2), DomainRef::component(x, 3), DomainRef::component(v, 1)});
    cn.add(std::make_shared<CtcDeriv>(), {x, v});
    benchmark::DoNotOptimize(cn.contract());
    benchmark::DoNotOptimize(x->gate(0));
  }
  state.SetLabel("delta = " + std::to_string(dt));
}

BENCHMARK(BM_SinIvp)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CausalChain)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Lissajous)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_KidnappedRobot)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

// The dead-reckoning case of thesis 3.4 ((3.16)-(3.18) on [0, 64]) for each
// δ of the issue: the plain slice-wise resolution and the Taylor-on-gates one
// (tube_taylor.h), from building the input tubes to p(64). The examples
// print the resulting boxes; here only the time is measured.
#include <benchmark/benchmark.h>

#include "sillage/interval/elementary.h"
#include "sillage/tube/tube_arithmetic.h"
#include "sillage/tube/tube_integral.h"
#include "sillage/interval/interval_vector.h"
#include "sillage/tube/tube_taylor.h"

namespace {

using namespace sillage;

const double kDeltas[] = {0.05, 0.01, 0.005, 0.001};

IntervalVector initial_box() {  // (3.17)
  const Interval c = Interval(-1, 1) / Interval(100);
  return {Interval(-1, 1), Interval(-1, 1), Interval::half_pi() + c, c};
}

void BM_DeadReckoningPlain(benchmark::State& state) {
  const double dt = kDeltas[state.range(0)];
  const IntervalVector x0 = initial_box();
  for (auto _ : state) {
    const auto td = TDomain::create(0.0, 64.0, dt);
    const Tube u1(td, "-9/20*cos(t/5) + [-0.001,0.001]"), u2(td, "1/10 + sin(t/4) + [-0.001,0.001]");
    const Tube x3 = primitive(u1, x0[2]), x4 = primitive(u2, x0[3]);
    const Tube x1 = primitive(x4 * cos(x3), x0[0]), x2 = primitive(x4 * sin(x3), x0[1]);
    benchmark::DoNotOptimize(x1.gate(x1.nb_slices()));
    benchmark::DoNotOptimize(x2.gate(x2.nb_slices()));
  }
  state.SetLabel("delta = " + std::to_string(dt));
}

void BM_DeadReckoningTaylor(benchmark::State& state) {
  const double dt = kDeltas[state.range(0)];
  const IntervalVector x0 = initial_box();
  const Interval noise = Interval(-1, 1) / Interval(1000);
  for (auto _ : state) {
    const auto td = TDomain::create(0.0, 64.0, dt);
    const Tube u1n(td, "-9/20*cos(t/5)"), u2n(td, "1/10 + sin(t/4)");
    const Tube x3 = primitive_taylor(u1n, Tube(td, "9/100*sin(t/5)"), x0[2], noise);
    const Tube x4 = primitive_taylor(u2n, Tube(td, "cos(t/4)/4"), x0[3], noise);
    const Tube u1 = u1n + noise, u2 = u2n + noise;
    const Tube c = cos(x3), s = sin(x3), v1 = x4 * c, v2 = x4 * s;
    const Tube x1 = primitive_from_increments(v1, taylor_increments(v1, u2 * c - x4 * s * u1), x0[0]);
    const Tube x2 = primitive_from_increments(v2, taylor_increments(v2, u2 * s + x4 * c * u1), x0[1]);
    benchmark::DoNotOptimize(x1.gate(x1.nb_slices()));
    benchmark::DoNotOptimize(x2.gate(x2.nb_slices()));
  }
  state.SetLabel("delta = " + std::to_string(dt));
}

BENCHMARK(BM_DeadReckoningPlain)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DeadReckoningTaylor)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

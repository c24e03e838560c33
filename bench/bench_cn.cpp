// Propagation time of the thesis' range-only localization (Table 2.1, 2.3.3):
// three beacons, x = [-inf, inf]^2, one CtcFunction per beacon on (x, rho_k).
//   BM_Table21_Network     ContractorNetwork::contract (queue of woken contractors)
//   BM_Table21_Sweeps      the thesis' loop: sweep C1, C2, C3 until a sweep changes nothing
//   BM_Table21_Primitives  the same network decomposed into primitives (2.30)
// The counters report iterations (rounds / sweeps) and contractor calls.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_binary.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/ctc/ctc_unary.h"
#include "sillage/ctc/shrink.h"

using namespace sillage;

namespace {

struct Beacon {
  double x, y;
  Interval rho;
};
const Beacon kBeacons[] = {{-0.5, 4.0, {3.63, 4.43}}, {-2.5, -2.5, {3.13, 3.93}}, {2.5, -0.5, {2.15, 2.95}}};

std::vector<std::shared_ptr<const Ctc>> range_ctcs() {
  std::vector<std::shared_ptr<const Ctc>> cs;
  for (const auto& b : kBeacons) {
    const Function f({"x1", "x2", "rho"},
                     "sqrt((x1 - " + std::to_string(b.x) + ")^2 + (x2 - " + std::to_string(b.y) + ")^2) - rho");
    cs.push_back(std::make_shared<CtcFunction>(f));
  }
  return cs;
}

void BM_Table21_Network(benchmark::State& state) {
  const auto cs = range_ctcs();
  ContractStats s;
  for (auto _ : state) {
    ContractorNetwork cn;
    auto x = cn.create_dom(IntervalVector(2));
    for (std::size_t k = 0; k < 3; ++k) cn.add(cs[k], {x, cn.create_dom(kBeacons[k].rho)});
    s = cn.contract();
    benchmark::DoNotOptimize(x->lb());
  }
  state.counters["iterations"] = static_cast<double>(s.iterations);
  state.counters["calls"] = static_cast<double>(s.contractor_calls);
}
BENCHMARK(BM_Table21_Network);

void BM_Table21_Sweeps(benchmark::State& state) {
  const auto cs = range_ctcs();
  std::size_t sweeps = 0;
  for (auto _ : state) {
    IntervalVector x(2);
    Interval rho[3] = {kBeacons[0].rho, kBeacons[1].rho, kBeacons[2].rho};
    sweeps = 0;
    bool changed = true;
    while (changed && !x.is_empty()) {
      changed = false;
      ++sweeps;
      for (std::size_t k = 0; k < 3; ++k) {
        IntervalVector b{x[0], x[1], rho[k]};
        const IntervalVector before(b);
        cs[k]->contract(b);
        changed = changed || shrank(before, b, 0.01);
        x = b.subvector(0, 1);
        rho[k] = b[2];
      }
    }
    benchmark::DoNotOptimize(x[0].lb());
  }
  state.counters["iterations"] = static_cast<double>(sweeps);
  state.counters["calls"] = static_cast<double>(3 * sweeps);
}
BENCHMARK(BM_Table21_Sweeps);

void BM_Table21_Primitives(benchmark::State& state) {
  const auto sub = std::make_shared<CtcSub>();
  const auto add = std::make_shared<CtcAdd>();
  const auto sqr_c = std::make_shared<CtcUnary>("sqr"), sqrt_c = std::make_shared<CtcUnary>("sqrt");
  ContractStats s;
  for (auto _ : state) {
    ContractorNetwork cn;
    auto x = cn.create_dom(IntervalVector(2));
    for (const auto& bc : kBeacons) {
      auto a = cn.create_dom(Interval()), b = cn.create_dom(Interval()), c = cn.create_dom(Interval()),
           d = cn.create_dom(Interval()), e = cn.create_dom(Interval()), rho = cn.create_dom(bc.rho);
      cn.add(sub, {a, DomainRef::component(x, 0), cn.create_dom(Interval(bc.x))});
      cn.add(sub, {b, DomainRef::component(x, 1), cn.create_dom(Interval(bc.y))});
      cn.add(sqr_c, {c, a});
      cn.add(sqr_c, {d, b});
      cn.add(add, {e, c, d});
      cn.add(sqrt_c, {rho, e});
    }
    s = cn.contract();
    benchmark::DoNotOptimize(x->lb());
  }
  state.counters["iterations"] = static_cast<double>(s.iterations);
  state.counters["calls"] = static_cast<double>(s.contractor_calls);
}
BENCHMARK(BM_Table21_Primitives);

}  // namespace

BENCHMARK_MAIN();

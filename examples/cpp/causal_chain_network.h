#pragma once
// The network of the causal kinematic chain (thesis 4.4.1, (4.25)-(4.27)),
// shared by examples/cpp/causal_chain.cpp and bench/bench_examples_ch4.cpp.
#include <memory>

#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"

namespace causal_chain {

using namespace sillage;

inline constexpr double kTf = 14.0;

inline IntervalVector initial_box() {  // (4.26)
  const Interval h = Interval::pi() * Interval(-6) / Interval(5);
  return {Interval(-1, 1), Interval(-1, 1), h + Interval(-0.02, 0.02)};
}
inline const IntervalVector kFinalBox{{53.9, 55.9}, {6.9, 8.9}, {-2.36, -2.32}};

// The network and its domains (read back after contract()).
struct Problem {
  std::shared_ptr<TubeVector> x, v;
  std::unique_ptr<ContractorNetwork> cn = std::make_unique<ContractorNetwork>();
};

// x' = v (CtcDeriv), v1 = 10 cos x3, v2 = 10 sin x3 (pointwise), v3 = u
// (4.27), x(0) in (4.26), and x(14) in kFinalBox if `with_final_box`.
inline Problem build(const std::shared_ptr<TDomain>& td, bool with_final_box) {
  Problem p;
  p.x = std::make_shared<TubeVector>(td, 3);
  p.v = std::make_shared<TubeVector>(td, 3);
  (*p.v)[2] = Tube(td, "-cos((t+33)/5) + [-0.02, 0.02]");  // (4.27)
  p.x->set_gate(0, initial_box());
  if (with_final_box) p.x->set_gate(td->nb_slices(), kFinalBox);
  ContractorNetwork& cn = *p.cn;
  cn.add(std::make_shared<CtcFunction>(Function({"v1", "x3"}, "v1 - 10*cos(x3)")),
         {DomainRef::component(p.v, 0), DomainRef::component(p.x, 2)});
  cn.add(std::make_shared<CtcFunction>(Function({"v2", "x3"}, "v2 - 10*sin(x3)")),
         {DomainRef::component(p.v, 1), DomainRef::component(p.x, 2)});
  cn.add(std::make_shared<CtcDeriv>(), {p.x, p.v});
  cn.set_name(p.x, "x");  // named, so that an empty network says which tube emptied
  cn.set_name(p.v, "v");
  return p;
}

}  // namespace causal_chain

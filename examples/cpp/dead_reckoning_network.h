#pragma once
// The network (3.18) of the dead reckoning example (thesis 3.4), shared by
// examples/cpp/dead_reckoning.cpp and the test of examples/problems/dead_reckoning.toml.
#include <memory>

#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"

namespace dead_reckoning {

using namespace sillage;

// x' = v (CtcDeriv), v1 = x4 cos x3, v2 = x4 sin x3 (pointwise), in that order.
inline void add_constraints(ContractorNetwork& cn, const std::shared_ptr<TubeVector>& x,
                            const std::shared_ptr<TubeVector>& v) {
  cn.add(std::make_shared<CtcFunction>(Function({"x3", "x4", "v"}, "x4*cos(x3) - v")),
         {DomainRef::component(x, 2), DomainRef::component(x, 3), DomainRef::component(v, 0)});
  cn.add(std::make_shared<CtcFunction>(Function({"x3", "x4", "v"}, "x4*sin(x3) - v")),
         {DomainRef::component(x, 2), DomainRef::component(x, 3), DomainRef::component(v, 1)});
  cn.add(std::make_shared<CtcDeriv>(), {x, v});
  cn.set_name(x, "x");  // named, so that an empty network says which tube emptied
  cn.set_name(v, "v");
}

}  // namespace dead_reckoning

#pragma once
// The network nodes of CtcDeriv and CtcEval (ContractorNetwork::add(ctc,
// {domains}) builds them through NetworkCtc::make_node).
//
//   cn.add(ctc_deriv, {x, v});        x' = v: tubes or tube vectors (x first)
//   cn.add(ctc_increment, {x, i});    x(t_{k+1}) - x(t_k) ∈ [i](k), likewise
//   cn.add(ctc_eval, {t, z, y, w});   z = y(t), y' = w: t an Interval, z an
//                                     Interval or a box, y, w tubes or tube
//                                     vectors (w optional)
//
// Each run contracts its whole tubes (CtcDeriv: forward-backward sweeps;
// CtcEval: fronts from [t]) and reports to the network the slices and gates
// that shrank, which wakes the pointwise contractors on those slices only.
// In a network CtcEval does not sample the TDomain (the layout is fixed).
#include <memory>
#include <vector>

#include "sillage/cn/network_ctc.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/dynamics/ctc_increment.h"

namespace sillage {

std::shared_ptr<const CnNode> make_deriv_node(const CtcDeriv& ctc, const std::vector<BoundDomain>& args);
std::shared_ptr<const CnNode> make_eval_node(const CtcEval& ctc, const std::vector<BoundDomain>& args);
std::shared_ptr<const CnNode> make_increment_node(const CtcIncrement& ctc, const std::vector<BoundDomain>& args);

}  // namespace sillage

#pragma once
// The network node of CtcEval (ContractorNetwork::add(ctc, {domains}) builds
// it through NetworkCtc::make_node):
//
//   cn.add(ctc_eval, {t, z, y, w});   z = y(t), y' = w: t an Interval, z an
//                                     Interval or a box, y, w tubes or tube
//                                     vectors (w optional)
//
// Each run contracts [t], [z] and the tubes (fronts from [t]) and reports the
// slices and gates that shrank, which wakes the pointwise contractors on
// those slices only. The node touches only the region of [t] (the tube's
// CtcDeriv propagates further) and never samples the TDomain while it runs;
// the bounds of [t] become gates at the next contract() when the CtcEval has
// gates_at_time_bounds (CtcEval::gates_for). CtcDeriv and CtcIncrement use
// TubeContractor (cn/tube_contractor.h).
#include <memory>
#include <vector>

#include "sillage/cn/network_ctc.h"
#include "sillage/dynamics/ctc_eval.h"

namespace sillage::detail {

std::shared_ptr<const CnNode> make_eval_node(const CtcEval& ctc, const std::vector<BoundDomain>& args);

}  // namespace sillage::detail

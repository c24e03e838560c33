#pragma once
// TubeCtcNode: a box contractor applied at every time, on tubes and on
// constant (time-independent) variables: f(x_1(t), ..., x_n(t), p) ∈ [y] for
// all t (thesis 3.2.3, 4.3.1). ContractorNetwork::add makes one when an
// argument is a tube.
//
// Slice granularity: at each run only the time atoms (slices, gates) that
// changed since the last run are contracted, plus the gates next to a changed
// slice (a gate lies in both neighbouring slices, and is intersected with
// them first). Atom i of every tube is the same time element (all tubes are
// on one TDomain), so the box of atom i gathers atom i of each tube. The
// contraction of the boxes is contract_time_elements (tube/time_box_ctc.h),
// the one shared with contract(ctc, tubes).
//
// Constant variables p hold at every t: each contracted time element gives a
// valid contraction of p, and p is intersected with all of them. When p
// shrinks (by more than the ratio) every time element is contracted again,
// until p is stable.
#include <cstddef>
#include <memory>
#include <vector>

#include "sillage/cn/tube_node.h"

namespace sillage {

class TubeCtcNode : public TubeNode {
 public:
  // `args`: tubes (one variable each) and constants (Interval or box atoms).
  // Every tube argument must be a whole tube, and all tubes must share one
  // TDomain (DimensionError otherwise).
  TubeCtcNode(std::shared_ptr<const Ctc> ctc, const std::vector<BoundDomain>& args);
  std::string describe() const override { return ctc_->describe(); }
  bool run(NodeRun& r) const override;
  // Nothing in it depends on the number of slices: grown in place when its
  // tubes gain slices (online estimation).
  bool follows_appends() const override { return true; }

 private:
  // Contracts the time atoms `atoms` (sorted) by contract_time_elements
  // (tube/time_box_ctc.h); false if proven empty.
  bool contract_atoms(NodeRun& r, const std::vector<std::size_t>& atoms, IntervalVector& params) const;

  std::shared_ptr<const Ctc> ctc_;
  std::vector<std::size_t> var_range_;  // per variable of ctc_, its argument
  std::size_t nb_params_ = 0;
};

}  // namespace sillage

#pragma once
// CtcIncrement: x(t_{k+1}) − x(t_k) ∈ [i](k) for every slice k, where [i](k)
// (the slice k of a tube i) encloses the integral of x' over the slice: the
// discrete form of x' = v that odometry gives (a distance or a heading change
// per sampling period, not an instantaneous rate). Only the gates of x are
// contracted, by a forward then a backward sweep:
//   [x](t_{k+1}) ∩= [x](t_k) + [i](k),   [x](t_k) ∩= [x](t_{k+1}) − [i](k).
// One forward-backward call reaches the fixed point of these rules. The
// slices of x are left to CtcDeriv with bounds of the instantaneous rate,
// which are looser than the increments but hold inside the slices.
//
// Empty: an empty increment or gate empties x; contract returns false.
// In a ContractorNetwork: cn.add(ctc, {x, i}) with tubes or tube vectors.
#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/tube_contractor.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

class CtcIncrement : public TubeContractor<CtcIncrement, bool(Tube&, const Tube&)> {
 public:
  // The increment contractor.
  CtcIncrement() = default;
  std::string name() const override { return "CtcIncrement"; }
  // Its network node stays right when the tubes gain slices (it holds nothing per slice).
  bool follows_appends() const { return true; }

  // DimensionError if x and i are not on one TDomain.
  bool contract(Tube& x, const Tube& i) const;
  // The same after a change in slices first..last of i or x (and gates
  // first..last+1 of x) when x was a fixed point of contract() before: the
  // sweeps start at the change and stop where the gates stop moving, with
  // contract()'s result bit for bit (the network's node uses it after its
  // first run). `changes` receives what shrank. Error if first > last or
  // last >= N; DimensionError as contract().
  bool contract_local(Tube& x, const Tube& i, std::size_t first, std::size_t last, const TubeChanges& changes) const;
  // The same for a tube vector x, component by component.
  bool contract(TubeVector& x, const TubeVector& i) const;
};

}  // namespace sillage

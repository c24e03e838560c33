#pragma once
// CtcSecondDeriv: x'' ∈ [a](k) on every slice k, as a bound on how far x
// leaves the chord between its gates inside the slice. With g = x − chord,
// g(t_k) = g(t_{k+1}) = 0 and g'' = x'', so g(t_k + τ) ∈ −[a](k) τ (δ − τ) / 2
// (the Green function of the slice is ≥ 0 and integrates to τ (δ − τ) / 2),
// and the chord lies in the hull of the gates:
//   [x](k) ∩= ([x](t_k) ∪ [x](t_{k+1})) − [a](k) [0, δ² / 8].
// A bound on the acceleration (a turn acceleration for a heading) is much
// tighter inside short slices than the rate bound of CtcDeriv, which lets x
// go out and back at full rate. Only the slices of x are contracted.
//
// Empty: an empty slice or gate of x, or an empty [a], empties x; contract
// returns false. In a ContractorNetwork: cn.add(ctc, {x, a}) with tubes or
// tube vectors (as many components).
#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/tube_contractor.h"
#include "sillage/tube/tube.h"

namespace sillage {

class CtcSecondDeriv : public TubeContractor<CtcSecondDeriv, bool(Tube&, const Tube&)> {
 public:
  // The second-derivative contractor.
  CtcSecondDeriv() = default;
  std::string name() const override { return "CtcSecondDeriv"; }
  // Its network node stays right when the tubes gain slices (it holds nothing per slice).
  bool follows_appends() const { return true; }

  // DimensionError if x and a are not on one TDomain. Tube vectors: in a
  // network, cn.add(ctc, {x, a}), component by component.
  bool contract(Tube& x, const Tube& a) const;
  // The same on slices first..last alone, after a change there (slices of x
  // or a, gates first..last+1 of x) when x was a fixed point of contract()
  // before: each slice depends on its own gates only, so this is contract()'s
  // result bit for bit (the network's node uses it after its first run).
  // `changes` receives what shrank. Error if first > last or last >= N.
  bool contract_local(Tube& x, const Tube& a, std::size_t first, std::size_t last, const TubeChanges& changes) const;
};

}  // namespace sillage

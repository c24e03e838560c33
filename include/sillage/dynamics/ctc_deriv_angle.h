#pragma once
// CtcDerivAngle: x' = v for an angle tube x, one whose slices and gates are
// known modulo 2π (interval/angle.h): a heading that bearings narrow back
// after dead reckoning let it grow past a turn.
//
// Slice rule, in the frame of a gate that is not the whole circle (the input
// gate [a], else the output gate [b] backwards): a lift of the true angle
// through [a] stays in [a] + τ[v], so with δ the slice's width
//   [b]' = angle_lift([b], [a] + δ[v])         forward (4.16), modulo 2π
//   [x]' = angle_lift([x](k), [a] + [0, δ][v])
//   [a]  ∩= [b]' - δ[v]                        backward (4.17)
//   [x]' ∩= ([a] + [0, δ][v]) ∩ ([b]' - [0, δ][v])
// and each is written back as angle_meet(old, new): a subset of the old
// representative (the contractor only shrinks) that keeps every angle the
// rule keeps. The lift is a real number: angle_lift keeps every copy of [b]
// it may reach (angle_meet would keep one). Gates lie in their slices (modulo 2π). CtcDeriv's polygon is
// replaced by its box (sound, a little looser inside a slice).
//
// Sweeps: forward over the slices, then backward. The result is a valid
// enclosure whatever the representatives; it is not always a fixed point
// (a representative choice can let a second call shrink more).
//
// Empty: a slice or gate of x or a slice of v empty, or an arc emptied,
// empties x and returns false. In a ContractorNetwork: cn.add(ctc, {x, v}).
#include <cstddef>
#include <string>

#include "sillage/cn/tube_changes.h"
#include "sillage/cn/tube_contractor.h"
#include "sillage/tube/tube.h"

namespace sillage {

class CtcDerivAngle : public TubeContractor<CtcDerivAngle, bool(Tube&, const Tube&)> {
 public:
  // The differential contractor on an angle tube.
  CtcDerivAngle() = default;
  std::string name() const override { return "CtcDerivAngle"; }
  // Its network node stays right when the tubes gain slices (it holds nothing per slice).
  bool follows_appends() const { return true; }

  // Contracts the angle tube x with x' ∈ v (v a real tube: a turn rate).
  // False if x is now empty. DimensionError if x and v are not on one TDomain.
  bool contract(Tube& x, const Tube& v) const;
  // For a network node: after a change in slices first..last (of x or v),
  // the sweeps start there and go on, both ways, while they move gates.
  // `changes` receives what shrank. Error if first > last or last >= N.
  bool contract_local(Tube& x, const Tube& v, std::size_t first, std::size_t last, const TubeChanges& changes) const;
};

}  // namespace sillage

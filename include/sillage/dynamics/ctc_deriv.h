#pragma once
// CtcDeriv: the differential contractor C_d/dt of the constraint x' = v
// (thesis 4.2, Prop. 4.1, Alg. 3-5). Only [x] is contracted: nothing can be
// learnt on [v] from [x] (Lemma 4.1).
//
// Slice rule (k = 0 .. N-1), with gates [a] = [x](t_k), [b] = [x](t_{k+1}),
// derivative [v] = [v](k) (its slice; v's gates are not used) and the
// rigorous width δ of the slice:
//   [a], [b] ∩= [x](k)                 gates lie in their neighbouring slices
//   [b] ∩= [a] + δ[v]                  forward  (4.16)
//   [a] ∩= [b] - δ[v]                  backward (4.17)
//   [x](k) ∩= hull{ ([a] + τ[v]) ∩ ([b] - (δ-τ)[v]) : τ ∈ [0, δ] }
// The last hull (the polygon of the design guide) has a closed form: its
// upper bound is the maximum over τ of min(a⁺ + τv⁺, b⁺ - (δ-τ)v⁻), the
// crossing of the two lines when v⁻ < 0 < v⁺, else an end of the slice
// (tube/slice_deriv.h). Per slice this is the exact projection of the
// trajectories of the slice: every value it keeps is reached by a piecewise
// linear trajectory with slopes in [v] through [a], the value and [b].
//
// Sweeps: FORWARD applies the forward rule and the polygon for k = 0..N-1
// (Alg. 3); BACKWARD the backward rule and the polygon for k = N-1..0
// (Alg. 4); FWD_BWD a forward sweep on the gates then a backward sweep with
// the polygon (Alg. 5). After FWD_BWD the tube is a fixed point of the slice
// rule: a second call changes nothing, bit for bit (the rounded gate bounds
// are monotone in each other, see docs/dynamics.md).
//
// Rigor: all arithmetic is outward rounded (rounding.h), slice widths are
// enclosures, unbounded gates and derivatives are supported (v = [0, +inf)
// keeps x nondecreasing, v = (-inf, +inf) contracts nothing but the gates into
// their slices).
//
// Empty: if a slice, a gate of x or a slice or gate of v met by the sweep is empty,
// or the contraction proves it, every slice and gate of x is set empty and
// contract returns false.
//
// Cost: two passes over contiguous arrays, no allocation, no virtual call,
// no data-dependent branch; directed rounding by the hardware's static
// rounding modes where available (AVX-512F), else emulated (interval/rounding_policies.h).
// About 5 ns per slice for FWD_BWD with the former (docs/dynamics.md).
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/tube_changes.h"
#include "sillage/cn/tube_contractor.h"
#include "sillage/dynamics/time_propag.h"
#include "sillage/interval/interval.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

// The differential contractor C_d/dt of x' = v (thesis 4.2, (4.4), Alg. 3-5): contract(x, v)
// contracts the tube (or tube vector) x in place and returns false if it is now empty; v is not
// changed. Optional restrictions: a slice range (first, last) or a time interval t. In a
// ContractorNetwork: cn.add(ctc, {x, v}) (cn/tube_contractor.h).
class CtcDeriv : public TubeContractor<CtcDeriv, bool(Tube&, const Tube&)> {
 public:
  // The contractor with the sweeps of time_propag: FORWARD (Alg. 3, (4.16)), BACKWARD (Alg. 4,
  // (4.17)) or FWD_BWD (Alg. 5, the default).
  explicit CtcDeriv(TimePropag propag = TimePropag::FWD_BWD) : propag_(propag) {}
  std::string name() const override { return "CtcDeriv"; }

  // The direction of the sweeps.
  TimePropag time_propag() const { return propag_; }
  // Whether contract(x, v) reaches the fixed point of x' = v (both sweeps):
  // in a network, other nodes then leave that propagation to this one.
  bool enforces_derivative() const { return propag_ == TimePropag::FWD_BWD; }
  // Its network node stays right when the tubes gain slices (it holds nothing per slice).
  bool follows_appends() const { return true; }

  // Contracts x in place with x' ∈ v (x.version() steps if it changed). Returns
  // false if x is now empty. DimensionError if x and v are not on the same
  // TDomain.
  bool contract(Tube& x, const Tube& v) const;

  // Restricted to slices first..last (inclusive) and gates first..last+1:
  // nothing else is read or changed (a contractor network propagates from
  // where a change happened). Returns false if emptiness was found there (x
  // is then set empty everywhere). Error if first > last or last >= N.
  bool contract(Tube& x, const Tube& v, std::size_t first, std::size_t last) const;

  // Restricted to the slices whose time domain meets the interior of t (a
  // degenerate t: the slices that contain it), as above. Empty t: nothing
  // done, returns true. Error if t is not inside the TDomain.
  bool contract(Tube& x, const Tube& v, const Interval& t) const;

  // For a network node, the local propagation: x was a fixed point of this
  // contractor before slices first..last changed (in x or in v). The sweeps
  // start there and go on, both ways, while they move gates, so the cost is
  // that of how far the change reaches, not of the tube; the result is the
  // one of contract(x, v) on such a tube (FORWARD or BACKWARD alone, one pass
  // being no fixed point: the whole pass). `changes` receives what shrank.
  // False if x is now empty (x is then set empty). Error if first > last or
  // last >= N; DimensionError if x and v are not on the same TDomain.
  bool contract_local(Tube& x, const Tube& v, std::size_t first, std::size_t last, const TubeChanges& changes) const;

  // Component-wise: x[i]' ∈ v[i]. DimensionError if the sizes differ; if a
  // component becomes empty, all are set empty and false is returned.
  bool contract(TubeVector& x, const TubeVector& v) const;
  // Only slices first..last and gates first..last+1 of each component are read or changed.
  bool contract(TubeVector& x, const TubeVector& v, std::size_t first, std::size_t last) const;
  // Only the slices meeting the time interval t.
  bool contract(TubeVector& x, const TubeVector& v, const Interval& t) const;

 private:
  TimePropag propag_;
};

}  // namespace sillage

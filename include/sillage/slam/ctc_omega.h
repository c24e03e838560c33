#pragma once
// CtcOmega: the contractor C_Ω of thesis Alg. 12, (7.22):
//   [p](·) ∩= ⋃_j C_{t1,t2}([t1]_j, [t2]_j, [p](·), [w](·))
// over the t-boxes [t]_j = [t1]_j × [t2]_j of one component Ω of the t-plane
// known to hold a loop time pair of the true trajectory (the union: which box
// holds it is unknown).
//
// Alg. 12 copies the whole tube once per box. Here each box is contracted in
// place on one working tube, and what it changed is read from CtcT1T2's
// change logs, folded into a sparse hull (atom -> hull of the values the
// boxes gave it), then put back from the reference tube: the cost of a box is
// the window of slices its contraction reaches, not the tube. An atom (gate
// or slice) that some consistent box did not touch keeps its value (the hull
// with the untouched value is the value). A box whose contraction is
// inconsistent (no loop there) is left out of the union; when all of them
// are, p is emptied. The result does not depend on the order of the boxes,
// so they are visited spread over Ω (a golden-ratio stride), and the visit
// stops once no atom can shrink any more (every atom left is either untouched
// by a consistent box or already back to its reference value): on a wide Ω
// that holds after a few boxes instead of all of them.
#include <cstddef>
#include <vector>

#include "sillage/budget.h"
#include "sillage/interval/interval_vector.h"
#include "sillage/slam/ctc_t1t2.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

// What C_Ω would do to a tube: the atoms (gates and slices) it narrows and
// their new values; `empty` when no box is consistent.
struct OmegaHull {
  // One gate or slice narrowed by CtcOmega.hull.
  struct Atom {
    // Component of the tube vector.
    std::size_t component;
    std::size_t atom;  // 2k: gate k, 2k + 1: slice k
    // Its new value (the hull over the consistent boxes).
    Interval value;
  };
  // No box is consistent: the tube would be emptied.
  bool empty = false;
  std::vector<Atom> atoms;        // sorted by (component, atom)
  std::size_t nb_boxes = 0;       // boxes of Ω
  std::size_t nb_consistent = 0;  // boxes whose contraction is consistent (of those visited)
  std::size_t nb_touched = 0;     // atoms touched, summed over the boxes (the cost)

  // p ∩= the hull (empty: p emptied). Returns false if p is empty after.
  // nb_shrunk, if given, is increased by the atoms that shrank by more than
  // `ratio` (shrink.h).
  bool apply_to(TubeVector& p, std::size_t* nb_shrunk = nullptr, double ratio = 0.0) const;
};

class CtcOmega {
 public:
  // The contractor, with the CtcT1T2 used on each box.
  explicit CtcOmega(const CtcT1T2& t1t2 = CtcT1T2()) : t1t2_(t1t2) {}

  // p ∩= (7.22) over the t-boxes (2-D each: DimensionError otherwise; an
  // empty list gives an empty p: Ω holds the true loop by assumption).
  // Returns false if p becomes empty.
  bool contract(const std::vector<IntervalVector>& boxes, TubeVector& p, const TubeVector& w) const;

  // The sparse hull against the reference tube `p`; `work` must equal p on
  // entry (it is used as scratch and is equal to p again on return). Several
  // threads may run it at once with their own `work`. `cancel` is checked at
  // every box: once cancelled, Cancelled (work is then left as scratch).
  OmegaHull hull(const std::vector<IntervalVector>& boxes, const TubeVector& p, const TubeVector& w,
                 TubeVector& work, const CancelToken& cancel = {}) const;

 private:
  CtcT1T2 t1t2_;
};

}  // namespace sillage

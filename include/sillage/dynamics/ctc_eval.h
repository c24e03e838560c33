#pragma once
// CtcEval: the evaluation contractor C_eval of z = y(t), y' = w, with an
// uncertain time t (thesis 5.2, Prop. 5.1, (5.6)):
//   [t]    ∩= [y]⁻¹([z])
//   [z]    ∩= [y]([t])
//   [y](·) ∩= ⊔_{t1 ∈ [t]} ( ([y](t1) ∩ [z]) + ∫_{t1}^{·} [w] )
// [t] and [z] use the tube with its derivative (Tube::inverse(y, w),
// Tube::eval(t, w): the polygon inside each slice, tighter than the boxes).
//
// The tube, in the region of [t] (the slices meeting it and their gates),
// by two fronts (docs/ctc_eval.md): F(t_i) encloses y(t_i) for a measurement
// time t1 <= t_i, B(t_i) for t1 >= t_i. Across slice k a front moves by
// δ[w](k) and gains, when [t] meets the slice on [c1, c2],
//   F: ([y]([c1, c2]) ∩ [z]) + [t_{k+1} - c2, t_{k+1} - c1]·[w](k),
//   B: ([y]([c1, c2]) ∩ [z]) - [c1 - t_k, c2 - t_k]·[w](k),
// [y]([c1, c2]) being the slice's polygon over [c1, c2] (its box when [t]
// covers it), so [t] is never rounded out to whole slices. A gate after [t]
// is intersected with F, one before with B, one inside with F ∪ B; each slice
// with the hull of its polygon. [t], [z] and the region are iterated until
// nothing changes: one call is a fixed point. Beyond the region the fronts go
// on while they shrink gates (further they would only repeat CtcDeriv), and
// the slices next to those gates are hulled. A standalone call then runs
// CtcDeriv over the whole tube, so that CtcEval is monotone whatever its
// input; the overloads with `changes` (network nodes, CtcT1T2, CtcQEval)
// leave that to the network's CtcDeriv. A network node leaves it the fronts
// too when the network has CtcDeriv (both sweeps) on every (y, w) it evaluates.
//
// A degenerate [t] = {t} that is not a time point samples the TDomain there
// (a new gate, in every tube on it) when sampling is allowed (the default);
// a network node never samples while it runs, but with
// enable_gates_at_time_bounds(true) the network adds the bounds of [t] as
// time points at its next contract() (ContractorNetwork, "Gates").
//
// Inconsistency (Lemma 5.1): when [t], [z] or a gate becomes empty, [t], [z]
// and [y] are all set empty and contract returns false.
//
// Without a derivative only [t], [z] and, for a t that is a time point, its
// gate are contracted.
//
// In a ContractorNetwork: cn.add(ctc, {t, z, y, w}) (src/sillage/dynamics/tube_nodes.h).
#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/network_ctc.h"
#include "sillage/cn/tube_changes.h"
#include "sillage/interval/interval.h"
#include "sillage/interval/interval_vector.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

class CtcEval : public NetworkCtc {
 public:
  // The evaluation contractor, time sampling enabled.
  CtcEval() = default;
  std::string name() const override { return "CtcEval"; }
  std::shared_ptr<const CnNode> make_node(const std::vector<BoundDomain>& args) const override;

  // Allow (default) or not the sampling of the TDomain at a degenerate t.
  void enable_time_sampling(bool on) { sampling_ = on; }
  // Whether a degenerate t may sample the TDomain.
  bool time_sampling() const { return sampling_; }
  // In a ContractorNetwork: add the bounds of [t] (as given to add()) as
  // time points of y's TDomain at the next contract(), so that the values at
  // the ends of [t], and later queries inside those slices, are as tight as
  // (5.6) allows (ContractorNetwork, "Gates"). Off by default: every tube of
  // that TDomain gains up to two slices per observation.
  void enable_gates_at_time_bounds(bool on) { gates_at_bounds_ = on; }
  // Whether a network adds the bounds of t as time points.
  bool gates_at_time_bounds() const { return gates_at_bounds_; }
  Gates gates_for(const std::vector<DomainRef>& args) const override;

  // z = y(t), y' ∈ w. DimensionError if y and w are not on one TDomain;
  // Error if t does not meet [t_0, t_N] (it is intersected with it).
  bool contract(Interval& t, Interval& z, Tube& y, const Tube& w) const;
  bool contract(Interval& t, Interval& z, Tube& y) const;  // no derivative
  // Vector case, component-wise with one t (DimensionError on sizes).
  bool contract(Interval& t, IntervalVector& z, TubeVector& y, const TubeVector& w) const;
  bool contract(Interval& t, IntervalVector& z, TubeVector& y) const;
  // For network nodes: the vector case on component tubes (w empty: no
  // derivative), and, when `beyond`, the fronts beyond the region of [t]
  // while they shrink gates (a node whose network runs CtcDeriv on every
  // (y[i], w[i]) leaves them to it: it would redo them, once per
  // observation instead of once for all); changes[i] (one per y[i]) receives
  // the slices and gates of y[i] that shrank (TubeNode::changes()).
  // With `one_pass`, one pass over [t], [z] and the region instead of passes
  // to the fixed point: for a node that its network runs again when the pass
  // shrank something (NodeRun::again).
  bool contract(Interval& t, IntervalVector& z, const std::vector<Tube*>& y, const std::vector<const Tube*>& w,
                const std::vector<TubeChanges>& changes, bool beyond = true, bool one_pass = false) const;
  // Deprecated (the atom encoding leaks): changed[i] receives the atoms of
  // y[i] (2k: gate k, 2k+1: slice k) that shrank by more than `ratio`. Use
  // the TubeChanges overload.
  bool contract(Interval& t, IntervalVector& z, const std::vector<Tube*>& y, const std::vector<const Tube*>& w,
                double ratio, std::vector<std::vector<std::size_t>>& changed) const;

 private:
  bool sampling_ = true;
  bool gates_at_bounds_ = false;
};

}  // namespace sillage

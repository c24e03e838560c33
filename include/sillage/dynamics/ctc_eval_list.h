#pragma once
// CtcEvalList: a list of fixes x(t_i) ∈ z_i, t_i ∈ [t_i] (TubeObservation)
// on a tube x with x' ∈ [v], all true, as one network node: the network form
// of m CtcEval contractors and their observation contractors (a range to a
// beacon, a position fix), without a node, a domain and a name per fix.
//
//   CtcEvalList ranges(obs);          // obs[i]: {t_i, z_i, ctc_i, name_i}
//   cn.add(ranges, {x, v});           // x, v tube vectors (or tubes) of one size
//
// A run contracts each fix whose slices changed (the slices meeting [t_i]
// and their neighbours, as a CtcEval node watches): CtcEval (one pass, thesis
// 5.2) on (t_i, z_i, x, v), then ctc_i on z_i, again while t_i or z_i shrink
// by more than the network's ratio; then the next fix, on the tube as the
// previous ones left it. t_i and z_i live in the node (contracted across runs
// and contract() calls, as the domains t and z of a CtcEval node would be: a
// network whose tubes are widened again is to be built again, which starts
// from the fixes as given); the fronts beyond [t_i] are left to the network's
// CtcDeriv when it has one on every (x[j], v[j]), as a CtcEval node does.
// The set is that of m CtcEval nodes with their observation nodes (the same
// contractors, to the same kind of fixed point); the order of the runs
// differs, so the bounds may differ in the last digits of a ratio.
//
// Inconsistency (Lemma 5.1): a fix that CtcEval or its contractor finds empty
// empties x; the network's emptiness names the fix (describe(): its name, or
// its index) and the first slice meeting [t_i].
//
// The TDomain is never sampled: put the bounds of each [t_i] as time points
// beforehand for the tightest values there (the problem files do, `gates`).
#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/network_ctc.h"
#include "sillage/dynamics/tube_observation.h"

namespace sillage {

class CtcEvalList : public NetworkCtc {
 public:
  // The fixes, all true (a non-empty list; each z and ctc of one size n, the
  // x of add(); each t meeting its time domain: checked by add()).
  explicit CtcEvalList(std::vector<TubeObservation> obs);
  std::string name() const override { return "CtcEvalList"; }
  // The fixes as given (the node contracts copies of t and z).
  const std::vector<TubeObservation>& observations() const { return *obs_; }
  // cn.add(ctc, {x, v}): DimensionError naming CtcEvalList unless x and v
  // are whole tubes of one size n on one TDomain and every fix has n
  // components; Error if a time misses the time domain.
  std::shared_ptr<const CnNode> make_node(const std::vector<BoundDomain>& args) const override;

 private:
  std::shared_ptr<const std::vector<TubeObservation>> obs_;  // shared with the nodes
};

}  // namespace sillage
